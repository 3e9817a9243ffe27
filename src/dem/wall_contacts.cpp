#include "dem/wall_contacts.h"

#include "core/error.h"
#include "dem/parallel.h"

#include <algorithm>
#include <string>

namespace veridem::dem
{

bool WallContactList::needsRebuild(const std::vector<Wall>& walls, Real skin) const
{
    if (wallDisplacementAtBuild_.size() != walls.size() || wallActiveAtBuild_.size() != walls.size())
        return true;
    for (std::size_t w = 0; w < walls.size(); ++w)
        if (lengthSquared(walls[w].displacement - wallDisplacementAtBuild_[w]) > 0.25 * skin * skin ||
            wallActive(walls[w]) != bool(wallActiveAtBuild_[w]))
            return true;
    return false;
}

void WallContactList::markActivity(const std::vector<Wall>& walls)
{
    wallActiveAtBuild_.resize(walls.size());
    for (std::size_t w = 0; w < walls.size(); ++w)
        wallActiveAtBuild_[w] = wallActive(walls[w]);
}

void WallContactList::setRecordLoads(bool on)
{
    recordLoads = on;
    loadForce.assign(on ? particle.size() : 0, Vec3{});
    loadMoment.assign(on ? particle.size() : 0, Vec3{});
}

WallLoad wallLoad(const WallContactList& list, std::uint32_t w, const Vec3& reference)
{
    Vec3 force, moment;
    for (std::size_t k = 0; k < list.loadForce.size() && k < list.size(); ++k)
        if (list.wall[k] == w)
        {
            force += list.loadForce[k];
            moment += list.loadMoment[k];
        }
    // On the particles about the reference: moment - reference x force; the wall takes minus that.
    return {-force, cross(reference, force) - moment};
}

void WallContactList::rebuild(const ParticleStore& particles, const std::vector<Wall>& walls, Real skin,
                              ContactHistoryStore& history)
{
    const std::size_t n = particles.size();
    wallDisplacementAtBuild_.resize(walls.size());
    for (std::size_t w = 0; w < walls.size(); ++w)
        wallDisplacementAtBuild_[w] = walls[w].displacement;
    markActivity(walls);

    // Candidates per chunk of particles, concatenated in order (sorted by (particle, wall)).
    const int chunks = std::min(loopThreads(n), 64);
    std::vector<std::vector<std::uint32_t>> chunkParticle(static_cast<std::size_t>(chunks)),
        chunkWall(static_cast<std::size_t>(chunks));
    parallelChunks(n, chunks,
                   [&](int c, std::size_t begin, std::size_t end)
                   {
                       auto& ps = chunkParticle[static_cast<std::size_t>(c)];
                       auto& ws = chunkWall[static_cast<std::size_t>(c)];
                       for (std::size_t i = begin; i < end; ++i)
                           for (std::size_t w = 0; w < walls.size(); ++w)
                               if (wallNear(walls[w], particles.position[i], particles.radius[i], skin))
                               {
                                   ps.push_back(static_cast<std::uint32_t>(i));
                                   ws.push_back(static_cast<std::uint32_t>(w));
                               }
                   });
    std::vector<std::uint32_t> newParticle, newWall;
    for (int c = 0; c < chunks; ++c)
    {
        const auto& ps = chunkParticle[static_cast<std::size_t>(c)];
        const auto& ws = chunkWall[static_cast<std::size_t>(c)];
        newParticle.insert(newParticle.end(), ps.begin(), ps.end());
        newWall.insert(newWall.end(), ws.begin(), ws.end());
    }
    const std::size_t count = newParticle.size();

    // Re-key the history: each slot's source is the old slot with the same (particle, wall).
    std::vector<std::uint32_t> source(count, ContactHistoryStore::kNoSource);
    const auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
    std::size_t old = 0;
    for (std::size_t k = 0; k < count; ++k)
    {
        const std::uint64_t wanted = key(newParticle[k], newWall[k]);
        while (old < particle.size() && key(particle[old], wall[old]) < wanted)
            ++old;
        if (old < particle.size() && key(particle[old], wall[old]) == wanted)
            source[k] = static_cast<std::uint32_t>(old);
    }
    if (history.size() != particle.size()) // (never built: no history to carry)
        history.clear();
    history.carry(source.data(), count);
    particle.swap(newParticle);
    wall.swap(newWall);
    if (recordLoads)
    {
        loadForce.assign(count, Vec3{});
        loadMoment.assign(count, Vec3{});
    }
    start.assign(n + 1, 0);
    for (std::size_t k = 0; k < count; ++k)
        ++start[particle[k] + 1];
    for (std::size_t i = 0; i < n; ++i)
        start[i + 1] += start[i];
}

void WallContactList::renameParticles(const std::vector<std::uint32_t>& newIndex,
                                      ContactHistoryStore& history)
{
    constexpr std::uint32_t kGone = 0xffffffffu;               // (NeighborList::kGone)
    std::vector<std::pair<std::uint64_t, std::uint32_t>> kept; // new (particle, wall) key, old slot
    kept.reserve(particle.size());
    for (std::size_t k = 0; k < particle.size(); ++k)
        if (const std::uint32_t p = newIndex[particle[k]]; p != kGone)
            kept.push_back({(std::uint64_t(p) << 32) | wall[k], static_cast<std::uint32_t>(k)});
    std::sort(kept.begin(), kept.end());
    ContactHistoryStore renamed(history.keepFormed);
    renamed.keepRolling = history.keepRolling;
    const bool rolling = history.keepRolling && history.rolling.size() == history.spring.size();
    std::vector<std::uint32_t> newParticle(kept.size()), newWall(kept.size());
    renamed.spring.resize(kept.size());
    if (rolling)
        renamed.rolling.resize(kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k)
    {
        newParticle[k] = static_cast<std::uint32_t>(kept[k].first >> 32);
        newWall[k] = static_cast<std::uint32_t>(kept[k].first);
        renamed.spring[k] = history.spring[kept[k].second];
        if (rolling)
            renamed.rolling[k] = history.rolling[kept[k].second];
    }
    particle.swap(newParticle);
    wall.swap(newWall);
    history = std::move(renamed);
    start.clear();
}

std::size_t WallContactList::slotOf(std::uint32_t particleIndex, std::uint32_t wallIndex) const
{
    for (std::size_t k = 0; k < particle.size(); ++k)
        if (particle[k] == particleIndex && wall[k] == wallIndex)
            return k;
    throw InputError("particle " + std::to_string(particleIndex) + " has no contact slot with wall " +
                     std::to_string(wallIndex) + " (it is not within the neighbour skin of it)");
}

std::size_t WallContactList::memoryBytes() const
{
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(particle) + bytes(wall) + bytes(start) + bytes(wallDisplacementAtBuild_) +
           bytes(wallActiveAtBuild_) + bytes(loadForce) + bytes(loadMoment);
}

} // namespace veridem::dem
