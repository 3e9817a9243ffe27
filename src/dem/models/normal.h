// Normal contact force models (pure functions, templates over the number type T: double or a
// vector of lanes, dem/lanes.h).
//
// Linear spring-dashpot (Cundall & Strack 1979; damping from restitution as in Tsuji et al. 1992):
//     Fn = kn * delta + etaN * deltaDot,    deltaDot = -vn > 0 while approaching,
//     etaN = 2 zeta sqrt(m* kn),  zeta = -ln(e) / sqrt(pi^2 + ln^2 e)            (BENCHMARKS 2.1)
// which gives a coefficient of restitution exactly e (independent of impact speed) and a contact
// time tc = pi / (omegaN sqrt(1 - zeta^2)), omegaN = sqrt(kn/m*).
//
// Hertz (Hertz 1882; Johnson, Contact Mechanics, 1985):
//     Fn = max(0, (4/3) E* sqrt(R*) delta^{3/2} + etaN(delta) * deltaDot),
//     etaN = 2 sqrt(5/6) beta sqrt(Sn m*), Sn = 2 E* sqrt(R* delta)
// (the Tsuji et al. 1992 damping form as written by LIGGGHTS/Lethe). The total force is clipped at
// zero: a non-cohesive contact never pulls (LIGGGHTS `limitForce on`; the Hertz models Thornton,
// Cummins & Cleary 2013 compare have no attractive end). Near separation the dashpot,
// ~ delta^{1/4}, outweighs the elastic delta^{3/2}: unclipped, the force pulls during the last 19 %
// of a contact at e = 0.5, the Coulomb cap mu max(Fn, 0) sees a compressive impulse 3.4 % above the
// normal impulse, and a sliding impact misses the rigid-body tangential impulse mu (1 + e) m* v_n
// (chung_ooi_t6, t8). The clipped contact dissipates less, so beta is computed for the clipped law
// (hertzDampingFactorWithoutTension): the restitution is still e, independent of the impact speed.
//
// Linear model: no clipping. The attractive dashpot force at the end of a contact is kept, so that
// zeta(e) and tc above hold exactly (the paper's spring-dashpot; with clipping, e = 0.8 would
// become 0.808 and e = 0.5 would become 0.550; BENCHMARKS 2.1). Friction and rolling caps use
// max(Fn, 0). Adhesive models (JKR, DMT) pull by design and are not clipped either.
#pragma once

#include "core/constants.h"
#include "core/hot.h"
#include "core/vec3.h"
#include "dem/lanes.h"

#include <cmath>

