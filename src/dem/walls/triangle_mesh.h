// A triangle surface in its body frame: vertices welded (within kWeldTolerance of the mesh's
// size: float32 STL files repeat a shared corner with a last-digit difference), triangles, edge and
// vertex adjacency, and a uniform grid over the triangles for O(1) queries near a point.
//
// Built once from a triangle soup (buildTriangleMesh: three corners per triangle, as the STL and
// Gmsh readers give them); never changed afterwards, so a moving mesh wall maps particles into
// this frame (mesh_wall.h) and the grid is never rebuilt.
#pragma once

#include "core/vec3.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace veridem::dem
{

class TriangleMesh
{
  public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    std::vector<Vec3> vertices;                              // [m]
    std::vector<std::array<std::uint32_t, 3>> triangles;     // vertex indices; edge e is (v[e], v[e+1 mod 3])
    std::vector<Vec3> normals;                               // unit, right-handed from the vertex order
    std::vector<std::array<std::uint32_t, 3>> triangleEdges; // edge id of each triangle edge
    // Per triangle and local edge e: the unit direction in the triangle's plane, perpendicular to
    // the edge, pointing into the triangle.
    std::vector<std::array<Vec3, 3>> inward;
    // Per triangle, what the contact query's distance lower bound reads (triangleFartherThan in
    // mesh_wall.h), copied from the arrays above into one 128-byte record so the bound takes one
    // direct load instead of the vertex indices, three vertices, the normal and the inward
    // directions from five arrays: corner v[0] [m], unit normal, the inward directions of edges
    // 0-2, and apexHeight = (v[0] - v[1]).inward[1], the distance [m] of v[0] from edge 1's line
    // (edges 0 and 2 pass through v[0]).
    struct alignas(64) Bound
    {
        Vec3 corner, normal;
        std::array<Vec3, 3> inward;
        Real apexHeight;
    };
    std::vector<Bound> bounds;
    // Edges (unique vertex pairs) with the triangles that use them: edge g's users are
    // edgeUsers[edgeStart[g], edgeStart[g+1]), each as triangle * 3 + local edge.
    std::vector<std::array<std::uint32_t, 2>> edges;
    std::vector<std::uint32_t> edgeStart, edgeUsers;
    // Vertex v's neighbours (the other ends of its edges): vertexNeighbours[vertexStart[v], ...[v+1]).
    std::vector<std::uint32_t> vertexStart, vertexNeighbours;

    Vec3 lower, upper;                            // bounding box [m]
    Real size = 0;                                // bounding-box diagonal [m]
    Real farthestVertex(const Vec3& point) const; // largest vertex distance from point [m]

    /// Triangles whose grid cells overlap the box [low, high] (each once, ascending), into `out`.
    void trianglesNear(const Vec3& low, const Vec3& high, std::vector<std::uint32_t>& out) const;

    std::size_t memoryBytes() const;

    // The grid (filled by buildTriangleMesh).
    Vec3 gridOrigin;
    Real cell = 1;
    std::array<int, 3> cells{1, 1, 1};
    std::vector<std::uint32_t> cellStart, cellTriangles;
};

/// What buildTriangleMesh found worth a warning (open boundary, non-manifold edges), one line
/// each, naming the source.
struct MeshReport
{
    std::vector<std::string> warnings;
};

/// Corners closer than this fraction of max(bounding-box diagonal, largest coordinate magnitude)
/// in every coordinate are one vertex [-]: ~10 float32 roundings (relative precision 6e-8), far
/// below any edge of a mesh a contact could resolve.
inline constexpr Real kWeldTolerance = 1e-6;

/// Welds the corners (3 per triangle, [m]) within kWeldTolerance (relative, above) and builds
/// adjacency and grid. Open edges and non-manifold edges are reported with an example edge and,
/// for open edges, the box around them.
/// Throws InputError naming `source` and the triangle index (from 0, in file order) of the first
/// degenerate triangle: twice its area below 1e-12 times the squared bounding-box diagonal (or
/// two corners welded together), and its line `lines[t]` of the source if `lines` is given (a text
/// format with one triangle a line). An empty soup is refused too.
TriangleMesh buildTriangleMesh(const std::vector<Vec3>& corners, const std::string& source,
                               MeshReport& report, const std::vector<std::size_t>& lines = {});

/// The feature of a triangle nearest to a point.
enum class MeshFeature : std::uint8_t
{
    Face,
    Edge,  // local edge `index` (v[index] to v[index+1 mod 3])
    Vertex // local vertex `index`
};

struct TrianglePoint
{
    Vec3 point; // closest point of the triangle [m]
    MeshFeature feature;
    std::uint8_t index;
};

/// The closest point of triangle (a, b, c) to p, classified by the Voronoi region of the triangle
/// it falls in (Ericson, Real-Time Collision Detection, 2005, sec. 5.1.5).
TrianglePoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace veridem::dem
