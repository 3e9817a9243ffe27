// Stage 4a of the step (declared in dem/forces.h): the cross-block shares the pair stage deferred
// (NeighborList::deferred) added to their particles' sums, per particle in slot order, so the sums
// are the same bits for any thread count. No physics here.
#include "dem/forces.h"
#include "dem/lanes.h"
#include "exec/isa.h"

#include <algorithm>

namespace veridem::dem
{

namespace
{

using namespace lanes; // Lanes4, load, store (dem/lanes.h)

/// addCrossBlockForces for a world with pair slots: adds each particle's incoming cross-block
/// entries, in slot order, to the sums the pair stage left in its force and torque. Inlined into
/// an instruction-set variant below (one 32-byte add per row with AVX2, two with SSE2).
VERIDEM_HOT_INLINE void crossBlockSumsBody(World& world, std::size_t begin, std::size_t end)
{
    ParticleStore& p = world.particles;
    const NeighborList& pairs = world.neighbors;
    if (pairs.deferred.empty())
        return;
    const std::uint32_t* const start = pairs.incomingStart.data();
    const std::uint32_t* const entry = pairs.incomingEntry.data();
    const NeighborList::DeferredShare* const deferred = pairs.deferred.data();
    // The entries are stored in slot order, so a particle's lie scattered: they are fetched
    // kEntriesAhead entries before their use.
    constexpr std::uint32_t kEntriesAhead = 16;
    const std::uint32_t lastEntry = start[p.size()] - 1;
    for (std::size_t i = begin; i < end; ++i)
    {
        if (start[i] == start[i + 1])
            continue;
        // Padded rows: x, y, z and the padding (+0) summed in lanes, each lane's adds those of
        // the Vec3 sum.
        Lanes4 force = load<Lanes4>(&p.force[i].x), torque = load<Lanes4>(&p.torque[i].x);
        for (std::uint32_t e = start[i]; e < start[i + 1]; ++e)
        {
            __builtin_prefetch(&deferred[entry[std::min(e + kEntriesAhead, lastEntry)]]);
            force += load<Lanes4>(&deferred[entry[e]].force.x);
            torque += load<Lanes4>(&deferred[entry[e]].torque.x);
        }
        store(&p.force[i].x, force);
        store(&p.torque[i].x, torque);
    }
}

VERIDEM_AVX2_TARGET void crossBlockSumsAvx2(World& world, std::size_t begin, std::size_t end)
{
    crossBlockSumsBody(world, begin, end);
}

void crossBlockSumsPortable(World& world, std::size_t begin, std::size_t end)
{
    crossBlockSumsBody(world, begin, end);
}

} // namespace

void addCrossBlockForces(World& world, std::size_t begin, std::size_t end)
{
    ParticleStore& p = world.particles;
    const NeighborList& pairs = world.neighbors;
    if (pairs.incomingStart.size() != p.size() + 1) // no list built (no particles)
        return;
    if (pairs.size() == 0 && world.periodicPairs.empty()) // no pairs (one ball on a turntable): the
                                                          // sums were not written
    {
        for (std::size_t i = begin; i < end; ++i)
            p.force[i] = p.torque[i] = Vec3{};
        return;
    }
    if (exec::isAvx2())
        crossBlockSumsAvx2(world, begin, end);
    else
        crossBlockSumsPortable(world, begin, end);
}

} // namespace veridem::dem
