// Recursive coordinate bisection: the space of a run cut into `parts` boxes of equal particle
// cost, one per MPI rank (issue: MPI domain decomposition; Berger & Bokhari 1987, "A partitioning
// strategy for nonuniform problems on multiprocessors", IEEE Trans. Computers 36(5)).
//
// The cut. The box of all particles (its bounds) is split across its longest axis at the
// coordinate c below which lies floor(parts/2)/parts of its weight (particles at x < c go below),
// and each side is split again with its share of the parts, until every box holds one part. A
// part's weight is the sum of its particles' integer weights (their cost: 1 plus their contacts,
// say). All boxes of one level are cut together: c is found by bisection on the coordinate, each
// step one global sum of the weights below the trial cuts (Collective::sum, one value per box), to
// 2^-40 of the box's extent, and c is then the trial point whose weight below is nearer the
// target (the lower on a tie). Each part's weight is within the largest particle weight per level
// of its ideal share (more only when particles share a coordinate).
//
// The same bits on any rank count. Every decision is taken on exact integer sums and maxima,
// which do not depend on how the particles are spread over the ranks or in what order they are
// added, so the tree is the same whether one process holds all the particles or N ranks hold
// them in any split (tests/distributed/mpi_bisection_check.cpp checks it bit for bit on 1, 2 and 4 ranks).
//
// Regions. A part's region is its box with the faces on the bounds moved to infinity, so the
// regions tile all of space and a particle that leaves the bounds between two decompositions
// still has one owner (owner()).
//
// Periodic axes (dem/periodic.h). The cut prefers the non-periodic axes: a region then spans each
// periodic axis whole, and a rank finds the pairs through those faces among its own particles and
// ghosts as one process does. A domain periodic along all three axes is cut across periodic axes
// (the only ones there are). Either way forEachPartNear looks through the periodic faces: a part
// whose region comes near an image x + s of x (s a sum of box edges, dem::forEachImageShift) is
// near x, so the part holds a ghost of the particle at x itself, and its PeriodicPairs pairs it
// with the image. The positions must be wrapped into the box (RankStep wraps them before it cuts
// or exchanges), as they are when one process searches for its periodic pairs.
#pragma once

#include "core/vec3.h"
#include "dem/periodic.h"
#include "distributed/collective.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace veridem::distributed
{

/// An axis-aligned box [lo, hi) [m]; a face may be at infinity.
struct Box
{
    Vec3 lo, hi;
};

/// Component `axis` (0, 1, 2) of v.
inline Real component(const Vec3& v, int axis)
{
    return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}
inline Real& component(Vec3& v, int axis)
{
    return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/// The squared distance [m^2] from the point x to the box (0 inside).
Real distanceSquared(const Box& box, const Vec3& x);

class Decomposition
{
  public:
    /// A cut of the tree: points with x[axis] < cut go to `below`, the others to `above`; a child
    /// >= 0 is a node, a child < 0 the part -(child + 1).
    struct Node
    {
        int axis = 0;
        Real cut = 0; // [m]
        int below = -1, above = -1;
    };
    std::vector<Node> nodes;         // nodes[0] is the root (empty for one part)
    std::vector<Box> region;         // per part: where it owns particles (tiles all of space)
    std::vector<std::uint64_t> cost; // per part: the weight of its particles when cut
    Box bounds;                      // the box of all particles when cut [m]
    dem::PeriodicDomain domain;      // the run's domain box and periodic axes (file comment)

    int parts() const { return static_cast<int>(region.size()); }
    /// The part whose region holds x.
    int owner(const Vec3& x) const;
    /// Calls f(part) once for each part whose region comes nearer than `reach` [m] to x or, along
    /// the periodic axes, to one of its images (the parts that need a ghost copy of a particle at
    /// x whose interaction range is `reach`), the owner included, in ascending part order.
    template <class F> void forEachPartNear(const Vec3& x, Real reach, F&& f) const;

  private:
    /// forEachPartNear without the images.
    template <class F> void forEachPartNearPoint(const Vec3& x, Real reach, F&& f) const;
};

/// The axes bisect may cut across: the non-periodic ones, or all three when every axis of
/// `domain` is periodic (file comment).
std::array<bool, 3> cuttableAxes(const dem::PeriodicDomain& domain);

/// Cuts the particles at `position` [m] (this rank's; every rank calls it with its own) with
/// weights `weight` into `parts` regions by recursive coordinate bisection (file comment), each box
/// across the longest of cuttableAxes(domain) (`domain`: the run's box and periodic axes; the
/// positions wrapped into it along those). Collective: every rank of `comm` must call it; every
/// rank gets the same decomposition.
Decomposition bisect(std::span<const Vec3> position, std::span<const std::uint32_t> weight, int parts,
                     const Collective& comm, const dem::PeriodicDomain& domain = {});

template <class F> void Decomposition::forEachPartNear(const Vec3& x, Real reach, F&& f) const
{
    if (!domain.any())
    {
        forEachPartNearPoint(x, reach, f);
        return;
    }
    // The parts near each image, merged: ascending and each once.
    thread_local std::vector<int> near;
    near.clear();
    dem::forEachImageShift(
        domain, x, reach,
        [&](const Vec3& shift)
        { forEachPartNearPoint(x + shift, reach, [&](int part) { near.push_back(part); }); });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (const int part : near)
        f(part);
}

template <class F> void Decomposition::forEachPartNearPoint(const Vec3& x, Real reach, F&& f) const
{
    if (nodes.empty())
    {
        f(0);
        return;
    }
    // Depth-first, below before above: parts are numbered in that order, so they come ascending.
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
        const int child = stack[--top];
        if (child < 0)
        {
            const int part = -(child + 1);
            if (distanceSquared(region[part], x) < reach * reach)
                f(part);
            continue;
        }
        const Node& n = nodes[child];
        const Real d = component(x, n.axis) - n.cut;
        if (d > -reach) // (pushed first: visited after `below`)
            stack[top++] = n.above;
        if (d < reach)
            stack[top++] = n.below;
    }
}

} // namespace veridem::distributed
