// Newton's cradle with gaps (BENCHMARKS 5.6): five equal balls in a row, 1 mm apart (more than
// v0 tc = 64 um, so each collision ends before the next begins), elastic linear contacts (e = 1),
// no friction, no gravity; the first ball moves at v0 = 0.1 m/s. Hard-sphere theory: each
// collision of equal masses exchanges the velocities, so exactly one ball leaves, at v0, and the
// others are at rest. Checks:
//  * the last ball's speed equals v0, the others are at rest, to 1e-6 of v0: velocity Verlet
//    integrates the undamped linear spring symplectically, and the only error is the spring's
//    switch-on and switch-off between steps, which at 2000 steps per contact changes the
//    exchanged speed by ~(pi/2000)^2 per collision at most;
//  * momentum conserved to 1e-12 relative (Newton's third law, round-off only);
//  * kinetic energy after the cascade equal to the initial to 2e-6 (twice the speed tolerance).
#include "support.h"

namespace veridem::verify
{
namespace
{
CaseResult run(const CaseContext& context)
{
    Material ball = flatTurntableBall();
    ball.restitution = 1.0;
    ball.friction = 0;
    ball.rollingModel = dem::RollingModel::None;
    const Real radius = kFlatBallRadius, gap = 1e-3, v0 = 0.1;
    World world = worldWith(ball, {0, 0, 0});
    for (int i = 0; i < 5; ++i)
        world.particles.add({i * (2 * radius + gap), 0, 0}, {i == 0 ? v0 : 0.0, 0, 0}, {}, radius,
                            ball.density, 0);
    const Real m = world.particles.mass[0];
    const Real tc = kPi * std::sqrt(0.5 * m / ball.normalStiffness);
    const Real duration = 5 * gap / v0; // four gaps to close, then one more of free flight
    Series s{"velocities", {"t", "v_0", "v_1", "v_2", "v_3", "v_4"}, {}};
    std::uint64_t sample = 0;
    runFor(world, duration, tc / 2000, context, "asmar_newton_cradle",
           [&](const World& w)
           {
               if (++sample % 200 == 0)
               {
                   std::vector<double> row{w.time};
                   for (int i = 0; i < 5; ++i)
                       row.push_back(w.particles.velocity[static_cast<std::size_t>(i)].x);
                   s.rows.push_back(row);
               }
           });
    const auto& p = world.particles;
    Real rest = 0, momentum = 0, energy = 0;
    for (std::size_t i = 0; i < 5; ++i)
    {
        if (i < 4)
            rest = std::fmax(rest, length(p.velocity[i]) / v0);
        momentum += m * p.velocity[i].x;
        energy += 0.5 * m * lengthSquared(p.velocity[i]);
    }
    CaseResult r;
    const char* why = "symplectic spring; switch-on/off between steps at 2000 steps/contact";
    r.quantities.push_back(relativeQuantity("last ball's speed", "m/s", v0, p.velocity[4].x, 1e-6, why));
    r.quantities.push_back(absoluteQuantity("largest speed of the other balls / v0", "", 0, rest, 1e-6, why));
    r.quantities.push_back(
        relativeQuantity("momentum", "kg m/s", m * v0, momentum, 1e-12, "Newton's third law"));
    r.quantities.push_back(relativeQuantity("kinetic energy", "J", 0.5 * m * v0 * v0, energy, 2e-6, why));
    r.series.push_back(std::move(s));
    return r;
}
} // namespace

VERIDEM_CASE({.name = "asmar_newton_cradle",
              .summary = "Newton's cradle with gaps: one ball leaves at v0, momentum and energy conserved",
              .reference = "BENCHMARKS 5.6; Herrmann & Seitz 1982",
              .labels = {"dem", "quick", "asmar", "ranks"},
              .run = run});
VERIDEM_SWEEP("asmar_newton_cradle", {});
} // namespace veridem::verify
