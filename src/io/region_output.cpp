#include "io/region_output.h"

namespace veridem::io
{

RegionRecorder::RegionRecorder(const std::filesystem::path& directory, const Vec3& lo, const Vec3& hi,
                               std::optional<std::uint64_t> resumeBytes)
    : lo_(lo), hi_(hi), table_(directory,
                               {"t", "particles", "contacts", "coordination", "packing_fraction", "sxx",
                                "syy", "szz", "sxy", "sxz", "syz"},
                               resumeBytes, "region.csv")
{
}

void RegionRecorder::record(const dem::World& world, const std::vector<dem::ContactRecord>& contacts)
{
    const dem::RegionMeasures m = dem::measureRegion(world, contacts, lo_, hi_);
    table_.row({world.time, m.particles, m.contacts, m.coordination, m.packingFraction, m.stress[0],
                m.stress[1], m.stress[2], m.stress[3], m.stress[4], m.stress[5]});
}

} // namespace veridem::io
