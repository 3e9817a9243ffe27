// Incremental Delaunay triangulation of points in the plane (Bowyer 1981, Watson 1981: each new
// point removes the triangles whose circumcircle contains it, the "cavity", and is joined to the
// cavity's boundary). Used by the polygon mesher (mesher.h) on points it places itself.
//
// Triangles keep their three neighbours, so a point is located by walking from the last triangle
// made (points inserted in a spatially coherent order make the walk short) and the cavity is grown
// from the triangle that holds the point through neighbours whose circumcircle holds it too: the
// cost per point is that of its cavity, not of the whole triangulation. The predicates are plain
// floating point (no exact arithmetic): the mesher only inserts points that are at least a fraction
// of the edge length apart, and it checks the result (orientation and area) before returning it.
#pragma once

#include "fdem/vec2.h"

#include <array>
#include <cstdint>
#include <vector>

namespace veridem::fdem
{

class DelaunayTriangulation
{
  public:
    /// Starts with a triangle enclosing the box [lo, hi] [m] with a wide margin (3 helper points).
    DelaunayTriangulation(Vec2 lo, Vec2 hi);

    /// Inserts a point [m] strictly inside the enclosing triangle; returns its index (the helper
    /// points take indices 0, 1, 2, so the first inserted point is 3).
    std::uint32_t insert(Vec2 p);

    /// True if the segment between points a and b is an edge of the triangulation.
    bool hasEdge(std::uint32_t a, std::uint32_t b) const;

    const std::vector<Vec2>& points() const { return points_; }

    /// The counter-clockwise triangles that use none of the 3 helper points (indices into points()).
    std::vector<std::array<std::uint32_t, 3>> triangles() const;

  private:
    static constexpr std::uint32_t kNone = ~0u;
    std::uint32_t locate(Vec2 p) const;
    bool inCircumcircle(std::uint32_t t, Vec2 p) const;

    std::vector<Vec2> points_;
    std::vector<std::array<std::uint32_t, 3>> corners_; // counter-clockwise
    std::vector<std::array<std::uint32_t, 3>>
        neighbour_; // neighbour_[t][k]: across the edge opposite corner k
    std::vector<std::uint8_t> alive_;
    std::vector<std::uint8_t> mark_;           // scratch of insert(): triangles in the cavity
    std::vector<std::uint32_t> pointTriangle_; // a live triangle using each point (for hasEdge)
    std::uint32_t last_ = 0;
};

} // namespace veridem::fdem
