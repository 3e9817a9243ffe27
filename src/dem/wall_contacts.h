// Particle-wall contact list with history (sparse: only particles near a wall have a slot).
//
// Candidates (particle, wall) are the pairs whose gap is below the neighbour skin (wallNear), kept
// sorted by (particle, wall) and rebuilt together with the pair list: when some particle has moved
// more than skin/2, or some wall has translated more than skin/2, since the last build. Relative
// motion is then below the skin, so no wall contact is missed. History is merged by key on a
// rebuild and zeroed when a contact opens, as for particle pairs (neighbor_list.h).
//
// A dense (particle x wall) history would cost 24-48 bytes per particle per wall and test every
// wall for every particle each step; a bed in a box has 5 walls and 1 in 5 particles near one.
#pragma once

#include "core/vec3.h"
#include "dem/contact_law.h"
#include "dem/particles.h"
#include "dem/walls/wall.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

class WallContactList
{
  public:
    bool keepRollingHistory = false; // store a rolling spring per slot (EPSD rolling model in use)

    std::vector<std::uint32_t> particle; // sorted by (particle, wall)
    std::vector<std::uint32_t> wall;
    std::vector<Vec3> tangentialSpring; // history per slot [m]
    std::vector<Vec3> rollingSpring;    // [N m] (empty unless keepRollingHistory)
    std::vector<std::uint32_t> start;   // slots [start[p], start[p+1]) belong to particle p

    /// True if some wall translated more than skin/2 since the last build (or never built).
    bool needsRebuild(const std::vector<Wall>& walls, Real skin) const;
    /// Rebuilds the candidate list, carrying history over by (particle, wall).
    void rebuild(const ParticleStore& particles, const std::vector<Wall>& walls, Real skin);

    ContactHistory history(std::size_t k) const
    {
        return historyAt(tangentialSpring, rollingSpring, keepRollingHistory, k);
    }
    void setHistory(std::size_t k, const ContactHistory& h)
    {
        storeHistoryAt(tangentialSpring, rollingSpring, keepRollingHistory, k, h);
    }
    /// Tangential spring of the contact (particle, wall) [m], e.g. to start a case in a loaded
    /// contact state after prepare(). Throws InputError if the particle is not near that wall.
    Vec3& tangentialSpringOf(std::uint32_t particleIndex, std::uint32_t wallIndex);

    std::size_t size() const { return particle.size(); }
    std::size_t memoryBytes() const;

  private:
    friend struct CheckpointAccess; // io/dem_checkpoint.cpp saves and restores the private state
    std::vector<Vec3> wallDisplacementAtBuild_;
};

} // namespace veridem::dem
