// A ball released from rest on an incline of angle theta (here gravity is tilted and the plane
// is z = 0, which is the same physics).
//   rolls without slip if tan(theta) <= (7/2) mu:  a = (5/7) g sin(theta)
//   slides otherwise:                              a = g (sin(theta) - mu cos(theta))
// Runs on both sides of the threshold (theta = 20 deg: mu_c = (2/7) tan(theta) = 0.1040): mu =
// 0.5 and 0.11 roll, mu = 0.098 and 0.05 slide. The acceleration is the least-squares slope of
// v(t) over 0.1-0.5 s, after the tangential spring has loaded (tc ~ 1 ms): 0.5 % (BENCHMARKS 7 #8).
#include "support.h"

#include <cstdio>

namespace veridem::verify
{
namespace
{
CaseResult run(const CaseContext& context)
{
    const Real theta = degToRad(20.0);
    CaseResult r;
    for (const Real mu : {0.5, 0.11, 0.098, 0.05})
    {
        Material steel = flatTurntableBall();
        steel.friction = mu;
        steel.rollingModel = dem::RollingModel::None;
        const Real a = kFlatBallRadius;
        World world = worldWith(steel, {kG * std::sin(theta), 0, -kG * std::cos(theta)});
        world.walls.push_back(floorWall());
        const Real m = sphereMass(steel.density, a);
        world.particles.add({0, 0, a - m * kG * std::cos(theta) / steel.normalStiffness}, {}, {}, a,
                            steel.density, 0);
        std::vector<Real> t, v;
        runFor(world, 0.5, 1e-5, context, "incline_roll_or_slide",
               [&](const World& w)
               {
                   if (w.time >= 0.1 && w.stepCount % 100 == 0)
                   {
                       t.push_back(w.time);
                       v.push_back(w.particles.velocity[0].x);
                   }
               });
        const bool rolls = std::tan(theta) <= 3.5 * mu;
        const Real expected =
            rolls ? 5.0 / 7.0 * kG * std::sin(theta) : kG * (std::sin(theta) - mu * std::cos(theta));
        char name[64];
        std::snprintf(name, sizeof name, "a (mu=%.3g, %s)", mu, rolls ? "rolls" : "slides");
        r.quantities.push_back(
            relativeQuantity(name, "m/s^2", expected, fitSlope(t, v), 5e-3, "BENCHMARKS 7 #8"));
    }
    return r;
}
} // namespace

VERIDEM_CASE({.name = "incline_roll_or_slide",
              .summary = "ball on a 20 deg incline on both sides of tan(theta) = 7/2 mu",
              .reference = "BENCHMARKS 5 #1 and 7 #8",
              .labels = {"dem", "quick"},
              .run = run});
VERIDEM_SWEEP("incline_roll_or_slide", {});
} // namespace veridem::verify
