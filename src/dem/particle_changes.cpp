#include "dem/particle_changes.h"

#include "dem/contact_law.h"

#include <algorithm>
#include <functional>
#include <numeric>

namespace veridem::dem
{

// (declared in world.h)
void refreshFixedParticles(World& world)
{
    const ParticleStore& p = world.particles;
    world.fixedIndex.clear();
    world.fixedHome.clear();
    for (std::size_t i = 0; i < p.fixed.size(); ++i)
        if (p.fixed[i])
        {
            world.fixedIndex.push_back(static_cast<std::uint32_t>(i));
            world.fixedHome.push_back(p.position[i]);
        }
    world.neighbors.anyFixed = !world.fixedIndex.empty();
}

void removeParticles(World& world, std::vector<std::uint32_t> doomed)
{
    if (doomed.empty())
        return;
    ParticleStore& p = world.particles;
    const std::size_t n = p.size();
    // original[s]: the index before the removals of the particle now at slot s. From the highest
    // index down, the last particle is never one still to be removed.
    std::vector<std::uint32_t> original(n);
    std::iota(original.begin(), original.end(), 0u);
    std::sort(doomed.begin(), doomed.end(), std::greater<>());
    for (const std::uint32_t i : doomed)
    {
        original[i] = original[p.size() - 1];
        original.pop_back();
        p.swapRemove(i);
    }
    std::vector<std::uint32_t> newIndex(n, NeighborList::kGone);
    for (std::size_t s = 0; s < original.size(); ++s)
        newIndex[original[s]] = static_cast<std::uint32_t>(s);
    world.neighbors.renameParticles(newIndex, world.pairHistory);
    world.wallContacts.renameParticles(newIndex, world.wallHistory);
    world.periodicPairs.renameParticles(newIndex);
}

bool retiresWithoutRebuild(const World& world)
{
    const std::size_t n = world.particles.size();
    return world.prepared && !world.observer && world.neighbors.reach == 0 && world.neighbors.builtFor(n) &&
           world.wallContacts.start.size() == n + 1;
}

void retireParticles(World& world, const std::vector<std::uint32_t>& doomed)
{
    ParticleStore& p = world.particles;
    const Vec3 parked{kParkedCoordinate, kParkedCoordinate, kParkedCoordinate};
    for (const std::uint32_t i : doomed)
    {
        p.position[i] = parked;
        p.velocity[i] = p.angularVelocity[i] = Vec3{};
        p.force[i] = p.torque[i] = PaddedVec3{};
        p.radius[i] = 0;
        if (p.positionRadius.size() == p.size())
            p.positionRadius[i] = p.positionRadiusRow(i);
        world.neighbors.parkParticle(i, parked);
    }
}

bool removeRetiredParticles(World& world)
{
    const ParticleStore& p = world.particles;
    std::vector<std::uint32_t> doomed;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.retired(i))
            doomed.push_back(static_cast<std::uint32_t>(i));
    if (doomed.empty())
        return false;
    removeParticles(world, std::move(doomed));
    return true;
}

void compactRetiredParticles(World& world)
{
    const ParticleStore& p = world.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.retired(i))
            return rebuildAfterParticleChange(world);
}

bool insertsWithoutRebuild(const World& world, std::size_t particleCount, Real largestRadius)
{
    if (!world.prepared || !world.neighbors.builtFor(particleCount) ||
        world.wallContacts.start.size() != particleCount + 1 || world.pairs.count() != world.materials.size())
        return false;
    // The list's touch reach (JKR adhesion, NeighborList::reach) must cover the new particles'
    // pairs with any material at the largest radius (touchReach grows with R*), or be widened by
    // a rebuild. A reach wider than a pair's own changes nothing: the law decides whether a pair
    // within it is formed.
    const ParticleStore& p = world.particles;
    std::vector<bool> seen(world.materials.size(), false);
    for (std::size_t i = particleCount; i < p.size(); ++i)
    {
        const std::uint32_t a = p.material[i];
        if (seen[a])
            continue;
        seen[a] = true;
        for (std::uint32_t b = 0; b < world.pairs.count(); ++b)
            if (touchReach(world.pairs(a, b), 0.5 * largestRadius) > world.neighbors.reach)
                return false;
    }
    // A periodic axis must hold the inserted pairs' search twice, so that a pair has at most one
    // image within it (the key (i, j) of its history names one contact).
    const Vec3 edge = world.domain.length();
    const Real edges[3] = {edge.x, edge.y, edge.z};
    const Real cutoff = 2 * largestRadius + insertedPairSearch(world.neighbors);
    for (int a = 0; a < 3; ++a)
        if (world.domain.periodic[a] && !(edges[a] >= 2 * cutoff))
            return false;
    return true;
}

void addInsertedParticles(World& world, std::size_t from, const ParticleIndex& index)
{
    const ParticleStore& p = world.particles;
    const Real search = insertedPairSearch(world.neighbors);
    std::vector<std::uint32_t> first, second;
    std::vector<Vec3> shift;
    for (std::size_t i = from; i < p.size(); ++i)
    {
        const Vec3 xi = p.position[i];
        const Real ri = p.radius[i];
        // Through a periodic face: particle j's image x_j - s near xi, i.e. x_j near xi + s (every
        // particle is within skin/2 of the box: wrapped at the last rebuild).
        const Real near = ri + index.largestRadius() + search + 0.5 * world.neighbors.skin;
        forEachImageShift(world.domain, xi, near,
                          [&](const Vec3& s)
                          {
                              const Vec3 q = xi + s;
                              index.forEachNear(q,
                                                [&](std::uint32_t j)
                                                {
                                                    const Real within = ri + p.radius[j] + search;
                                                    if (j < i &&
                                                        lengthSquared(p.position[j] - q) < within * within)
                                                    {
                                                        first.push_back(j);
                                                        second.push_back(static_cast<std::uint32_t>(i));
                                                        shift.push_back(s);
                                                    }
                                                });
                          });
    }
    world.neighbors.appendParticles(p, from);
    if (!first.empty())
    {
        // (Rolling springs kept as the pair candidates keep them: an EPSD model is in use.)
        world.periodicPairs.history.keepRolling = world.pairHistory.keepRolling;
        world.periodicPairs.history.scalarCount = world.pairHistory.scalarCount;
        world.periodicPairs.addPairs(p, world.neighbors.anyFixed, first, second, shift);
    }
    // Walls: skin/2 of the particle's motion plus up to skin of the wall's (WallContactList).
    world.wallContacts.appendParticles(p, from, world.walls, 1.5 * world.neighbors.skin, world.wallHistory);
}

} // namespace veridem::dem
