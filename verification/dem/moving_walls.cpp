// Moving plane walls (translation enters the relative velocity and moves the geometry).
// Conveyor: a ball at rest dropped (resting overlap) on a belt moving at U along x. In the belt
//   frame this is the bowling ball with v0 = -U, so the ball ends rolling at v_f = (2/7) U (lab)
//   after t* = 2 U / (7 mu g). v_f follows from angular momentum about the contact point, kept to
//   round-off: 1e-6; t* 0.5 % (the soft contact's O(tc) transition, as for the bowling ball).
// Piston: a plane moving at V along its normal hits a ball at rest (no gravity). The wall has
//   infinite mass, so the ball leaves at (1 + e) V: 0.3 % at >= 50 steps per contact
//   (BENCHMARKS 2.1, as for the fixed wall).
#include "support.h"

namespace veridem::verify
{
namespace
{
CaseResult run(const CaseContext& context)
{
    CaseResult r;
    {
        Material steel = flatTurntableBall();
        steel.friction = 0.3;
        steel.rollingModel = dem::RollingModel::None;
        const Real a = kFlatBallRadius, belt = 1.0, mu = steel.friction;
        World world = worldWith(steel, {0, 0, -kG});
        dem::Wall wall = floorWall();
        wall.motion.velocity = {belt, 0, 0};
        world.walls.push_back(wall);
        const Real m = sphereMass(steel.density, a);
        world.particles.add({0, 0, a - m * kG / steel.normalStiffness}, {}, {}, a, steel.density, 0);
        Real tStar = -1, previousSlip = -belt, previousT = 0;
        runFor(world, 0.3, 1e-5, context, "moving_walls",
               [&](const World& w)
               {
                   const Real slip = w.particles.velocity[0].x - a * w.particles.angularVelocity[0].y - belt;
                   if (tStar < 0 && slip >= 0)
                       tStar = crossingTime(previousT, previousSlip, w.time, slip);
                   previousSlip = slip;
                   previousT = w.time;
               });
        r.quantities.push_back(relativeQuantity("conveyor v_final", "m/s", 2.0 / 7.0 * belt,
                                                world.particles.velocity[0].x, 1e-6,
                                                "angular momentum about the contact point"));
        r.quantities.push_back(relativeQuantity("conveyor t*", "s", 2 * belt / (7 * mu * kG), tStar, 5e-3,
                                                "O(tc) spring loading, as for the bowling ball"));
    }
    {
        const Material steel = flatTurntableBall();
        const Real a = kFlatBallRadius, speed = 0.5;
        World world = worldWith(steel, {0, 0, 0});
        dem::Wall piston = floorWall();
        piston.shape = dem::PlaneShape{{0, 0, -1e-4}, {0, 0, 1}};
        piston.motion.velocity = {0, 0, speed};
        world.walls.push_back(piston);
        world.particles.add({0, 0, a}, {}, {}, a, steel.density, 0);
        const Real tc = kPi / std::sqrt(steel.normalStiffness / world.particles.mass[0]);
        runFor(world, 1e-4 / speed + 2 * tc, tc / 100, context, "moving_walls", nullptr);
        r.quantities.push_back(relativeQuantity("piston rebound", "m/s", (1 + steel.restitution) * speed,
                                                world.particles.velocity[0].z, 3e-3, "BENCHMARKS 2.1"));
    }
    return r;
}
} // namespace

VERIDEM_CASE(
    {.name = "moving_walls",
     .summary = "translating planes: ball on a conveyor ends at 2/7 U; piston throws a ball at (1+e) V",
     .reference = "rigid-body mechanics (bowling ball in the belt frame); BENCHMARKS 2.1",
     .labels = {"dem", "quick"},
     .run = run});
VERIDEM_SWEEP(
    "moving_walls",
    {.orders = {
         {"conveyor t*", 1.0,
          "the end of sliding is resolved by the tangential spring, first order (convergence_orders)"}}});
} // namespace veridem::verify
