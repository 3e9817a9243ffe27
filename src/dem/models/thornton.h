// Thornton's elastic-perfectly-plastic normal contact (C. Thornton, Coefficient of restitution for
// collinear collisions of elastic-perfectly plastic spheres, J. Appl. Mech. 64 (1997) 383-386).
// Pure functions of the overlap delta [m] and the contact's history, its largest overlap so far
// delta_max [m]; E* [Pa], R* [m], the limiting contact pressure p_y [Pa]. No viscous damping: the
// energy is lost to plastic flow alone.
//
//   Hertz until the largest pressure 2 E* a / (pi R*) reaches p_y (a = sqrt(R* delta)):
//     a_y = pi p_y R* / (2 E*),  delta_y = a_y^2 / R*,  F_y = (4/3) E* sqrt(R*) delta_y^{3/2}
//   loading beyond it, linear:          F = F_y + pi p_y R* (delta - delta_y)
//   unloading from delta_max > delta_y, Hertz with the enlarged radius R_p:
//     F = (4/3) E* sqrt(R_p) (delta - delta_p)^{3/2},
//     R_p = (4 E* / (3 F_max)) a_p^3,  a_p^2 = (2 F_max + F_y) / (2 pi p_y) = R* delta_max,
//     delta_max - delta_p = a_p^2 / R_p,  F_max the loading force at delta_max.
// (a_p^2 = R* delta_max follows from F_y = (2/3) pi p_y a_y^2; so the unloading stiffness at
// delta_max, 2 E* a_p, is the Hertz stiffness there, and the stable time step is Hertz's.)
//
// Restitution of an impact at speed v of a pair of effective mass m* (energy balance of the
// three branches above): with V = v / v_y, (1/2) m* v_y^2 = (2/5) F_y delta_y, x = delta_max /
// delta_y the root of V^2 = 1 + (5/2)(x - 1) + (15/8)(x - 1)^2, and F_max / F_y = 1 + (3/2)(x - 1),
//     e = (F_max / F_y) / (x^{1/4} V)   (V >= 1;  e = 1 below),
// which is Thornton's closed form written in x (thorntonRestitution; tests/dem/thornton_test.cpp
// checks the two forms against each other).
#pragma once

#include "core/constants.h"
#include "core/hot.h"
#include "dem/lanes.h"

#include <cmath>

