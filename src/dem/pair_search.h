// The candidate-pair search of the neighbour list: every pair i < j with
// |x_i - x_j| < r_i + r_j + search, in O(N) for any mix of sizes.
//
// Size classes. One grid of cells as wide as the largest pair distance (2 r_max + search) is
// O(N) only while the radii are alike: with a size ratio of 10 a cell of the large spheres'
// width holds ~10^3 small ones, and each small sphere would test the ~27,000 small spheres of its
// 27 cells (the problem LAMMPS's `neighbor multi` addresses, lammps#2423). Particles are therefore
// sorted into classes by radius, class k holding r in (r_max / 2^(k+1), r_max / 2^k] (the last
// class everything smaller), each with a grid of its own whose cells are as wide as its largest
// pair distance (2 R_k + search, R_k its largest radius). A sphere i finds its partners of class
// k in the cells of that grid within r_i + R_k + search: the 27 around it when r_i <= R_k, a
// wider block (a few cells) only for a sphere larger than the class, which is itself few of the
// class's partners. Radii within a factor 2 make one class: one grid and 27 cells, as before
// classes existed.
//
// The result does not depend on the classes: each i's partners are sorted, so the list (and
// everything computed from it) is the same bits whatever the search visits.
#pragma once

#include "core/vec3.h"
#include "dem/particles.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// Finds, for each particle i, the particles j > i with |x_i - x_j| < r_i + r_j + search [m]:
/// count[i + 1] is set to i's number of partners (count has n + 1 entries; count[0] untouched)
/// and `partners` receives every i's partners in ascending j, i after i. `expected`: the pairs
/// expected (the last search's count; 0 if unknown): each chunk's buffer is reserved for its share
/// plus an eighth on the calling thread, so that the worker threads rarely allocate (a worker's
/// malloc arena keeps the memory it frees).
void findPairsWithin(const ParticleStore& particles, Real search, std::vector<std::uint32_t>& count,
                     std::vector<std::uint32_t>& partners, std::size_t expected = 0);

/// The number of size classes the search uses for radii in [smallest, largest] [m] (1 when
/// largest <= 2 smallest; at most kMaxSizeClasses).
inline constexpr int kMaxSizeClasses = 8;
int sizeClassCount(Real smallest, Real largest);

} // namespace veridem::dem
