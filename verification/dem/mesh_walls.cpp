// Mesh walls (dem/walls/mesh_wall.h) against the analytic plane and turntable, through the same
// set-ups (bowling_ball.h, rolling_resistance_stop.h, turntable.h) on meshed stand-ins
// (mesh_floors.h: irregular triangles with slivers, a path along edges and over vertices).
// mesh_plane_equivalence: the bowling ball and the type A rolling stop on a meshed floor meet the
//   plane cases' formulas with the plane cases' tolerances, and their paths equal the plane runs'
//   to 1e-9 m (a face contact of a flat mesh is the plane's contact; an edge or vertex one differs
//   from it by round-off in the normal, ~1e-16).
// mesh_edge_crossing: a ball rolling across edges, along an edge and over the vertices on it keeps
//   v = 5/7 v0 (it neither catches on an edge nor feels two contacts) and a normal force m g to
//   1e-9 relative (the contact-elimination rule: one contact on a connected flat surface).
// turntable_t1b_mesh: Test 1b on a meshed disk turning at 10 rad/s: the orbit of 2/7 Omega within
//   0.2 % (the mesh turns with the table; the contact takes the exact surface velocity).
#include "bowling_ball.h"
#include "mesh_floors.h"
#include "rolling_resistance_stop.h"
#include "turntable.h"

#include <algorithm>
#include <cmath>

namespace veridem::verify
{
namespace
{

/// The floor of the mesh cases: [-0.5, 3.5] x [-0.5, 0.5] m in 16 x 8 cells (a 0.25 x 0.125 m cell).
dem::Wall floorMesh()
{
    return meshedFloor(-0.5, 3.5, 0.5, 16, 8);
}

Real largestDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
    if (a.size() != b.size())
        throw SimulationError("mesh_plane_equivalence: the paths have different lengths");
    Real largest = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        largest = std::fmax(largest, length(a[k] - b[k]));
    return largest;
}

void prefixed(CaseResult& into, const CaseResult& from, const std::string& prefix)
{
    for (Quantity q : from.quantities)
    {
        q.name = prefix + q.name;
        into.quantities.push_back(q);
    }
}

CaseResult runEquivalence(const CaseContext& context)
{
    CaseResult r;
    std::vector<Vec3> planePath, meshPath;
    bowlingBall(context, floorWall(), &planePath);
    prefixed(r, bowlingBall(context, floorMesh(), &meshPath), "mesh bowling: ");
    r.quantities.push_back(absoluteQuantity("bowling: max |x_mesh - x_plane|", "m", 0,
                                            largestDistance(planePath, meshPath), 1e-9,
                                            "the same contact up to round-off in the normal"));

    planePath.clear();
    meshPath.clear();
    const Real a = kFlatBallRadius, v0 = 0.1, muR = flatTurntableBall().rollingFrictionLength;
    Real planeDrift = 0, meshDrift = 0;
    rollingStopDistance(context, floorWall(), planeDrift, &planePath);
    const Real stop = rollingStopDistance(context, floorMesh(), meshDrift, &meshPath);
    r.quantities.push_back(relativeQuantity("mesh: type A stop distance", "m",
                                            7 * a * v0 * v0 / (10 * muR * kG), stop, 1e-2,
                                            "BENCHMARKS 7 #12 (as rolling_resistance_stop)"));
    r.quantities.push_back(
        absoluteQuantity("mesh: type A drift after stop (5 s)", "m", 0, meshDrift, 1e-6,
                         "rest treatment: no chatter at rest (as rolling_resistance_stop)"));
    r.quantities.push_back(absoluteQuantity("rolling stop: max |x_mesh - x_plane|", "m", 0,
                                            largestDistance(planePath, meshPath), 1e-9,
                                            "the same contact up to round-off in the normal"));
    return r;
}

CaseResult runEdgeCrossing(const CaseContext& context)
{
    // The bowling ball's material and launch (bowling_ball.cpp), two balls: one along y = 0 (on
    // the row of edges and over its vertices), one at y = 0.046 m crossing edges and diagonals.
    // Checked from 0.05 s after the end of sliding, when both balls roll (about 2 m, 8 cells of
    // edges and vertices): by then the start's normal transient (the first half kick is gravity
    // alone, as on a plane; damped at ~240 1/s) is below 1e-12.
    Material steel = flatTurntableBall();
    steel.friction = 0.3;
    steel.rollingModel = dem::RollingModel::None;
    const Real a = kFlatBallRadius, v0 = 2.0;
    World world = worldWith(steel, {0, 0, -kG});
    world.walls.push_back(floorMesh());
    const Real m = sphereMass(steel.density, a);
    const Real restingOverlap = m * kG / steel.normalStiffness;
    for (const Real y : {0.0, 0.046})
        world.particles.add({0, y, a - restingOverlap}, {v0, 0, 0}, {}, a, steel.density, 0);
    const Real tStar = 2 * v0 / (7 * steel.friction * kG), rolling = 5.0 / 7.0 * v0;
    Real speedError = 0, forceError = 0;
    std::size_t mostContacts = 0;
    runFor(world, 1.5, 1e-5, context, "mesh_edge_crossing",
           [&](const World& w)
           {
               mostContacts = std::max(mostContacts, w.health.touchingWalls);
               for (std::size_t i = 0; i < 2; ++i)
               {
                   if (w.time < tStar + 0.05) // past the end of sliding and its O(tc) transition
                       continue;
                   forceError = std::fmax(forceError, std::fabs(w.particles.force[i].z - m * kG) / (m * kG));
                   speedError =
                       std::fmax(speedError, std::fabs(length(w.particles.velocity[i]) - rolling) / rolling);
               }
           });
    CaseResult r;
    r.quantities.push_back(absoluteQuantity("max |v - 5/7 v0| / (5/7 v0) while rolling", "", 0, speedError,
                                            1e-6,
                                            "as bowling_ball's v_final: angular momentum about the contact "
                                            "point is conserved exactly on a flat surface"));
    r.quantities.push_back(absoluteQuantity("max |F_n - m g| / (m g)", "", 0, forceError, 1e-9,
                                            "one contact at the resting overlap (round-off only)"));
    r.quantities.push_back(absoluteQuantity("most touching wall contacts (2 balls)", "", 2,
                                            Real(mostContacts), 0,
                                            "one contact per ball on a connected flat surface"));
    return r;
}

CaseResult runMeshTurntable(const CaseContext& context)
{
    TurntableSetup s = orbitSetup();
    s.meshedTable = true;
    return turntableOrbit(context, s);
}

} // namespace

VERIDEM_CASE(
    {.name = "mesh_plane_equivalence",
     .summary = "bowling ball and type A rolling stop on an irregular meshed floor equal the plane's",
     .reference = "BENCHMARKS 5 #2 and 7 #12; Su et al. 2011 contact elimination",
     .labels = {"dem", "quick"},
     .run = runEquivalence});
VERIDEM_CASE({.name = "mesh_edge_crossing",
              .summary = "rolling across mesh edges and vertices: v = 5/7 v0 and F_n = m g throughout",
              .reference = "Kremmer & Favier 2001; Su et al. 2011; Hu et al. 2013",
              .labels = {"dem", "quick"},
              .run = runEdgeCrossing});
VERIDEM_CASE({.name = "turntable_t1b_mesh",
              .summary = "paper Test 1b on a meshed disk turning at 10 rad/s: orbit at 2/7 Omega",
              .reference = "Weltner 1979; Xiang et al. Fig. 3; BENCHMARKS 1b T1b",
              .labels = {"dem", "quick"},
              .run = runMeshTurntable});
} // namespace veridem::verify
