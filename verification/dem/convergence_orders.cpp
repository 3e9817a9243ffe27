// Observed orders of convergence in dt (issue 21): collision, friction and rolling cases re-run at
// dt, dt/2 and dt/4; the error e(dt) against the closed form gives the observed order
// p = log2(e(dt)/e(dt/2)) (and again from dt/2 to dt/4), checked against the scheme's order.
//
// The scheme: velocity Verlet, second order for smooth forces; the contact law evaluates the
// normal dashpot with the end-of-step normal speed and weights it at first touch and separation
// (docs/models.md), the tangential spring adds the half-step slip v_t dt, and the rolling torques
// use the half-step angular velocity. Expected orders, from where each error comes from:
//   collision, linear restitution: 2 (docs/models.md: second-order damping);
//   collision, Hertz restitution: 5/4. The Hertz dashpot coefficient grows as delta^(1/4), with
//     an infinite slope at delta = 0: in the first step of a contact the damping force is of order
//     (v dt)^(1/4) and is credited for a fraction of the step that depends on where first touch
//     falls, an impulse error ~dt^(5/4) (the contact ends where the clipped force reaches zero,
//     continuously). The error scatters with that phase, so the study takes the
//     largest error over eight start phases and fits the order over five doublings;
//   friction, no-slip tangential spring (linear, and Hertz-Mindlin against its integrated
//     no-slip reference): 1. The spring adds the slip of the whole step in which the contact
//     begins (and ends), although the contact covers only part of it: an O(v_t dt) error in xi;
//   rolling, viscous (type B) spin-down: 1. The torque -c_r Fn R^2 w uses the half-step w, so the
//     decay rate is integrated with an O(dt) lag; the speed also carries a dt-independent offset
//     of the elastic contact (lever arm a - delta), so the order is taken from successive
//     differences q(dt) - q(dt/2), q(dt/2) - q(dt/4) (dt = tau/50000 .. tau/200000).
// Each impact starts a fixed number of steps of travel before first touch, so that first touch
// falls at the same fraction of a step at every dt.
// Margin: |p - p_expected| <= 0.3, i.e. the error ratio between levels within a factor 2^0.3 =
// 1.23 of 2^p: the levels are in the asymptotic range (errors >= 1e-6, far above round-off), where
// the next term of the error expansion changes the ratio by O(dt/tc) <= 1/25.
#include "chung_ooi.h"
#include "dem/models/normal.h"
#include "support.h"

#include <cstdio>

