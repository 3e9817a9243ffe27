// Tangential force: linear spring with history and a Coulomb cap (Cundall & Strack 1979;
// algorithm of BENCHMARKS 1a "robust algorithm" and 2.2).
//
//   1. The stored spring xi is projected onto the current tangent plane and rescaled to keep its
//      magnitude (the contact frame rotates, the stored elastic energy does not change).
//   2. xi += vt * dt, with vt the tangential relative velocity at the contact point, evaluated at
//      the half step (the displacement over [t, t+dt]).
//   3. Trial force F* = -kt xi - etaT vt.
//   4. If |F*| <= mu Fn the contact sticks: Ft = F*. Otherwise it slides: Ft = mu Fn F*/|F*| and
//      the spring is reset to the cap, xi = -(Ft + etaT vt)/kt, so the dashpot sits inside the cap.
#pragma once

#include "core/hot.h"
#include "core/vec3.h"

#include <cmath>

namespace veridem::dem
{

struct TangentialResult
{
    Vec3 force;  // on the particle [N]
    Vec3 spring; // updated spring displacement xi [m]
    bool sliding = false;
};

/// Rotates the stored spring into the plane normal to `normal`, keeping its length.
VERIDEM_HOT_INLINE Vec3 projectSpringToTangentPlane(const Vec3& spring, const Vec3& normal)
{
    const Real oldLength2 = lengthSquared(spring);
    if (oldLength2 == 0)
        return spring;
    Vec3 projected = spring - dot(spring, normal) * normal;
    const Real newLength2 = lengthSquared(projected);
    if (newLength2 == 0)
        return Vec3{};
    // Already in the plane (on a flat wall the normal is exact and so is the projection): the
    // scale below would be exactly 1. Skipping its division and square root gives the same bits
    // and takes ~35 cycles off a single ball's step-to-step dependency chain (docs/performance.md).
    if (newLength2 == oldLength2)
        return projected;
    return projected * std::sqrt(oldLength2 / newLength2);
}

/// kt [N/m], etaT [N s/m], mu [-], normalForce Fn [N] (clipped to >= 0 here),
/// tangentialVelocity vt [m/s] (in the tangent plane), dt [s].
VERIDEM_HOT_INLINE TangentialResult coulombSpringForce(Real kt, Real etaT, Real mu, Real normalForce,
                                                       Vec3 spring, const Vec3& normal,
                                                       const Vec3& tangentialVelocity, Real dt)
{
    spring = projectSpringToTangentPlane(spring, normal) + tangentialVelocity * dt;
    const Vec3 trial = -kt * spring - etaT * tangentialVelocity;
    const Real cap =
        mu * (normalForce > 0 ? normalForce : 0.0); // mu max(Fn, 0), NaN -> 0 like fmax (inlined)
    const Real trialLength2 = lengthSquared(trial);
    if (trialLength2 <= cap * cap)
        return {trial, spring, false};
    const Vec3 force = trial * (cap / std::sqrt(trialLength2));
    const Vec3 cappedSpring = kt > 0 ? -(force + etaT * tangentialVelocity) / kt : Vec3{};
    return {force, cappedSpring, true};
}

} // namespace veridem::dem
