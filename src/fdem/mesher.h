// Built-in meshers: structured rectangles and simple polygons (ear clipping).
#pragma once

#include "fdem/mesh.h"

namespace veridem::fdem
{

enum class DiagonalPattern : std::uint8_t
{
    Right,     ///< every cell split along the same diagonal (lower-left to upper-right)
    Alternate, ///< diagonals alternate in a checkerboard (more isotropic)
};

/// Rectangle [origin, origin + size] split into nx x ny cells, each cut into 2 triangles.
/// origin, size [m]; nx, ny >= 1. Throws InputError for non-positive sizes or counts.
TriangleMesh meshRectangle(Vec2 origin, Vec2 size, int nx, int ny,
                           DiagonalPattern pattern = DiagonalPattern::Alternate);

/// A simple polygon (vertices [m] in either orientation, no self-intersection) triangulated by ear
/// clipping, without interior nodes. Throws InputError for fewer than 3 vertices, zero area or a
/// self-intersecting outline.
TriangleMesh meshPolygon(const std::vector<Vec2>& vertices);

} // namespace veridem::fdem
