// Rolling resistance torques (pure functions, templates over the number type T: double or a
// vector of lanes, dem/lanes.h). Both oppose the angular velocity of the particle RELATIVE TO ITS
// CONTACT PARTNER, w_rel = w_i - w_partner (for a wall: the wall's own angular velocity),
// twisting part included, so that the torque is objective on rotating and curved walls
// (BENCHMARKS 1b, 1c: without the twisting part the dish test locks at a wrong height).
//
// Type A, constant directional torque (Beer & Johnson 1976; Zhou et al. 1999; the paper's eq. 3):
//     M = -muR Fn w_rel / |w_rel|,    muR a length [m] (= muR' * R_r with R_r = R1 R2/(R1+R2)).
//   Rest treatment: |M| is limited to I_r |w_rel| / dt, the torque that would stop the relative
//   rotation within one step, so it does not chatter (+-muR Fn each step) at rest
//   (BENCHMARKS 2.3 fix (a)). This only acts when |w_rel| < muR Fn dt / I_r.
//
// Type C, elastic-plastic spring-dashpot "EPSD" (Ai, Chen, Rotter & Ooi 2011):
//     dMk = -kr w_rel dt, |Mk| <= muR Fn,  kr = 2.25 kn muR^2   (kn muR'^2 R_r^2 form),
//     Md  = -Cr w_rel while |Mk| < muR Fn (zero once fully mobilised), Cr = etaR 2 sqrt(I_r kr).
//   It holds a ball at rest on an incline with tan(theta) <= muR'.
//
// Type B, viscous, and the absolute-frame variant of type A (M = -muR Fn w_i/|w_i| with the
// particle's own w_i, as EDEM's "standard" rolling friction and MUSEN apply it) are selectable
// too; the absolute variant is not objective on moving walls (rolling_resistance_models shows the
// consequence) and, for particle pairs, uses particle i's w and applies the reaction to j.
#pragma once

#include "core/hot.h"
#include "core/vec3.h"
#include "dem/lanes.h"

namespace veridem::dem
{

/// Type A torque on the particle [N m]. muR [m], Fn [N] (clipped >= 0), wRel [rad/s],
/// rollingInertia I_r [kg m^2] (reduced moment of inertia of the pair), dt [s].
template <class T>
VERIDEM_HOT_INLINE lanes::Vec3Of<T> constantRollingTorqueOf(T muR, T normalForce,
                                                            const lanes::Vec3Of<T>& relativeAngularVelocity,
                                                            T rollingInertia, Real dt)
{
    using namespace lanes;
    using V = Vec3Of<T>;
    const T zero{};
    const T w = laneSqrt(lengthSquared(relativeAngularVelocity));
    MaskOf<T> none = w == zero;
    none = none | (muR == zero);
    none = none | (normalForce <= zero);
    if (allLanes(none))
        return V{};
    // |M| / w = min(muR Fn / w, I_r / dt): one division after the square root instead of two, and
    // a comparison instead of a call to libm's fmin (w > 0 and Fn > 0 here).
    const T mobilised = muR * normalForce / w, stopping = rollingInertia / dt;
    const T scale = -(mobilised < stopping ? mobilised : stopping);
    return select(none, V{}, relativeAngularVelocity * scale);
}

/// Type B, viscous (Ai et al. 2011's class B; the torque grows with the rolling speed as in the
/// viscoelastic rolling friction of Brilliantov & Poeschel 1998): M = -c_r Fn R_r^2 w_rel,
/// c_r [s/m], R_r [m], Fn [N] (clipped >= 0). A ball rolling on a plane slows as exp(-(5/7) c_r g t)
/// and on an incline tends to v = tan(theta)/c_r; it never holds a ball at rest on a slope.
template <class T>
VERIDEM_HOT_INLINE lanes::Vec3Of<T> viscousRollingTorqueOf(T coefficient, T rollingRadius, T normalForce,
                                                           const lanes::Vec3Of<T>& relativeAngularVelocity)
{
    using namespace lanes;
    using V = Vec3Of<T>;
    const MaskOf<T> none = normalForce <= T{};
    if (allLanes(none))
        return V{};
    const T scale = -(coefficient * normalForce * rollingRadius * rollingRadius);
    return select(none, V{}, relativeAngularVelocity * scale);
}

template <class T> struct RollingSpringResultOf
{
    lanes::Vec3Of<T> torque; // on the particle [N m]
    lanes::Vec3Of<T> spring; // updated elastic torque Mk [N m]
    lanes::MaskOf<T> fullyMobilised{};
};
using RollingSpringResult = RollingSpringResultOf<Real>;

/// The EPSD rolling stiffness kr = 2.25 kn muR^2 [N m/rad] of a contact of normal stiffness kn
/// [N/m] and rolling friction length muR [m] (the one source: the law and the stable time step).
template <class T> VERIDEM_HOT_INLINE T epsdRollingStiffness(T kn, T muR)
{
    return 2.25 * kn * muR * muR;
}

/// Type C (EPSD) torque. kr [N m/rad], cr [N m s/rad], muR [m], Fn [N], spring Mk [N m].
template <class T>
VERIDEM_HOT_INLINE RollingSpringResultOf<T>
epsdRollingTorqueOf(T kr, T cr, T muR, T normalForce, lanes::Vec3Of<T> spring,
                    const lanes::Vec3Of<T>& relativeAngularVelocity, Real dt)
{
    using namespace lanes;
    using V = Vec3Of<T>;
    const T zero{};
    spring = spring - relativeAngularVelocity * (kr * dt);
    const T cap = muR * (normalForce > zero ? normalForce : zero); // mu max(Fn, 0), NaN -> 0
    const T springLength = laneSqrt(lengthSquared(spring));
    const MaskOf<T> mobilised = springLength > cap;
    V capped = spring;
    if (anyLane(mobilised))
        capped = select(springLength > zero, spring * (cap / springLength), V{});
    const V torque = select(mobilised, capped, spring - relativeAngularVelocity * cr);
    return {torque, select(mobilised, capped, spring), mobilised};
}

/// Scalar forms (unit tests).
inline Vec3 viscousRollingTorque(Real coefficient, Real rollingRadius, Real normalForce,
                                 const Vec3& relativeAngularVelocity)
{
    return viscousRollingTorqueOf<Real>(coefficient, rollingRadius, normalForce, relativeAngularVelocity);
}
inline Vec3 constantRollingTorque(Real muR, Real normalForce, const Vec3& relativeAngularVelocity,
                                  Real rollingInertia, Real dt)
{
    return constantRollingTorqueOf<Real>(muR, normalForce, relativeAngularVelocity, rollingInertia, dt);
}
inline RollingSpringResult epsdRollingTorque(Real kr, Real cr, Real muR, Real normalForce, Vec3 spring,
                                             const Vec3& relativeAngularVelocity, Real dt)
{
    return epsdRollingTorqueOf<Real>(kr, cr, muR, normalForce, spring, relativeAngularVelocity, dt);
}

} // namespace veridem::dem
