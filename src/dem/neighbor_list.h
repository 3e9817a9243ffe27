// Neighbour list with contact history (Verlet list on a cell grid).
//
// Design. Candidate pairs (i < j) whose gap is below `skin` are found by binning particles into
// cubic cells of edge >= 2 r_max + skin and testing the 27 surrounding cells: O(N). The list is
// kept sorted by (i, j) and rebuilt only when some particle has moved more than skin/2 since the
// last build, so between rebuilds no pair can come into contact unseen. Each pair slot carries its
// contact history (tangential spring, rolling spring); on a rebuild the new sorted list is merged
// with the old one by key, so history survives rebuilds and pairs that separated are dropped
// (Jolt's read-old/write-new contact cache; LAMMPS FixNeighHistory). History is also zeroed the
// moment a contact opens (in the force loop), so a re-formed contact starts fresh.
#pragma once

#include "core/vec3.h"
#include "dem/contact_law.h"
#include "dem/particles.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

class NeighborList
{
  public:
    Real skin = 0; // extra search distance beyond touching [m]

    std::vector<std::uint32_t> first;    // i of each pair (sorted, i < j)
    std::vector<std::uint32_t> second;   // j of each pair
    std::vector<ContactHistory> history; // per pair slot

    /// True if some particle moved more than skin/2 since the last build (or never built).
    bool needsRebuild(const ParticleStore& particles) const;
    /// Rebuilds the pair list, carrying history over by (i, j).
    void rebuild(const ParticleStore& particles);

    std::size_t size() const { return first.size(); }
    std::size_t rebuildCount() const { return rebuilds_; }

  private:
    std::vector<Vec3> positionAtBuild_;
    std::vector<std::uint32_t> cellStart_, cellParticles_, cellOf_;
    std::vector<std::uint32_t> newFirst_, newSecond_, scratch_;
    std::vector<ContactHistory> newHistory_;
    std::size_t rebuilds_ = 0;
};

} // namespace veridem::dem
