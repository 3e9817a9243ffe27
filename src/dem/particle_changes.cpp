#include "dem/particle_changes.h"

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

bool insertsWithoutRebuild(const World& world, std::size_t particleCount)
{
    if (!world.prepared || world.domain.any() || !world.neighbors.builtFor(particleCount) ||
        world.wallContacts.start.size() != particleCount + 1 || world.pairs.count() != world.materials.size())
        return false;
    for (std::uint32_t a = 0; a < world.pairs.count(); ++a)
        for (std::uint32_t b = 0; b < world.pairs.count(); ++b)
            if (world.pairs(a, b).normalModel == NormalModel::Jkr)
                return false;
    return true;
}

void addInsertedParticles(World& world, std::size_t from, const ParticleIndex& index)
{
    const ParticleStore& p = world.particles;
    const Real search = insertedPairSearch(world.neighbors);
    std::vector<std::uint32_t> first, second;
    for (std::size_t i = from; i < p.size(); ++i)
    {
        const Vec3 xi = p.position[i];
        const Real ri = p.radius[i];
        index.forEachNear(xi,
                          [&](std::uint32_t j)
                          {
                              const Real within = ri + p.radius[j] + search;
                              if (j < i && lengthSquared(xi - p.position[j]) < within * within)
                              {
                                  first.push_back(j);
                                  second.push_back(static_cast<std::uint32_t>(i));
                              }
                          });
    }
    world.neighbors.appendParticles(p, from);
    if (!first.empty())
    {
        // (Rolling springs kept as the pair candidates keep them: an EPSD model is in use.)
        world.periodicPairs.history.keepRolling = world.pairHistory.keepRolling;
        world.periodicPairs.addPairs(p, world.neighbors.anyFixed, first, second);
    }
    // Walls: skin/2 of the particle's motion plus up to skin of the wall's (WallContactList).
    world.wallContacts.appendParticles(p, from, world.walls, 1.5 * world.neighbors.skin, world.wallHistory);
}

} // namespace veridem::dem
