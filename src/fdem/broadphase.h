// Broad phase of the 2D contact detection: linked-cell binning of triangle bounding boxes in O(N)
// time and memory (in the spirit of Munjiza & Andrews' NBS, IJNME 43:131, 1998; BENCHMARKS 6.4).
//
// Each triangle gets its axis-aligned bounding box. With a buffer (Verlet skin) b, a pair is a
// candidate when the boxes, each grown by b/2 on every side, overlap (the gap between them is at
// most b along both axes). Boxes rather than circles: a circle round a long or flat triangle
// reaches far past it (a rigid base of coarse cells under a fine block: every block row within
// the base's circle radius became a candidate and was tested every step). The cell size is the
// largest box side plus b, so candidates lie in the same or a neighbouring cell of their centres;
// each cell is tested against itself and its 4 "half-neighbourhood" cells (E, NE, N, NW), so each
// pair is tested once. The triangles are binned by a counting sort (no search tree). If the grid
// would have more than 4N + 1024 cells the cell size is enlarged, keeping memory O(N).
//
// Re-detection criterion: a node that moved by d since the last detection stays within the old
// box grown by d, so two triangles can only touch if their old boxes are at most 2 d_max apart.
// The candidate list is therefore valid until 2 d_max > b (World::step checks this).
#pragma once

#include "fdem/vec2.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace veridem::fdem
{

struct BoundingBox
{
    Vec2 lo, hi;         ///< corners [m]
    std::uint32_t group; ///< pairs in the same group are not reported (same body)
    bool active;         ///< pairs of two inactive (static) boxes are not reported
};

/// True if the gap between the boxes is at most `buffer` [m] along both axes.
inline bool withinBuffer(const BoundingBox& a, const BoundingBox& b, Real buffer)
{
    return a.lo.x - b.hi.x <= buffer && b.lo.x - a.hi.x <= buffer && a.lo.y - b.hi.y <= buffer &&
           b.lo.y - a.hi.y <= buffer;
}

/// Candidate pairs (i < j) of different groups, one of them active, withinBuffer(), in ascending
/// (i, j) order.
std::vector<std::pair<std::uint32_t, std::uint32_t>> findCandidatePairs(const std::vector<BoundingBox>& boxes,
                                                                        Real buffer);

} // namespace veridem::fdem
