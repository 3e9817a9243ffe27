// Data of the 2D FEM/DEM world, in structure-of-arrays form (STYLE.md section 3.7).
// Everything is per unit thickness (plane problems): masses in kg/m, forces in N/m.
#pragma once

#include "fdem/vec2.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace veridem::fdem
{

/// A triangulation as produced by the mesher or read from a .msh file (geometry only).
struct TriangleMesh
{
    std::vector<Vec2> points;                            ///< [m]
    std::vector<std::array<std::uint32_t, 3>> triangles; ///< node indices into points
};

/// Checks a triangulation and returns it with every triangle counter-clockwise. A mesh whose
/// triangles are all clockwise is flipped; a mix of orientations (an inverted triangle), a
/// degenerate triangle (area <= 1e-10 of its squared longest edge), an index out of range or a
/// non-finite coordinate throws InputError naming `source` and the triangle.
TriangleMesh validatedMesh(TriangleMesh mesh, const std::string& source);

/// Nodes (hot data first). Central-difference state: `position` at t_n, `velocity` at t_{n-1/2}.
struct NodeStore
{
    std::vector<Vec2> position;           ///< x [m]
    std::vector<Vec2> velocity;           ///< v [m/s] (half-step velocity)
    std::vector<Vec2> force;              ///< f [N/m], total force of the current step
    std::vector<Real> mass;               ///< lumped mass [kg/m]
    std::vector<Real> inverseMass;        ///< 1/mass [m/kg]; 0 for prescribed nodes
    std::vector<Vec2> referencePosition;  ///< X [m] at creation
    std::vector<std::uint8_t> prescribed; ///< 1: velocity prescribed (fixed node), not integrated
    std::vector<std::uint32_t> body;      ///< owning body id

    std::size_t size() const { return position.size(); }
};

/// Triangles. `referenceInverse` is X0^-1 of elements/cst.h.
struct TriangleStore
{
    std::vector<std::array<std::uint32_t, 3>> nodes; ///< counter-clockwise node ids
    std::vector<Mat2> referenceInverse;              ///< X0^-1 [1/m]
    std::vector<Real> referenceArea;                 ///< A0 [m^2]
    std::vector<std::uint32_t> material;             ///< index into World materials
    std::vector<std::uint32_t> body;                 ///< owning body id
    std::vector<SymTensor2> stress;                  ///< Cauchy stress of the last step [Pa]

    std::size_t size() const { return nodes.size(); }
};

/// Smallest altitude of a triangle [m].
Real minimumAltitude(const Vec2& a, const Vec2& b, const Vec2& c);
/// Longest edge of a triangle [m].
Real longestEdge(const Vec2& a, const Vec2& b, const Vec2& c);

} // namespace veridem::fdem
