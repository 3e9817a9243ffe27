// No-slip oblique impact with linear springs, undamped, full stick (mu large): during the contact
// time tc = pi/omega_n the contact-point tangential velocity oscillates at
// omega_t = sqrt(kt / ((2/7) m)) = omega_n sqrt(3.5 kt/kn), so it leaves reversed by
//     Vt'/Vt = cos(pi sqrt(3.5 kt/kn))      (BENCHMARKS 2.2)
// kt/kn = 2/7 gives perfect reversal (-1), 0.5 gives -0.528, 1.0 gives +0.919.
// 1000 steps per contact: the start and end of the contact are known to within a step, which
// shifts the tangential phase by at most omega_t dt = pi sqrt(3.5 kt/kn)/1000 <= 0.006 rad, so the
// ratio is checked to 0.01 absolute.
#include "support.h"

#include <cstdio>

namespace veridem::verify
{
namespace
{
CaseResult run(const CaseContext& context)
{
    CaseResult r;
    for (const Real ratio : {2.0 / 7.0, 0.5, 1.0})
    {
        Material m = flatTurntableBall();
        m.restitution = 1.0;
        m.friction = 10.0;
        m.rollingModel = dem::RollingModel::None;
        m.tangentialStiffnessRatio = ratio;
        const Real a = kFlatBallRadius, vn = 1.0, vt = 0.1;
        World world = worldWith(m, {0, 0, 0});
        world.walls.push_back(floorWall());
        world.particles.add({0, 0, a + 1e-4}, {vt, 0, -vn}, {}, a, m.density, 0);
        const Real mass = world.particles.mass[0];
        const Real tc = kPi * std::sqrt(mass / m.normalStiffness);
        runFor(world, 1e-4 / vn + 1.5 * tc, tc / 1000, context, "tangential_reversal", nullptr);
        const auto& p = world.particles;
        const Real contactPointVt = p.velocity[0].x + a * -p.angularVelocity[0].y; // v + w x (-a z)
        char name[64];
        std::snprintf(name, sizeof name, "Vt'/Vt (kt/kn=%.4g)", ratio);
        r.quantities.push_back(absoluteQuantity(name, "", std::cos(kPi * std::sqrt(3.5 * ratio)),
                                                contactPointVt / vt, 1e-2,
                                                "contact start/end within one step of 1000"));
    }
    return r;
}
} // namespace

VERIDEM_CASE({.name = "tangential_reversal",
              .summary = "no-slip oblique impact: tangential velocity factor cos(pi sqrt(3.5 kt/kn))",
              .reference = "BENCHMARKS 2.2",
              .labels = {"dem", "quick"},
              .run = run});
VERIDEM_SWEEP(
    "tangential_reversal",
    {.orders = {
         {"Vt'/Vt", 1.0,
          "the tangential spring adds the slip of the whole first step: first order (convergence_orders)"}}});
} // namespace veridem::verify