namespace veridem::verify
{
namespace
{
using namespace chung_ooi;

// Linear spring-dashpot ball on a plane, the paper's flat ball: returns the restitution or, with
// friction, the contact-point tangential velocity ratio.
struct LinearImpact
{
    Real restitution, tangentialRatio;
};

LinearImpact linearImpact(Real stepsPerContact, Real e, Real ktRatio, Real vt, const CaseContext& context)
{
    Material m = flatTurntableBall();
    m.restitution = e;
    m.friction = vt > 0 ? 10.0 : 0.0;
    m.rollingModel = dem::RollingModel::None;
    m.tangentialStiffnessRatio = ktRatio;
    const Real a = kFlatBallRadius, vn = 1.0;
    World world = worldWith(m, {0, 0, 0});
    world.walls.push_back(floorWall());
    const Real mass = sphereMass(m.density, a);
    const Real zeta = dem::dampingRatioFromRestitution(e);
    const Real tc = kPi / (std::sqrt(m.normalStiffness / mass) * std::sqrt(1 - zeta * zeta));
    const Real dt = tc / stepsPerContact;
    world.particles.add({0, 0, a + 2.5 * vn * dt}, {vt, 0, -vn}, {}, a, m.density, 0);
    runFor(world, 2.5 * dt + 1.5 * tc, dt, context, "convergence_orders", nullptr);
    const auto& p = world.particles;
    return {p.velocity[0].z / vn, vt > 0 ? (p.velocity[0].x - a * p.angularVelocity[0].y) / vt : 0.0};
}

struct Study
{
    std::string name;
    Real expectedOrder;
    std::vector<Real> steps;         // steps per contact (per reference time) of the levels, doubling
    std::function<Real(Real)> error; // error at `steps`; with `differences`, the measured value
    bool differences = false;        // order from successive differences (a dt-independent model offset)
};

// Type B (viscous) rolling on a plane: the ball's speed after tau = 7/(5 c_r g) = 2 s, dt = tau/n.
Real viscousRollSpeed(Real n, const CaseContext& context)
{
    Material m = flatTurntableBall();
    m.rollingModel = dem::RollingModel::Viscous;
    m.rollingFrictionLength = 0;
    const Real tau = 2.0, v0 = 0.1, a = kFlatBallRadius;
    m.rollingViscousCoefficient = 7.0 / (5.0 * kG * tau);
    World world = worldWith(m, {0, 0, -kG});
    world.walls.push_back(floorWall());
    const Real mass = sphereMass(m.density, a);
    world.particles.add({0, 0, a - mass * kG / m.normalStiffness}, {v0, 0, 0}, {0, v0 / a, 0}, a, m.density,
                        0);
    runFor(world, tau, tau / n, context, "convergence_orders", nullptr);
    return world.particles.velocity[0].x;
}

// Largest error over eight start phases (first touch at 0, 1/8, ..., 7/8 of a step): for the Hertz
// damping the error depends on where the contact begins between steps (see above), and its envelope
// is what converges.
Real envelope(const std::function<Real(Real)>& errorAtStart)
{
    Real worst = 0;
    for (int k = 0; k < 8; ++k)
        worst = std::fmax(worst, errorAtStart(2.0 + k / 8.0));
    return worst;
}

} // namespace

CaseResult convergenceRun(const CaseContext& context)
{
    const Real noSlipSteel =
        noSlipReversal(effectiveShearModulus(kSteel, true) / effectiveModulus(kSteel, true));
    std::vector<Study> studies{
        {"collision: linear e = 0.8",
         2.0,
         {25, 50, 100},
         [&](Real n) { return std::fabs(linearImpact(n, 0.8, 2.0 / 7.0, 0, context).restitution - 0.8); }},
        {"collision: Hertz e = 0.5 (Al2O3, t3), envelope of 8 phases",
         1.25,
         {50, 100, 200, 400, 800, 1600},
         [&](Real n)
         {
             return envelope(
                 [&](Real start)
                 {
                     return std::fabs(wallImpact(kAluminiumOxide, 0.5, 0, 2.5e-3, {0, 0, -3.9}, {}, n,
                                                 context, false, start)
                                              .velocity.z /
                                          3.9 -
                                      0.5);
                 });
         }},
        {"friction: linear no-slip reversal kt/kn = 0.5",
         1.0,
         {50, 100, 200},
         [&](Real n)
         {
             return std::fabs(linearImpact(n, 1.0, 0.5, 0.1, context).tangentialRatio -
                              std::cos(kPi * std::sqrt(3.5 * 0.5)));
         }},
        {"friction: Hertz-Mindlin no-slip psi_2/psi_1 (steel, t5 psi_1 = 0.05), envelope",
         1.0,
         {100, 200, 400},
         [&](Real n)
         {
             return envelope(
                 [&](Real start)
                 {
                     const Outcome o = wallImpact(kSteel, 1.0, 0.3, 10e-6, {0.05 * 0.3 * 5, 0, -5}, {}, n,
                                                  context, false, start);
                     const Real psi2 = (o.velocity.x - 10e-6 * o.angularVelocity.y) / (0.3 * o.velocity.z);
                     return std::fabs(psi2 / 0.05 - noSlipSteel);
                 });
         }},
        {"rolling: type B spin-down, v(tau) (successive differences)",
         1.0,
         {50000, 100000, 200000},
         [&](Real n) { return viscousRollSpeed(n, context); },
         true},
    };
    CaseResult r;
    Series s{"orders", {"study", "dt_over_tc", "error", "error_expected_slope"}, {}};
    int index = 0;
    for (const Study& study : studies)
    {
        std::vector<Real> logDt, logError, errors, values;
        for (const Real n : study.steps)
            values.push_back(study.error(n));
        // With `differences` the error of level i is estimated as |q_i - q_(i+1)| (the finest level
        // only serves as the reference of the one before).
        const std::size_t levels = study.differences ? values.size() - 1 : values.size();
        for (std::size_t i = 0; i < levels; ++i)
        {
            errors.push_back(study.differences ? std::fabs(values[i] - values[i + 1]) : values[i]);
            logDt.push_back(std::log2(1 / study.steps[i]));
            logError.push_back(std::log2(errors.back()));
        }
        std::string orders;
        for (std::size_t i = 1; i < errors.size(); ++i)
        {
            char o[32];
            std::snprintf(o, sizeof o, "%s%.2f", i > 1 ? ", " : "", std::log2(errors[i - 1] / errors[i]));
            orders += o;
        }
        const Real fitted = fitSlope(logDt, logError);
        char n[240];
        std::snprintf(n, sizeof n, "%s: order (fit over %zu levels; successive %s)", study.name.c_str(),
                      errors.size(), orders.c_str());
        r.quantities.push_back(absoluteQuantity(n, "", study.expectedOrder, fitted, 0.3,
                                                "the scheme's order (file header); margin 0.3"));
        for (std::size_t i = 0; i < errors.size(); ++i)
            s.rows.push_back({static_cast<double>(index), 1 / study.steps[i], errors[i],
                              errors[0] * std::pow(study.steps[0] / study.steps[i], study.expectedOrder)});
        r.notes.push_back("study " + std::to_string(index) + ": " + study.name);
        ++index;
    }
    r.series.push_back(std::move(s));
    return r;
}
namespace
{
VERIDEM_CASE({.name = "convergence_orders",
              .summary = "observed dt orders of collision, friction and rolling errors vs the scheme's",
              .reference = "issue 21; docs/models.md",
              .labels = {"dem", "quick", "convergence"},
              .run = convergenceRun});
} // namespace
} // namespace veridem::verify
