// A cell grid of the particles for queries between steps (insertion, dem/particle_flow.h), kept
// from one flow event to the next so that an event costs its own particles, not a pass over all.
//
// Reference positions. The grid bins each particle at its neighbour-list reference (the position
// at the last rebuild of the contact lists, or the insertion position of a particle inserted
// since: NeighborList::motionReference). Until the next rebuild every particle stays within
// skin/2 of its reference (the rebuild criterion), so every particle whose current position is
// within d of a point has its reference within d + skin/2 of it. The cells are at least as wide
// as the largest distance a query asks for plus skin/2, so forEachNear's 27 cells hold every such
// particle. The grid is valid until the neighbour list is rebuilt (NeighborList::rebuildCount);
// then the next event bins the particles near the inserters' regions again (a bounds test over
// all particles, once per rebuild, not per event).
//
// A particle inserted is appended to its cell in O(1) (a linked list per cell). The callers sort
// or reduce what they find, so the visiting order never reaches the results: a grid rebuilt at
// another time (after a restore) gives the same bits.
#pragma once

#include "core/vec3.h"
#include "dem/neighbor_list.h"
#include "dem/particles.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

class ParticleIndex
{
  public:
    /// True if the grid holds the `particleCount` particles of `list`'s current build, for
    /// particles appended up to radius `newRadius` [m] and queries up to r_i + r_j + `extra` [m].
    bool validFor(const NeighborList& list, std::size_t particleCount, Real newRadius, Real extra) const;
    /// Bins the particles at their references (at their positions if the list is not built for
    /// them; the grid is then valid for this event only) in cells at least 2 R + extra + skin/2
    /// wide (R [m]: the largest of newRadius and the particles' radii). With a cover box
    /// [coverLo, coverHi] [m] (the inserters' regions: every query point and every particle
    /// appended lies in it), only the particles within a cell of it are binned; without (an
    /// empty box), all. At most 4 cells a particle plus 2^16, and 2^22 in all. O(N) with a small
    /// constant (a bounds test a particle) plus the cells and the particles binned.
    void build(const ParticleStore& particles, const NeighborList& list, Real newRadius, Real extra,
               const Vec3& coverLo, const Vec3& coverHi);
    /// Appends particle i (the next index, radius at most newRadius) at reference x [m] (its
    /// current position). O(1).
    void append(std::uint32_t i, const Vec3& x);

    /// Calls visit(j) for every particle j binned in the 27 cells around x [m]: a superset of the
    /// particles whose current position is within r + r_j + extra of x for r up to R (the caller
    /// tests the distance).
    template <class Visit> void forEachNear(const Vec3& x, Visit&& visit) const
    {
        std::size_t c[3];
        coordinates(x, c);
        for (std::size_t z = c[2] ? c[2] - 1 : 0; z <= std::min(c[2] + 1, n_[2] - 1); ++z)
            for (std::size_t y = c[1] ? c[1] - 1 : 0; y <= std::min(c[1] + 1, n_[1] - 1); ++y)
                for (std::size_t xi = c[0] ? c[0] - 1 : 0; xi <= std::min(c[0] + 1, n_[0] - 1); ++xi)
                    for (std::uint32_t j = head_[(z * n_[1] + y) * n_[0] + xi]; j != kEnd; j = next_[j])
                        visit(j);
    }

    /// R [m]: the largest radius binned or announced for appending (build's newRadius).
    Real largestRadius() const { return radius_; }
    std::size_t size() const { return next_.size(); }
    std::size_t builds() const { return builds_; }

  private:
    static constexpr std::uint32_t kEnd = 0xffffffffu;
    void coordinates(const Vec3& x, std::size_t* c) const;

    Vec3 origin_;
    Real cell_ = 0;   // [m]
    Real radius_ = 0; // R [m]
    Real extra_ = 0;  // [m]
    std::size_t n_[3] = {1, 1, 1};
    std::size_t listBuild_ = ~std::size_t{0}; // NeighborList::rebuildCount at build
    std::vector<std::uint32_t> head_;         // per cell: its last particle binned (kEnd: none)
    std::vector<std::uint32_t> next_;         // per particle: the one binned before it in its cell
    std::size_t builds_ = 0;
};

} // namespace veridem::dem
