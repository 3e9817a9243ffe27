// Ball on a vibrating plate (Asmar et al. 2002 style; BENCHMARKS 3 #7): a plate z_p = A sin(W t)
// carries a ball resting on it. The plate pushes down on the ball only as long as its
// acceleration -A W^2 sin(W t) is above -g, so the ball leaves the plate exactly when
// Gamma = A W^2 / g first exceeds 1, at the phase sin(phi) = 1/Gamma of the first period; for
// Gamma < 1 it never leaves.
// Set-up: W = 2 pi 20 Hz, Gamma = 0.8, 0.95, 1.05, 1.2, 1.5, 2, 3 (A from Gamma), a stiff heavily
// damped contact (kn = 1e8 N/m, e = 0.1) so that the ball follows the plate quasi-statically; the
// ball starts at the static overlap with the plate's velocity A W. The plate's sinusoidal motion
// is WallMotion's oscillation (walls/wall.h).
// Tolerances: the contact follows the plate with a lag of about 2 zeta / omega_n (= 1.1e-5 s, a
// phase of 1.4e-3 rad at 20 Hz), so the lift-off phase is checked to 5e-3 rad. A lift-off is a
// step with zero overlap; for Gamma < 1 there must be none over two periods.
#include "dem/models/normal.h"
#include "support.h"

#include <cstdio>

namespace veridem::verify
{
namespace
{
CaseResult run(const CaseContext& context)
{
    CaseResult r;
    Material ball = flatTurntableBall();
    ball.normalStiffness = 1e8;
    ball.restitution = 0.1;
    ball.friction = 0;
    ball.rollingModel = dem::RollingModel::None;
    const Real radius = kFlatBallRadius, w = 2 * kPi * 20;
    const Real m = sphereMass(ball.density, radius);
    const Real omegaN = std::sqrt(ball.normalStiffness / m);
    const Real dt = kPi / omegaN / 100; // 100 steps per contact period
    Series s{"takeoff", {"Gamma", "phi_deg", "phi_deg_theory"}, {}};
    Real worstPhase = 0;
    int spuriousLiftOffs = 0;
    for (const Real gamma : {0.8, 0.95, 1.05, 1.2, 1.5, 2.0, 3.0})
    {
        const Real amplitude = gamma * kG / (w * w);
        World world = worldWith(ball, {0, 0, -kG});
        dem::Wall plate = floorWall();
        plate.motion.oscillationAmplitude = {0, 0, amplitude};
        plate.motion.oscillationAngularFrequency = w;
        plate.motion.velocity = {0, 0, amplitude * w}; // at t = 0 (the step resets it every step)
        world.walls.push_back(plate);
        world.particles.add({0, 0, radius - m * kG / ball.normalStiffness}, {0, 0, amplitude * w}, {}, radius,
                            ball.density, 0);
        Real liftOff = -1;
        runFor(world, 2 * 2 * kPi / w, dt, context, "asmar_vibrating_plate",
               [&](const World& wd)
               {
                   const Real gap = wd.particles.position[0].z - radius - wd.walls[0].displacement.z;
                   if (liftOff < 0 && gap > 0)
                       liftOff = wd.time;
               });
        if (gamma < 1)
        {
            spuriousLiftOffs += liftOff >= 0 ? 1 : 0;
            continue;
        }
        const Real phi = liftOff >= 0 ? w * liftOff : 1e9, theory = std::asin(1 / gamma);
        worstPhase = std::fmax(worstPhase, std::fabs(phi - theory));
        s.rows.push_back({gamma, phi * 180 / kPi, theory * 180 / kPi});
    }
    r.quantities.push_back(absoluteQuantity("lift-offs with Gamma = 0.8, 0.95 (2 periods)", "", 0,
                                            spuriousLiftOffs, 0.5,
                                            "below Gamma = 1 the plate never pulls away (exact)"));
    r.quantities.push_back(absoluteQuantity("worst |phi - asin(1/Gamma)|, Gamma = 1.05..3", "rad", 0,
                                            worstPhase, 5e-3,
                                            "contact lag 2 zeta/omega_n = 1.4e-3 rad at 20 Hz"));
    r.series.push_back(std::move(s));
    return r;
}
} // namespace

VERIDEM_CASE({.name = "asmar_vibrating_plate",
              .summary = "ball on a vibrating plate: lift-off iff Gamma > 1, at sin(phi) = 1/Gamma",
              .reference = "Asmar et al. 2002 (reconstructed, BENCHMARKS 3 #7)",
              .labels = {"dem", "quick", "asmar"},
              .run = run});
VERIDEM_SWEEP("asmar_vibrating_plate",
              {.orders = {
                   {"worst |phi", 1.0, "a lift-off time found between steps is at least first order"}}});
} // namespace veridem::verify