namespace veridem::dem
{

/// Damping ratio zeta of a linear oscillator whose half-period restitution is e (0 < e <= 1).
inline Real dampingRatioFromRestitution(Real e)
{
    const Real logE = std::log(e);
    return -logE / std::sqrt(kPi * kPi + logE * logE);
}

/// Linear spring force [N]: kn delta. kn [N/m], overlap delta [m].
template <class T> VERIDEM_HOT_INLINE T linearElasticForce(T kn, T overlap)
{
    return kn * overlap;
}

/// Spring-dashpot normal force [N] (> 0 repulsive) at the end of the step, as the contact law
/// composes every model's: the elastic force [N] minus the dashpot eta [N s/m] times the normal
/// speed at t+dt, u = (m* u_half + dt/2 elastic) / (m* + dt/2 eta), the solution of the pair's own
/// final half kick (dem/contact_law.h). normalSpeed u_half [m/s] (< 0 approaching), effective mass
/// m* [kg], halfStep dt/2 [s].
template <class T>
VERIDEM_HOT_INLINE T springDashpotNormalForce(T elastic, T eta, T normalSpeed, T effectiveMass, Real halfStep)
{
    const T normalSpeedEnd =
        (effectiveMass * normalSpeed + halfStep * elastic) / (effectiveMass + halfStep * eta);
    return elastic - eta * normalSpeedEnd;
}

/// Hertz elastic normal force [N]: (4/3) E* sqrt(R*) delta^{3/2}. E* [Pa], R* [m], delta [m].
template <class T> VERIDEM_HOT_INLINE T hertzElasticForce(T effectiveModulus, T effectiveRadius, T overlap)
{
    return (4.0 / 3.0) * effectiveModulus * lanes::laneSqrt(effectiveRadius * overlap) * overlap;
}

/// Hertz normal contact stiffness dFn/d(delta) = 2 E* sqrt(R* delta) [N/m].
template <class T> VERIDEM_HOT_INLINE T hertzNormalStiffness(T effectiveModulus, T effectiveRadius, T overlap)
{
    return 2.0 * effectiveModulus * lanes::laneSqrt(effectiveRadius * overlap);
}

/// The factor 2 sqrt(5/6) beta of the Hertz damping coefficient (beta from e) [-].
inline Real hertzDampingFactor(Real beta)
{
    return 2.0 * std::sqrt(5.0 / 6.0) * beta;
}

/// Hertz damping coefficient etaN [N s/m] = 2 sqrt(5/6) beta sqrt(Sn m*), beta from e.
inline Real hertzDampingCoefficient(Real beta, Real normalStiffness, Real effectiveMass)
{
    return hertzDampingFactor(beta) * std::sqrt(normalStiffness * effectiveMass);
}

/// The restitution [-] of a Hertz impact with damping factor beta [-]
/// (etaN = 2 sqrt(5/6) beta sqrt(Sn m*)) when the normal force is clipped at zero (a non-cohesive
/// contact never pulls). In units m* = 1, (4/3) E* sqrt(R*) = 1 and impact speed 1 the overlap obeys
///     x'' = -max(0, x^{3/2} + sqrt(5) beta x^{1/4} x'),  x(0) = 0, x'(0) = 1,
/// whose rebound speed depends on beta alone: the restitution is the speed -x' at which the force
/// reaches zero (from then on the bodies fly apart freely). RK4 in s = t^{1/4} (dx/ds = 4 s^3 x',
/// dx'/ds = -4 s^3 F: smooth at first touch, where the damping ~ x^{1/4} has an infinite slope in
/// t), step 1e-3 in s; the step in which the force reaches zero is retaken with steps 100 times
/// shorter down to 1e-11, then the zero is interpolated linearly. Halving the step changes e by
/// less than 3e-10 over e = 0.1..0.98.
inline Real hertzRestitutionOfClippedDamping(Real beta)
{
    const Real c = std::sqrt(5.0) * beta;
    const auto force = [c](Real x, Real v)
    {
        const Real root = std::sqrt(std::fmax(x, 0.0));
        return std::fmax(x * root + c * std::sqrt(root) * v, 0.0);
    };
    Real x = 0, v = 1, s = 0, h = 1e-3;
    for (int step = 0; step < 10000000; ++step)
    {
        // d(x, v)/ds at (s, x, v): w (v, -F) with w = dt/ds = 4 s^3.
        const auto rate = [&force](Real sa, Real xa, Real va, Real& dx, Real& dv)
        {
            const Real w = 4 * sa * sa * sa;
            dx = w * va;
            dv = -w * force(xa, va);
        };
        Real dx1, dv1, dx2, dv2, dx3, dv3, dx4, dv4;
        rate(s, x, v, dx1, dv1);
        rate(s + 0.5 * h, x + 0.5 * h * dx1, v + 0.5 * h * dv1, dx2, dv2);
        rate(s + 0.5 * h, x + 0.5 * h * dx2, v + 0.5 * h * dv2, dx3, dv3);
        rate(s + h, x + h * dx3, v + h * dv3, dx4, dv4);
        const Real xNext = x + h / 6 * (dx1 + 2 * dx2 + 2 * dx3 + dx4);
        const Real vNext = v + h / 6 * (dv1 + 2 * dv2 + 2 * dv3 + dv4);
        const Real fNext = force(xNext, vNext);
        if (vNext < 0 && fNext <= 0)
        {
            if (h > 1e-9)
            {
                h *= 1e-2; // retake the step in which the force reaches zero, shorter
                continue;
            }
            const Real fNow = force(x, v);
            const Real share = fNow > 0 ? fNow / (fNow - fNext) : 0.0;
            return -(v + share * (vNext - v));
        }
        x = xNext;
        v = vNext;
        s += h;
    }
    return 0; // not reached: a damped contact releases within the loop
}

/// The Hertz damping factor beta [-] whose impact has restitution e in (0, 1] when the normal
/// force is clipped at zero: hertzRestitutionOfClippedDamping inverted by bisection (e falls
/// monotonically with beta). beta(0.5) = 0.2553 against 0.2155 for the unclipped law: the clipped
/// contact dissipates less, so it needs more damping.
inline Real hertzDampingFactorWithoutTension(Real e)
{
    if (!(e < 1))
        return 0;
    Real low = 0, high = 1;
    while (hertzRestitutionOfClippedDamping(high) > e)
        high *= 2;
    for (int k = 0; k < 60 && high - low > 1e-13 * high; ++k)
    {
        const Real mid = 0.5 * (low + high);
        (hertzRestitutionOfClippedDamping(mid) > e ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

} // namespace veridem::dem
