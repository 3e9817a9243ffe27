// Tangential force: linear spring with history and a Coulomb cap (Cundall & Strack 1979;
// algorithm of BENCHMARKS 1a "robust algorithm" and 2.2). Templates over the number type T
// (double or a vector of lanes, dem/lanes.h): branches are selects, the same operations either way.
//
//   1. The stored spring xi is projected onto the current tangent plane and rescaled to keep its
//      magnitude (the contact frame rotates, the stored elastic energy does not change).
//   2. xi += vt * dt, with vt the tangential relative velocity at the contact point, evaluated at
//      the half step (the displacement over [t, t+dt]).
//   3. Trial force F* = -kt xi - etaT vt.
//   4. If |F*| <= mu Fn the contact sticks: Ft = F*. Otherwise it slides: Ft = mu Fn F*/|F*| and
//      the spring is reset so that it carries the part of Ft the dashpot does not,
//      -kt xi = Ft + etaT vt (the dashpot inside the cap: Luding 2008, "Cohesive, frictional
//      powders"; LAMMPS `gran/hooke/history`), but never a part opposing Ft: where the dashpot
//      alone exceeds the cap (etaT vt . Ft < -|Ft|^2, the first steps of a damped Hertz impact,
//      where the dashpot dominates Fn) the spring is set to zero. A spring stretched against the
//      friction force stores no physical elastic state, and as kt(delta) then grows it turns the
//      force round below the cap: without the clamp, 2-6 % of the normal impulse of a sliding
//      impact at e = 0.5 falls on such steps (chung_ooi_t6, t8).
//
// With Hertz-Mindlin, kt = 8 G* sqrt(R* delta) changes with the overlap while xi is stored: the
// force follows kt(delta) xi: a displacement history (LAMMPS's `mindlin`), so a shrinking overlap
// scales the stored force down with kt, the rescaling Thornton, Cummins & Cleary (2013) ask for
// (docs/models.md).
#pragma once

#include "core/hot.h"
#include "core/vec3.h"
#include "dem/lanes.h"

#include <type_traits>

namespace veridem::dem
{

template <class T> struct TangentialResultOf
{
    lanes::Vec3Of<T> force;  // on the particle [N]
    lanes::Vec3Of<T> spring; // updated spring displacement xi [m]
    lanes::MaskOf<T> sliding{};
};
using TangentialResult = TangentialResultOf<Real>;

/// Rotates the stored spring h [m] into the plane normal to the unit `normal`, keeping its length.
template <class T>
VERIDEM_HOT_INLINE lanes::Vec3Of<T> projectSpring(const lanes::Vec3Of<T>& spring,
                                                  const lanes::Vec3Of<T>& normal)
{
    using namespace lanes;
    using V = Vec3Of<T>;
    const T oldLength2 = lengthSquared(spring);
    const MaskOf<T> keep = oldLength2 == 0;
    constexpr bool kScalar = std::is_same_v<T, Real>;
    if constexpr (kScalar)
        if (keep)
            return spring;
    const V projected = spring - dot(spring, normal) * normal;
    const T newLength2 = lengthSquared(projected);
    // Already in the plane (on a flat wall the normal is exact and so is the projection): the
    // scale below would be exactly 1. Skipping its division and square root gives the same bits
    // and shortens a single ball's step-to-step dependency chain (docs/performance.md). (Lanes
    // compute the rescale: a test of every lane costs more than it saves there.)
    if constexpr (kScalar)
        if (newLength2 == oldLength2)
            return projected;
    const V rescaled = projected * laneSqrt(oldLength2 / newLength2);
    return select(keep, spring, select(newLength2 == 0, V{}, rescaled));
}

/// The Coulomb spring: kt [N/m], etaT [N s/m], mu [-], normalForce Fn [N] (clipped to >= 0 here),
/// spring xi [m] (already in the tangent plane if kProjected), tangentialVelocity vt [m/s] (in the
/// tangent plane), dt [s].
template <class T, bool kProjected = false>
VERIDEM_HOT_INLINE TangentialResultOf<T>
coulombSpring(T kt, T etaT, T mu, T normalForce, lanes::Vec3Of<T> spring, const lanes::Vec3Of<T>& normal,
              const lanes::Vec3Of<T>& tangentialVelocity, Real dt)
{
    using namespace lanes;
    using V = Vec3Of<T>;
    const T zero{};
    if constexpr (!kProjected)
        spring = projectSpring<T>(spring, normal);
    spring = spring + tangentialVelocity * dt;
    const V trial = -kt * spring - etaT * tangentialVelocity;
    const T cap = mu * (normalForce > zero ? normalForce : zero); // mu max(Fn, 0), NaN -> 0
    const T trialLength2 = lengthSquared(trial);
    const MaskOf<T> sticks = trialLength2 <= cap * cap;
    if (allLanes(sticks))
        return {trial, spring, !sticks};
    const V force = trial * (cap / laneSqrt(trialLength2));
    const V springForce = force + etaT * tangentialVelocity; // -kt xi: Ft less the dashpot's part
    const V held = select(dot(springForce, force) < zero, V{}, springForce);
    const V cappedSpring = select(kt > zero, -held / kt, V{});
    return {select(sticks, trial, force), select(sticks, spring, cappedSpring), !sticks};
}

/// Scalar forms (unit tests, the time-step estimate).
inline Vec3 projectSpringToTangentPlane(const Vec3& spring, const Vec3& normal)
{
    return projectSpring<Real>(spring, normal);
}
inline TangentialResult coulombSpringForce(Real kt, Real etaT, Real mu, Real normalForce, Vec3 spring,
                                           const Vec3& normal, const Vec3& tangentialVelocity, Real dt)
{
    return coulombSpring<Real>(kt, etaT, mu, normalForce, spring, normal, tangentialVelocity, dt);
}

} // namespace veridem::dem
