#include "distributed/rank_sums.h"

#include "distributed/bytes.h"

#include <string>

namespace veridem::distributed
{

std::vector<Real> sumInRankOrder(std::span<const Real> values, const Collective& comm, bool everyRank)
{
    Buffers out(static_cast<std::size_t>(comm.size()));
    ByteWriter w{out[0]};
    for (const Real v : values)
        w.put(v);
    if (everyRank)
        for (std::size_t b = 1; b < out.size(); ++b)
            out[b] = out[0];
    const Buffers in = comm.exchange(std::move(out));
    std::vector<Real> sums(values.begin(), values.end());
    if (!everyRank && comm.rank() != 0)
        return sums;
    sums.assign(values.size(), 0);
    for (int a = 0; a < comm.size(); ++a) // (rank order: one order of the sums)
    {
        if (in[a].size() != values.size() * sizeof(Real))
            throw SimulationError("MPI exchange: " + std::to_string(in[a].size()) + " bytes from rank " +
                                  std::to_string(a) + " for a sum of " + std::to_string(values.size()) +
                                  " numbers");
        ByteReader r{in[a]};
        for (Real& s : sums)
            s += r.get<Real>();
    }
    return sums;
}

dem::EnergyLedgerState ledgerTotals(const dem::EnergyLedgerState& mine, const Collective& comm)
{
    dem::EnergyLedgerState totals = mine;
    std::vector<Real> amounts;
    dem::forEachAmount(totals, [&](Real& a) { amounts.push_back(a); });
    const std::vector<Real> sums = sumInRankOrder(amounts, comm);
    std::size_t k = 0;
    dem::forEachAmount(totals, [&](Real& a) { a = sums[k++]; });
    return totals;
}

} // namespace veridem::distributed
