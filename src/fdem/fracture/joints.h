// Joint (crack) elements between the triangles of a body (Munjiza 2004 ch. 7): each selected
// interior edge is split, the two triangles get their own copies of its nodes, and a four-node joint
// element ties the copies with the cohesive law of fracture/cohesive_law.h until it breaks.
//
// Kinematics of joint (a0, a1 | b0, b1): a0 -> a1 is the edge of triangle A (counter-clockwise in A),
// b0 and b1 are B's copies of the points of a0 and a1. At the two integration points k = 0, 1 (the
// edge's ends: Newton-Cotes/Lobatto integration, the usual choice for interface elements because it
// does not couple the two ends' tractions; Schellekens & de Borst, IJNME 36:43, 1993) the jump is
// delta_k = x(b_k) - x(a_k); with the current mid-line tangent t = unit((x_a1 + x_b1 - x_a0 - x_b0)/2)
// and the normal n = (t_y, -t_x) (outward of A), the opening is o_k = delta_k . n and the slip
// s_k = delta_k . t. Each point carries half of the reference length L: the nodal forces are
// f(a_k) = (L/2)(sigma_k n + tau_k t) and f(b_k) = -f(a_k) (so they sum to zero). The joint size h of
// the law is L. A joint is broken (and removed) when the damage of either point reaches 1; its two
// edges then interact through the potential contact with friction like any two bodies.
#pragma once

#include "fdem/fracture/cohesive_law.h"
#include "fdem/mesh.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace veridem::fdem
{

/// A mesh whose selected edges were split, and the joints to insert (indices local to the mesh).
struct SplitMesh
{
    TriangleMesh mesh;
    std::vector<std::array<std::uint32_t, 4>> jointNodes;     ///< a0, a1, b0, b1
    std::vector<std::array<std::uint32_t, 2>> jointTriangles; ///< A, B
};

/// Splits the interior edges of a counter-clockwise mesh for which `selected(p, q)` is true (p, q the
/// edge's end points [m]). Nodes stay shared across the edges that are not split, so a partial
/// selection ends in a crack tip. Deterministic: nodes are numbered by their first corner.
SplitMesh splitForJoints(const TriangleMesh& mesh, const std::function<bool(Vec2, Vec2)>& selected);

/// The joints of the world (structure of arrays).
struct JointStore
{
    std::vector<std::array<std::uint32_t, 4>> nodes;     ///< a0, a1, b0, b1 (global node ids)
    std::vector<std::array<std::uint32_t, 2>> triangles; ///< A, B (global triangle ids)
    std::vector<Real> length;                            ///< reference length L = h [m]
    std::vector<std::uint32_t> material;                 ///< index into World materials
    std::vector<std::array<Real, 2>> damage;             ///< D_max of each integration point [1]
    std::vector<std::array<Real, 2>> opening;            ///< o of the last step [m]
    std::vector<std::array<Real, 2>> slip;               ///< s of the last step [m]
    std::vector<std::array<Real, 2>> normalTraction;     ///< sigma of the last step [Pa]
    std::vector<std::array<Real, 2>> shearTraction;      ///< tau of the last step [Pa]
    std::vector<Real> work;     ///< work done on the joint since t = 0 (trapezoidal) [J/m]
    std::vector<Real> brokenAt; ///< time of breaking [s]; NaN while intact
    std::vector<std::uint8_t> broken;
    std::vector<std::array<Vec2, 2>> endForce; ///< scratch of the step: forces on a0, a1 [N/m]
    std::vector<std::uint8_t> event;           ///< scratch of the step: 1 evaluated, 2 broke (evaluateJoints)

    std::size_t size() const { return nodes.size(); }
};

/// Joint states and end forces of one step, on the thread pool: each intact joint's endForce (on a0
/// and a1; b0 and b1 get the opposite) [N/m] and event (1: evaluated and intact, 2: broke in this
/// step, 0: broken before). Returns the joints broken in this step (their brokenAt is set to `time`
/// [s]). The caller adds the forces of the event-1 joints to the nodes in joint order.
std::vector<std::uint32_t> evaluateJoints(JointStore& joints, const std::vector<Vec2>& position,
                                          const std::vector<CohesiveConstants>& laws, Real time);

/// The law's constants, after checking that the parameters are finite and phi in [0, 90) degrees
/// (InputError naming `where`); default constants when f_t, G_f, G_II, c or p is not > 0 (a body of
/// that material may not crack: World::addBody says which is missing).
CohesiveConstants checkedCohesiveConstants(const FractureParameters& f, const std::string& where);

/// Largest joint size h [m] for which softening with this law cannot snap back against the elastic
/// element beside it (crack band argument, Bazant & Oh 1983: the softening stiffness
/// f_t max|z'| / (o_c - o_p) must not exceed E / h): h_max = E G_f / (f_t^2 Z max|z'|).
Real snapBackSize(const CohesiveConstants& law, Real youngsModulus);

} // namespace veridem::fdem
