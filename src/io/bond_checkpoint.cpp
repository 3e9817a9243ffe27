#include "io/bond_checkpoint.h"

#include <string>

namespace veridem::io
{

void writeBondRecords(CheckpointWriter& out, const dem::BondSet& set)
{
    out.value("bdCr", std::uint8_t(set.created));
    out.array("bdLs", set.bonds);
    out.array("bdCt", std::vector<std::uint64_t>{set.formed, set.broken, set.dropped, set.overstretched});
    out.value("bdMS", set.maxStrain);
}

void readBondRecords(CheckpointReader& in, dem::BondSet& set)
{
    set.created = in.value<std::uint8_t>("bdCr") != 0;
    in.array("bdLs", set.bonds);
    std::vector<std::uint64_t> counts;
    in.array("bdCt", counts);
    if (counts.size() != 4)
        in.fail("is corrupt: the bond counts have " + std::to_string(counts.size()) + " values");
    set.formed = counts[0];
    set.broken = counts[1];
    set.dropped = counts[2];
    set.overstretched = counts[3];
    in.value("bdMS", set.maxStrain);
    // (the partners' indices are a cache checked against their ids at each use, so a wrong one is
    // looked up again; the rest length divides)
    for (const dem::Bond& b : set.bonds)
        if (!(b.state.restLength > 0))
            in.fail("is corrupt: a bond has rest length " + std::to_string(b.state.restLength));
}

} // namespace veridem::io
