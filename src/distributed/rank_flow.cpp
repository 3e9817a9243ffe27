#include "distributed/rank_flow.h"

#include "dem/particle_changes.h"
#include "distributed/bytes.h"
#include "distributed/rank_gather.h"
#include "distributed/rank_sums.h"

#include <span>
#include <string>

namespace veridem::distributed
{

bool applyFlow(dem::ParticleFlow& flow, dem::World& world, RankStep& ranks, Real dt)
{
    const Collective& comm = ranks.comm();
    // [0]: particles retired on some rank, [1]: particles inserted
    std::uint64_t changed[2] = {0, 0};
    if (std::vector<std::uint32_t> doomed = flow.takeAtOutlets(world, ranks.owned()); !doomed.empty())
    {
        dem::retireParticles(world, doomed);
        changed[0] = doomed.size();
    }
    // Whether rank 0's inserters have particles due (their state is rank 0's).
    double due = comm.rank() == 0 && flow.insertionDue(world.time, dt) ? 1 : 0;
    comm.max(std::span(&due, 1));
    dem::ParticleStore made;
    if (due > 0)
    {
        Vec3 lo, hi;
        flow.insertionBounds(world.domain, lo, hi);
        const Real margin = flow.largestRadius() + ranks.haloWidth();
        const Vec3 m{margin, margin, margin};
        dem::ParticleStore near = gatherParticlesIn(world.particles, ranks.owned(), lo - m, hi + m, comm);
        if (comm.rank() == 0)
        {
            // The particles near the regions and the walls, as the inserters test them in one
            // process (a world of its own: its lists are not built, so the grid is made afresh).
            dem::World probe = worldLike(world);
            probe.particles = std::move(near);
            flow.index = dem::ParticleIndex{};
            const std::size_t before = probe.particles.size();
            flow.insertNew(probe, dt);
            for (std::size_t i = before; i < probe.particles.size(); ++i)
                made.appendRow(probe.particles, i);
            changed[1] = made.size();
        }
    }
    comm.sum(changed);
    if (changed[0] == 0 && changed[1] == 0)
        return false;
    // The retired particles leave at once (their ghosts elsewhere would otherwise keep their
    // radius at the parking place, where two of them would touch), the new ones join.
    ranks.admit(world, changed[1] > 0 ? broadcastParticles(made, comm) : dem::ParticleStore{});
    return true;
}

void countOnFirstRank(std::vector<dem::Outlet>& outlets, const Collective& comm)
{
    if (comm.rank() == 0)
        return;
    for (dem::Outlet& o : outlets)
    {
        o.count = 0;
        o.mass = 0;
    }
}

std::vector<dem::Outlet> outletTotals(const std::vector<dem::Outlet>& outlets, const Collective& comm,
                                      bool everyRank)
{
    std::vector<dem::Outlet> totals = outlets;
    std::vector<std::uint64_t> counts(outlets.size());
    for (std::size_t k = 0; k < outlets.size(); ++k)
        counts[k] = outlets[k].count;
    comm.sum(counts);
    std::vector<Real> masses;
    for (const dem::Outlet& o : outlets)
        masses.push_back(o.mass);
    masses = sumInRankOrder(masses, comm, everyRank);
    if (!everyRank && comm.rank() != 0)
        return totals;
    for (std::size_t k = 0; k < outlets.size(); ++k)
    {
        totals[k].count = counts[k];
        totals[k].mass = masses[k];
    }
    return totals;
}

} // namespace veridem::distributed
