// Broad phase of the 2D contact detection: linked-cell binning of triangle bounding circles in O(N)
// time and memory (in the spirit of Munjiza & Andrews' NBS, IJNME 43:131, 1998; BENCHMARKS 6.4).
//
// Each triangle gets a bounding circle (centroid c, radius r = max node distance). With a buffer
// (Verlet skin) b, a pair is a candidate when |c_a - c_b| <= r_a + r_b + b. The cell size is
// 2 r_max + b, so candidates lie in the same or a neighbouring cell; each cell is tested against
// itself and its 4 "half-neighbourhood" cells (E, NE, N, NW), so each pair is tested once. The
// triangles are binned by a counting sort (no search tree). If the grid would have more than
// 4N + 1024 cells the cell size is enlarged, keeping memory O(N).
//
// Re-detection criterion: a node that moved by d since the last detection stays within r + d of
// the old centroid, so two triangles can only touch if |c_a - c_b|_old <= r_a + r_b + 2 d_max.
// The candidate list is therefore valid until 2 d_max > b (World::step checks this).
#pragma once

#include "fdem/vec2.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace veridem::fdem
{

struct BoundingCircle
{
    Vec2 centre;         ///< [m]
    Real radius;         ///< [m]
    std::uint32_t group; ///< pairs in the same group are not reported (same body)
    bool active;         ///< pairs of two inactive (static) circles are not reported
};

/// Candidate pairs (i < j) with |c_i - c_j| <= r_i + r_j + buffer, in ascending (i, j) order.
std::vector<std::pair<std::uint32_t, std::uint32_t>>
findCandidatePairs(const std::vector<BoundingCircle>& circles, Real buffer);

} // namespace veridem::fdem
