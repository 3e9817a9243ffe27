// Built-in meshers: structured rectangles, simple polygons (ear clipping, or refined with interior
// nodes to a target edge length: polygon_mesher.cpp) and discs.
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

/// The vertices of a simple polygon in counter-clockwise order (reversed if given clockwise).
/// Throws InputError as meshPolygon.
std::vector<Vec2> counterClockwiseOutline(const std::vector<Vec2>& vertices);

/// The same polygon meshed with interior nodes and roughly equilateral triangles of edge length
/// ~`edgeLength` [m] (polygon_mesher.cpp): boundary edges split into pieces of ~edgeLength, a
/// triangular lattice of spacing edgeLength inside (points closer than edgeLength / 2 to the outline
/// dropped), the Delaunay triangulation of all points with the outline's pieces recovered, then
/// smoothing of the interior nodes. The polygon's area is kept exactly (its vertices are nodes).
/// Throws InputError as meshPolygon, and for edgeLength not > 0.
TriangleMesh meshPolygonRefined(const std::vector<Vec2>& vertices, Real edgeLength);

/// Vertices of the regular polygon inscribed in the circle (centre [m], radius [m]) with
/// max(12, ceil(2 pi radius / edgeLength)) sides, counter-clockwise from angle 0: the outline of a
/// disc meshed to `edgeLength` [m]. Throws InputError for radius or edgeLength not > 0.
std::vector<Vec2> discOutline(Vec2 centre, Real radius, Real edgeLength);

} // namespace veridem::fdem