namespace veridem::dem
{

/// The history scalars a Thornton contact carries (its normal model's declaration, dem/materials.h
/// kNormalModelList): the largest overlap so far, delta_max [m] (ContactHistory::scalars[0]).
inline constexpr unsigned kThorntonHistoryScalars = 1;

/// The yield point of a Thornton contact: the overlap delta_y [m] and force F_y [N] at which the
/// largest Hertz pressure reaches p_y.
struct ThorntonYield
{
    Real overlap; // delta_y [m]
    Real force;   // F_y [N]
};
inline ThorntonYield thorntonYield(Real effectiveModulus, Real effectiveRadius, Real yieldPressure)
{
    const Real a = kPi * yieldPressure * effectiveRadius / (2.0 * effectiveModulus);
    const Real overlap = a * a / effectiveRadius;
    return {overlap, (4.0 / 3.0) * effectiveModulus * std::sqrt(effectiveRadius * overlap) * overlap};
}

/// The loading (virgin) force [N] at overlap delta >= 0 [m]: Hertz to delta_y, linear beyond.
inline Real thorntonLoadingForce(Real effectiveModulus, Real effectiveRadius, Real yieldPressure,
                                 Real overlap)
{
    const ThorntonYield y = thorntonYield(effectiveModulus, effectiveRadius, yieldPressure);
    if (overlap <= y.overlap)
        return (4.0 / 3.0) * effectiveModulus * std::sqrt(effectiveRadius * overlap) * overlap;
    return y.force + kPi * yieldPressure * effectiveRadius * (overlap - y.overlap);
}

/// The unloading branch from the largest overlap delta_max > delta_y [m]: its radius R_p [m] and
/// the overlap delta_p [m] at which the force returns to zero (the permanent indentation).
struct ThorntonUnloading
{
    Real radius;         // R_p [m]
    Real plasticOverlap; // delta_p [m]
};
inline ThorntonUnloading thorntonUnloading(Real effectiveModulus, Real effectiveRadius, Real yieldPressure,
                                           Real maxOverlap)
{
    const Real maxForce = thorntonLoadingForce(effectiveModulus, effectiveRadius, yieldPressure, maxOverlap);
    const Real contactSquared = effectiveRadius * maxOverlap; // a_p^2
    const Real radius =
        4.0 * effectiveModulus * contactSquared * std::sqrt(contactSquared) / (3.0 * maxForce);
    return {radius, maxOverlap - contactSquared / radius};
}

/// The elastic normal force [N] (>= 0) at overlap delta [m] of a contact whose largest overlap so
/// far, this step's included, is maxOverlap >= delta [m].
inline Real thorntonForce(Real effectiveModulus, Real effectiveRadius, Real yieldPressure, Real overlap,
                          Real maxOverlap)
{
    if (overlap <= 0)
        return 0;
    const ThorntonYield y = thorntonYield(effectiveModulus, effectiveRadius, yieldPressure);
    if (overlap >= maxOverlap || maxOverlap <= y.overlap) // loading, or an elastic history
        return thorntonLoadingForce(effectiveModulus, effectiveRadius, yieldPressure, overlap);
    const ThorntonUnloading u =
        thorntonUnloading(effectiveModulus, effectiveRadius, yieldPressure, maxOverlap);
    const Real relief = overlap - u.plasticOverlap;
    return relief > 0 ? (4.0 / 3.0) * effectiveModulus * std::sqrt(u.radius * relief) * relief : 0;
}

/// The elastic energy stored at overlap delta [m] with largest overlap maxOverlap [m] [J]: the work
/// the unloading branch through delta gives back, (2/5) F (delta - delta_p) (Hertz: (2/5) F delta).
inline Real thorntonStoredEnergy(Real effectiveModulus, Real effectiveRadius, Real yieldPressure,
                                 Real overlap, Real maxOverlap)
{
    const Real force = thorntonForce(effectiveModulus, effectiveRadius, yieldPressure, overlap, maxOverlap);
    const Real peak = overlap > maxOverlap ? overlap : maxOverlap;
    const ThorntonYield y = thorntonYield(effectiveModulus, effectiveRadius, yieldPressure);
    if (peak <= y.overlap)
        return 0.4 * force * overlap;
    return 0.4 * force *
           (overlap -
            thorntonUnloading(effectiveModulus, effectiveRadius, yieldPressure, peak).plasticOverlap);
}

/// The largest normal stiffness dF/d(delta) [N/m] of a contact at overlap <= delta [m] on any branch:
/// the Hertz stiffness 2 E* sqrt(R* delta) (the unloading branch's at delta_max; the plastic
/// branch's pi p_y R* is smaller), for the stable time step.
inline Real thorntonStiffness(Real effectiveModulus, Real effectiveRadius, Real overlap)
{
    return 2.0 * effectiveModulus * std::sqrt(effectiveRadius * overlap);
}

/// The largest yield stress p_y [Pa] a material of Young's modulus E [Pa] and Poisson's ratio nu [-]
/// may have: for a like pair (E* = E / (2 (1 - nu^2))) the yield contact radius a_y = pi p_y R* /
/// (2 E*) reaches R* at p_y = 2 E* / pi = E / (pi (1 - nu^2)), beyond any small-strain contact.
inline Real thorntonYieldStressLimit(Real youngsModulus, Real poissonRatio)
{
    return youngsModulus / (kPi * (1 - poissonRatio * poissonRatio));
}

/// The largest overlap delta_max [m] of an impact at speed v [m/s] of a pair of effective mass m*
/// [kg] (the energy balance above: x = delta_max / delta_y from V = v / v_y; Hertz's
/// (15 m* v^2 / (16 E* sqrt(R*)))^{2/5} below v_y).
inline Real thorntonPeakOverlap(Real effectiveModulus, Real effectiveRadius, Real yieldPressure,
                                Real effectiveMass, Real speed);

/// The impact speed v_y [m/s] at which a pair of effective mass m* [kg] just reaches yield:
/// (1/2) m* v_y^2 = (2/5) F_y delta_y.
inline Real thorntonYieldSpeed(Real effectiveModulus, Real effectiveRadius, Real yieldPressure,
                               Real effectiveMass)
{
    const ThorntonYield y = thorntonYield(effectiveModulus, effectiveRadius, yieldPressure);
    return std::sqrt(0.8 * y.force * y.overlap / effectiveMass);
}

inline Real thorntonPeakOverlap(Real effectiveModulus, Real effectiveRadius, Real yieldPressure,
                                Real effectiveMass, Real speed)
{
    const ThorntonYield y = thorntonYield(effectiveModulus, effectiveRadius, yieldPressure);
    const Real ratio =
        speed / thorntonYieldSpeed(effectiveModulus, effectiveRadius, yieldPressure, effectiveMass);
    if (ratio <= 1) // Hertz: delta_max / delta_y = V^{4/5}
        return y.overlap * std::pow(ratio, 0.8);
    // (15/8) u^2 + (5/2) u - (V^2 - 1) = 0, u = x - 1 >= 0
    const Real u = (-2.5 + std::sqrt(6.25 + 7.5 * (ratio * ratio - 1))) / 3.75;
    return y.overlap * (1 + u);
}

/// Thornton's coefficient of restitution [-] at impact speed ratio V = v / v_y (his closed form):
/// e = 1 for V <= 1, else
///   e = (6 sqrt(3) / 5)^{1/2} [1 - (1/6) V^-2]^{1/2} [V^-1 / (V^-1 + 2 sqrt(6/5 - (1/5) V^-2))]^{1/4}.
inline Real thorntonRestitution(Real speedRatio)
{
    if (speedRatio <= 1)
        return 1;
    const Real r = 1 / speedRatio, r2 = r * r;
    return std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::sqrt(1 - r2 / 6.0) *
           std::pow(r / (r + 2.0 * std::sqrt(6.0 / 5.0 - r2 / 5.0)), 0.25);
}

} // namespace veridem::dem
