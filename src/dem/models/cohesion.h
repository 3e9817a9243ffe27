// Adhesive elastic contact of spheres: JKR and DMT (pure functions, templates over the number type
// T: double or a vector of lanes, dem/lanes.h).
//
// w: work of adhesion [J/m^2] (2 gamma for two like surfaces of surface energy gamma; materials.h
// mixes unlike ones), E* [Pa], R* [m], delta: overlap [m] (negative while the surfaces are apart),
// a: contact radius [m]. Forces are positive when repulsive.
//
// JKR (Johnson, Kendall & Roberts 1971; Johnson, Contact Mechanics 1985, sec. 5.5), parametric in a:
//     delta(a) = a^2 / R* - sqrt(2 pi w a / E*),     F(a) = 4 E* a^3 / (3 R*) - sqrt(8 pi w E* a^3).
// Under displacement control (an explicit DEM step prescribes the overlap) the contact forms when
// the surfaces touch (delta = 0: a jumps to (2 pi w R*^2 / E*)^(1/3), F to -(4/3) pi w R*), passes
// the force minimum -(3/2) pi w R* (the pull-off force under load control, at delta = -a^2/(3 R*)),
// and breaks where d delta / da = 0:
//     a_c = (pi w R*^2 / (8 E*))^(1/3),   delta_c = -3 a_c^2 / R* = -(3/4) (pi^2 w^2 R* / E*^2)^(1/3),
// with F(a_c) = -(5/6) pi w R*. So a JKR contact has hysteresis: it forms at delta >= 0 and holds
// while delta > delta_c (its touch criterion: contact_law.h).
// a(delta) is the larger root of x^4 - R* sqrt(2 pi w / E*) x - R* delta = 0, x = sqrt(a) (the
// stable branch). Newton's method from an upper bound descends onto it monotonically (the quartic
// is convex and increasing above its larger root).
// The energy of a formed contact, U(delta) = integral of F from delta = 0 (the contact formed at
// touch) to delta, is closed-form in a (jkrPathEnergy, jkrStoredEnergy); a contact that breaks at
// delta_c loses U(delta_c) (jkrBreakingEnergy), the hysteresis (docs/measurements.md).
//
// DMT (Derjaguin, Muller & Toporov 1975, in the form Maugis 2000 gives its limit): Hertz's
// deformation with a constant adhesive force, F = (4/3) E* sqrt(R*) delta^(3/2) - 2 pi w R* while
// delta > 0; it touches and separates at delta = 0, pull-off force 2 pi w R*.
//
// With adhesion, the friction and rolling caps take the load F + 2 F_pulloff instead of F
// (Thornton & Yin 1991): a contact can hold a tangential force while it pulls.
#pragma once

#include "core/constants.h"
#include "core/hot.h"
#include "dem/lanes.h"
#include "dem/models/normal.h"

#include <cmath>

