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
//     Fn = (4/3) E* sqrt(R*) delta^{3/2} + etaN(delta) * deltaDot,
//     etaN = 2 sqrt(5/6) beta sqrt(Sn m*), Sn = 2 E* sqrt(R* delta), beta = -ln e / sqrt(ln^2 e + pi^2)
// (Tsuji et al. 1992 form as written by LIGGGHTS/Lethe; it gives e only approximately).
//
// Clipping: veridem does NOT clip the attractive dashpot force at the end of a contact. With
// clipping, the force reaches zero before the overlap does and the measured e rises (e = 0.8
// becomes 0.808, e = 0.5 becomes 0.550; BENCHMARKS 2.1). Friction and rolling caps use max(Fn, 0).
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

/// Linear spring-dashpot normal force [N] (positive = repulsive).
/// kn [N/m], etaN [N s/m], overlap delta [m], overlapRate deltaDot [m/s] (> 0 approaching).
template <class T> VERIDEM_HOT_INLINE T linearNormalForce(T kn, T etaN, T overlap, T overlapRate)
{
    return kn * overlap + etaN * overlapRate;
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

} // namespace veridem::dem
