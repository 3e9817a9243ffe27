// Rolling-resistance models of Ai, Chen, Rotter & Ooi (2011) beyond types A and C
// (rolling_resistance_stop): type B, viscous, M = -c_r Fn R_r^2 w_rel (models/rolling.h), and the
// absolute-frame variant of type A, M = -muR Fn w/|w| with the particle's own w (EDEM "standard",
// MUSEN). A ball (the paper's flat ball, a = 6.35 mm) rolls without slipping on a fixed plane, so
// w_rel = w and I_eff = (7/5) m a^2 about the contact point [D]:
//   type B, plane:   v(t) = v0 exp(-t/tau), tau = 7/(5 c_r g); distance x(t) = v0 tau (1 - exp(-t/tau))
//                    (it never stops: x -> v0 tau);
//   type B, incline: from rest, v(t) = v_inf (1 - exp(-t/tau')), v_inf = tan(theta)/c_r,
//                    tau' = 7/(5 c_r g cos(theta)); it never holds a ball at rest;
//   type A absolute, plane: s = 7 a v0^2/(10 muR g) (as type A: w_rel = w on a fixed plane);
//   type A absolute, incline: a = (5/7) g (sin(theta) - (muR/a) cos(theta)).
// Tolerances: 1e-3 relative on the type B closed forms (the torque uses the half-step w, a
// first-order lag of dt/2 in a decay of time constant tau = 2 s: dt/(2 tau) = 2.5e-6, and the
// contact's elastic compliance, overlap/a = 1.3e-4, changes the lever arm by as much); type A as
// rolling_resistance_stop, 1 %.
#include "support.h"

#include <cstdio>

namespace veridem::verify
{
namespace
{
struct Rolled
{
    Real distance, velocity;
    std::vector<std::vector<double>> path; // t, x, v
};

Rolled roll(dem::RollingModel model, Real coefficient, Real tanTheta, Real v0, Real duration, Real dt,
            const CaseContext& context)
{
    Material m = flatTurntableBall();
    m.rollingModel = model;
    m.rollingViscousCoefficient = model == dem::RollingModel::Viscous ? coefficient : 0.0;
    m.rollingFrictionLength = model == dem::RollingModel::Viscous ? 0.0 : coefficient;
    const Real theta = std::atan(tanTheta), a = kFlatBallRadius;
    World world = worldWith(m, {kG * std::sin(theta), 0, -kG * std::cos(theta)});
    world.walls.push_back(floorWall());
    const Real mass = sphereMass(m.density, a);
    world.particles.add({0, 0, a - mass * kG * std::cos(theta) / m.normalStiffness}, {v0, 0, 0},
                        {0, v0 / a, 0}, a, m.density, 0);
    Rolled r{};
    std::uint64_t n = 0;
    runFor(world, duration, dt, context, "rolling_resistance_models",
           [&](const World& w)
           {
               if (++n % 2000 == 0)
                   r.path.push_back({w.time, w.particles.position[0].x, w.particles.velocity[0].x});
           });
    r.distance = world.particles.position[0].x;
    r.velocity = world.particles.velocity[0].x;
    return r;
}

CaseResult run(const CaseContext& context)
{
    CaseResult r;
    const Real a = kFlatBallRadius, dt = 1e-5;
    // Type B on a plane: c_r = 7/(5 g tau) with tau = 2 s; 10 s = 5 tau.
    const Real tau = 2.0, c = 7.0 / (5.0 * kG * tau), v0 = 0.1;
    const Rolled plane = roll(dem::RollingModel::Viscous, c, 0.0, v0, 5 * tau, dt, context);
    const char* whyB = "half-step w lag dt/(2 tau) and elastic lever arm, both ~1e-4";
    r.quantities.push_back(relativeQuantity("type B plane: x(5 tau) = v0 tau (1 - e^-5)", "m",
                                            v0 * tau * (1 - std::exp(-5.0)), plane.distance, 1e-3, whyB));
    r.quantities.push_back(relativeQuantity("type B plane: v(5 tau) = v0 e^-5", "m/s", v0 * std::exp(-5.0),
                                            plane.velocity, 1e-3, whyB));
    Series sp{"type_b_plane", {"t", "x", "v", "x_theory"}, {}};
    for (auto row : plane.path)
    {
        row.push_back(v0 * tau * (1 - std::exp(-row[0] / tau)));
        sp.rows.push_back(row);
    }
    r.series.push_back(std::move(sp));
    // Type B on an incline tan(theta) = 0.05 from rest: v_inf = 0.7 m/s.
    const Real tanTheta = 0.05, cosTheta = 1 / std::sqrt(1 + tanTheta * tanTheta);
    const Real tauIncline = 7.0 / (5.0 * c * kG * cosTheta), vInf = tanTheta / c;
    const Rolled incline = roll(dem::RollingModel::Viscous, c, tanTheta, 0.0, 3 * tauIncline, dt, context);
    r.quantities.push_back(relativeQuantity("type B incline: v(3 tau') = (tan/c_r)(1 - e^-3)", "m/s",
                                            vInf * (1 - std::exp(-3.0)), incline.velocity, 1e-3, whyB));
    Series si{"type_b_incline", {"t", "x", "v", "v_theory"}, {}};
    for (auto row : incline.path)
    {
        row.push_back(vInf * (1 - std::exp(-row[0] / tauIncline)));
        si.rows.push_back(row);
    }
    r.series.push_back(std::move(si));
    // Type A, absolute frame: on a fixed plane it is type A.
    const Real muR = flatTurntableBall().rollingFrictionLength, v0a = 0.02;
    const Real stopTime = 7 * a * v0a / (5 * muR * kG);
    const Rolled absolute =
        roll(dem::RollingModel::ConstantTorqueAbsolute, muR, 0.0, v0a, 1.2 * stopTime, dt, context);
    r.quantities.push_back(relativeQuantity("type A absolute plane: stop distance 7 a v0^2/(10 muR g)", "m",
                                            7 * a * v0a * v0a / (10 * muR * kG), absolute.distance, 1e-2,
                                            "as rolling_resistance_stop (BENCHMARKS 7 #12)"));
    const Real tanA = 4 * muR / a, thetaA = std::atan(tanA);
    const Rolled down = roll(dem::RollingModel::ConstantTorqueAbsolute, muR, tanA, 0.0, 2.0, dt, context);
    r.quantities.push_back(
        relativeQuantity("type A absolute incline tan = 4 muR/a: v(2 s)", "m/s",
                         5.0 / 7.0 * kG * (std::sin(thetaA) - muR / a * std::cos(thetaA)) * 2.0,
                         down.velocity, 1e-2, "as rolling_resistance_stop"));
    return r;
}
} // namespace

VERIDEM_CASE({.name = "rolling_resistance_models",
              .summary = "type B (viscous) and absolute-frame type A: plane and incline closed forms",
              .reference = "Ai, Chen, Rotter & Ooi 2011; BENCHMARKS 2.3",
              .labels = {"dem", "quick", "rolling"},
              .run = run});
VERIDEM_SWEEP(
    "rolling_resistance_models",
    {.orders = {{"type B", 1.0, "the rolling torque uses the half-step w: an O(dt) lag (docs/models.md)"},
                {"type A absolute incline", 1.0, "the rolling torque uses the half-step w: first order"}}});
} // namespace veridem::verify