namespace veridem::dem
{

/// The largest Newton steps of the JKR contact radius; the iteration ends earlier once no lane's
/// value changes (the update depends on a lane's own value only, so every width gives the same
/// bits). A root far from the breaking point converges quadratically in a few steps; at the
/// breaking point the root is double and the error halves a step, ~52 steps to full precision.
inline constexpr int kJkrNewtonSteps = 64;

/// JKR breaking overlap delta_c = -(3/4) (pi^2 w^2 R* / E*^2)^(1/3) [m] (<= 0).
template <class T> VERIDEM_HOT_INLINE T jkrBreakingOverlap(T modulus, T effectiveRadius, T adhesion)
{
    const T ratio = adhesion / modulus;
    return -0.75 * lanes::laneCbrt((kPi * kPi) * ratio * ratio * effectiveRadius);
}

/// JKR contact radius a [m] at overlap delta >= delta_c [m] (the stable branch). For delta below
/// delta_c (no contact) it returns the radius at delta_c.
template <class T> VERIDEM_HOT_INLINE T jkrContactRadius(T modulus, T effectiveRadius, T adhesion, T overlap)
{
    using namespace lanes;
    const T zero{};
    const T breaking = jkrBreakingOverlap<T>(modulus, effectiveRadius, adhesion);
    const T delta = overlap > breaking ? overlap : breaking;
    // f(x) = x^4 + p x + q, x = sqrt(a).
    const T p = -effectiveRadius * laneSqrt((2.0 * kPi) * adhesion / modulus);
    const T q = -effectiveRadius * delta;
    // An upper bound of the root: x0^4 >= |p| x0 + |q| when x0^3 >= 2|p| and x0^4 >= 2|q|.
    const T fromP = laneCbrt(-2.0 * p), fromQ = laneSqrt(laneSqrt(2.0 * laneAbs(q)));
    T x = fromP > fromQ ? fromP : fromQ;
    for (int step = 0; step < kJkrNewtonSteps; ++step)
    {
        const T x2 = x * x;
        const T slope = 4.0 * x2 * x + p;
        const T next = slope > zero ? x - (x2 * x2 + p * x + q) / slope : x;
        const auto changed = next != x;
        x = next;
        if (!anyLane(changed))
            break;
    }
    return x * x;
}

/// JKR force F(a) = 4 E* a^3 / (3 R*) - sqrt(8 pi w E* a^3) [N] at contact radius a [m].
template <class T> VERIDEM_HOT_INLINE T jkrForce(T modulus, T effectiveRadius, T adhesion, T contactRadius)
{
    const T a3 = contactRadius * contactRadius * contactRadius;
    return (4.0 / 3.0) * modulus * a3 / effectiveRadius -
           lanes::laneSqrt((8.0 * kPi) * adhesion * modulus * a3);
}

/// JKR overlap delta(a) = a^2 / R* - sqrt(2 pi w a / E*) [m] at contact radius a [m].
inline Real jkrOverlap(Real modulus, Real effectiveRadius, Real adhesion, Real contactRadius)
{
    return contactRadius * contactRadius / effectiveRadius -
           std::sqrt(2.0 * kPi * adhesion * contactRadius / modulus);
}

/// JKR path energy G(a) = E* [8 a^5 / (15 R*^2) - (4 c / (3 R*)) a^(7/2) + c^2 a^2 / 2] [J],
/// c = sqrt(2 pi w / E*), at contact radius a [m]: the integral of F(a) d delta/da from a = 0
/// (delta = 0, F = 0), so dG/d delta = F along delta(a). It is the JKR total energy (elastic
/// minus surface energy pi a^2 w); G(a0) = -(3/10) E* c^2 a0^2 at the touching radius
/// a0 = (2 pi w R*^2 / E*)^(1/3), G(a_c) = (1/5) E* c^2 a_c^2 at the breaking radius.
inline Real jkrPathEnergy(Real modulus, Real effectiveRadius, Real adhesion, Real contactRadius)
{
    const Real a = contactRadius, c = std::sqrt(2.0 * kPi * adhesion / modulus);
    const Real a2 = a * a, root = std::sqrt(a); // a^(7/2) = a^3 sqrt(a)
    return modulus * ((8.0 / 15.0) * a2 * a2 * a / (effectiveRadius * effectiveRadius) -
                      (4.0 / 3.0) * c * a2 * a * root / effectiveRadius + 0.5 * c * c * a2);
}

/// The energy stored in a formed JKR contact at overlap delta >= delta_c [m] [J]: the integral of
/// the law's force from delta = 0 (where the contact forms, a = a0) to delta,
/// U(delta) = G(a(delta)) - G(a0), so U = 0 for a contact formed at touch; negative while the
/// force attracts near delta = 0, and U(delta_c) > 0 (jkrBreakingEnergy) at the breaking point.
/// Below delta_c it returns U(delta_c). With w = 0 it is Hertz's (8/15) E* sqrt(R*) delta^(5/2).
inline Real jkrStoredEnergy(Real modulus, Real effectiveRadius, Real adhesion, Real overlap)
{
    const Real a = jkrContactRadius<Real>(modulus, effectiveRadius, adhesion, overlap);
    const Real touching = std::cbrt(2.0 * kPi * adhesion * effectiveRadius * effectiveRadius / modulus);
    return jkrPathEnergy(modulus, effectiveRadius, adhesion, a) -
           jkrPathEnergy(modulus, effectiveRadius, adhesion, touching);
}

/// The energy a formed JKR contact loses when it breaks at delta_c [J]: U(delta_c) =
/// G(a_c) - G(a0) = 2 pi w (a0^2 (3/10) + a_c^2 / 5), a_c = a0 / 16^(1/3) (the hysteresis of a
/// contact formed at touch and pulled apart under displacement control).
inline Real jkrBreakingEnergy(Real modulus, Real effectiveRadius, Real adhesion)
{
    const Real a0 = std::cbrt(2.0 * kPi * adhesion * effectiveRadius * effectiveRadius / modulus);
    const Real ac = a0 / std::cbrt(16.0);
    return 2.0 * kPi * adhesion * (0.3 * a0 * a0 + 0.2 * ac * ac);
}

/// DMT force (4/3) E* sqrt(R*) delta^(3/2) - 2 pi w R* [N] at overlap delta > 0 [m].
template <class T> VERIDEM_HOT_INLINE T dmtForce(T modulus, T effectiveRadius, T adhesion, T overlap)
{
    return hertzElasticForce<T>(modulus, effectiveRadius, overlap) - (2.0 * kPi) * adhesion * effectiveRadius;
}

/// Pull-off force magnitude [N]: (3/2) pi w R* (JKR, load control) and 2 pi w R* (DMT).
template <class T> VERIDEM_HOT_INLINE T jkrPullOffForce(T effectiveRadius, T adhesion)
{
    return (1.5 * kPi) * adhesion * effectiveRadius;
}
template <class T> VERIDEM_HOT_INLINE T dmtPullOffForce(T effectiveRadius, T adhesion)
{
    return (2.0 * kPi) * adhesion * effectiveRadius;
}

} // namespace veridem::dem
