// Chung & Ooi (2011) test 1, glass: two identical spheres, R = 10 mm, E = 48 GPa, nu = 0.2,
// rho = 2800, head-on at +-10 m/s, elastic (e = 1), Hertz contact.
//   E* = E / (2 (1 - nu^2)), R* = R/2, m* = m/2, v = 20 m/s relative
//   delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5),  F_max = (4/3) E* sqrt(R*) delta_max^(3/2),
//   tc = 2.868 (m*^2 / (R* E*^2 v))^(1/5)
// 1 % each (BENCHMARKS 7 #10; 1000 steps per contact resolve the peak to ~1e-5), e = 1 within 1e-3.
#include "support.h"

namespace veridem::verify
{
namespace
{
CaseResult run(const CaseContext& context)
{
    Material glass;
    glass.name = "glass";
    glass.density = 2800;
    glass.normalModel = dem::NormalModel::Hertz;
    glass.youngsModulus = 48e9;
    glass.poissonRatio = 0.2;
    glass.restitution = 1.0;
    glass.friction = 0.0;
    const Real radius = 0.01, speed = 10.0;
    World world = worldWith(glass, {0, 0, 0});
    world.particles.add({-radius - 1e-5, 0, 0}, {speed, 0, 0}, {}, radius, glass.density, 0);
    world.particles.add({radius + 1e-5, 0, 0}, {-speed, 0, 0}, {}, radius, glass.density, 0);

    const Real m = world.particles.mass[0];
    const Real mStar = m / 2, rStar = radius / 2, eStar = glass.youngsModulus / (2 * (1 - 0.2 * 0.2));
    const Real v = 2 * speed;
    const Real deltaMax = std::pow(15 * mStar * v * v / (16 * eStar * std::sqrt(rStar)), 0.4);
    const Real forceMax = 4.0 / 3.0 * eStar * std::sqrt(rStar) * std::pow(deltaMax, 1.5);
    const Real tc = 2.868 * std::pow(mStar * mStar / (rStar * eStar * eStar * v), 0.2);

    Real measuredDelta = 0, measuredForce = 0, tIn = -1, tOut = -1, previousGap = 2e-5, previousT = 0;
    runFor(world, 2e-6 + 1.5 * tc, tc / 1000, context, "hertz_impact",
           [&](const World& w)
           {
               const auto& p = w.particles;
               const Real gap = (p.position[1].x - p.position[0].x) - 2 * radius;
               measuredDelta = std::fmax(measuredDelta, -gap);
               measuredForce = std::fmax(measuredForce, -p.force[0].x);
               if (tIn < 0 && gap <= 0)
                   tIn = crossingTime(previousT, previousGap, w.time, gap);
               if (tIn >= 0 && tOut < 0 && gap > 0)
                   tOut = crossingTime(previousT, previousGap, w.time, gap);
               previousGap = gap;
               previousT = w.time;
           });
    CaseResult r;
    const char* why = "BENCHMARKS 7 #10 (Chung & Ooi test 1)";
    r.quantities.push_back(relativeQuantity("F_max", "N", forceMax, measuredForce, 1e-2, why));
    r.quantities.push_back(relativeQuantity("delta_max", "m", deltaMax, measuredDelta, 1e-2, why));
    r.quantities.push_back(relativeQuantity("tc", "s", tc, tOut - tIn, 1e-2, why));
    const Real e = (world.particles.velocity[1].x - world.particles.velocity[0].x) / v;
    r.quantities.push_back(relativeQuantity("e", "", 1.0, e, 1e-3, "elastic Hertz contact conserves energy"));
    return r;
}
} // namespace

VERIDEM_CASE({.name = "hertz_impact",
              .summary = "Chung & Ooi test 1 (glass): Hertz F_max, delta_max, tc, e = 1",
              .reference = "Chung & Ooi 2011; Johnson 1985; BENCHMARKS 4 and 7 #10",
              .labels = {"dem", "quick"},
              .run = run});
} // namespace veridem::verify
