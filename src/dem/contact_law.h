// The contact law: normal force, then tangential force capped by it, then rolling torque capped by
// it, in that fixed visible order. The same function serves particle pairs and particle-wall
// contacts: a wall is a partner of infinite mass with a prescribed velocity and angular velocity.
#pragma once

#include "core/hot.h"
#include "core/vec3.h"
#include "dem/materials.h"
#include "dem/models/normal.h"
#include "dem/models/rolling.h"
#include "dem/models/tangential.h"

#include <cmath>
#include <vector>

namespace veridem::dem
{

/// Geometry and kinematics of one contact, as seen by particle i.
struct ContactInput
{
    Vec3 normal;                  // unit, from the partner towards particle i
    Real overlap = 0;             // delta > 0 [m]
    Vec3 relativeVelocity;        // contact-point velocity of i minus that of the partner [m/s]
    Vec3 relativeAngularVelocity; // w_i - w_partner [rad/s]
    Real effectiveMass = 0;       // m* [kg]
    Real effectiveRadius = 0;     // R* [m] (Hertz, and R_r for dimensionless rolling friction)
    Real rollingInertia = 0;      // I_r = [(I1 + m1 r1^2)^-1 + (I2 + m2 r2^2)^-1]^-1 [kg m^2] (EPSD damping)
    Real spinInertia = 0;         // [1/I1 + 1/I2]^-1 [kg m^2] (type A rest treatment; twist-safe)
    Vec3 angularVelocity;         // w_i, particle i's own [rad/s] (absolute-frame type A only)
};

/// Per-contact history carried from step to step.
struct ContactHistory
{
    Vec3 tangentialSpring; // xi [m]
    Vec3 rollingSpring;    // EPSD elastic torque [N m]
};

/// Entry k of history kept as parallel arrays (the contact lists'): the tangential spring, and
/// the rolling spring only if `keepRolling` (an EPSD rolling model is in use; else it is empty).
inline ContactHistory historyAt(const std::vector<Vec3>& tangential, const std::vector<Vec3>& rolling,
                                bool keepRolling, std::size_t k)
{
    return {tangential[k], keepRolling ? rolling[k] : Vec3{}};
}
inline void storeHistoryAt(std::vector<Vec3>& tangential, std::vector<Vec3>& rolling, bool keepRolling,
                           std::size_t k, const ContactHistory& h)
{
    tangential[k] = h.tangentialSpring;
    if (keepRolling)
        rolling[k] = h.rollingSpring;
}

struct ContactOutput
{
    Vec3 force;           // total force on i [N] (normal + tangential)
    Vec3 tangentialForce; // its tangential part [N] (its torque lever is applied by the caller)
    Vec3 rollingTorque;   // rolling/twisting resistance torque on i [N m]
    Real normalForce = 0; // signed Fn [N] (> 0 repulsive; may be slightly < 0: no clipping)
    bool sliding = false;
};

/// Normal and tangential stiffness/damping of a pair at overlap delta (kn, kt [N/m]; eta [N s/m]).
struct ContactCoefficients
{
    Real kn = 0, kt = 0, etaN = 0, etaT = 0;
};

VERIDEM_HOT_INLINE ContactCoefficients contactCoefficients(const PairParams& p, Real overlap,
                                                           Real effectiveMass, Real effectiveRadius)
{
    ContactCoefficients c;
    if (p.normalModel == NormalModel::Linear)
    {
        c.kn = p.kn;
        c.kt = p.ktRatio * p.kn;
        c.etaN = p.dampingRate >= 0 ? p.dampingRate * effectiveMass
                                    : 2.0 * p.dampingRatio * std::sqrt(effectiveMass * p.kn);
    }
    else
    {
        c.kn = hertzNormalStiffness(p.effectiveModulus, effectiveRadius, overlap);
        c.kt = 8.0 * p.effectiveShearModulus * std::sqrt(effectiveRadius * overlap);
        c.etaN = p.dampingRate >= 0 ? p.dampingRate * effectiveMass
                                    : hertzDampingCoefficient(p.hertzBeta, c.kn, effectiveMass);
    }
    c.etaT = p.tangentialDampingRatio * c.etaN;
    return c;
}

/// Rolling friction as a length [m] for a contact of rolling radius R_r [m].
inline Real rollingFrictionLength(const PairParams& p, Real rollingRadius)
{
    return p.rollingLength + p.rollingDimensionless * rollingRadius;
}

VERIDEM_HOT_INLINE ContactOutput evaluateContact(const PairParams& p, const ContactInput& in,
                                                 ContactHistory& history, Real dt)
{
    // Built from locals and returned whole: a default-constructed `out` filled in field by field
    // makes GCC zero it in memory first (rep stos) on every contact.
    const ContactCoefficients c = contactCoefficients(p, in.overlap, in.effectiveMass, in.effectiveRadius);

    // 1. Normal force.
    const Real normalSpeed = dot(in.relativeVelocity, in.normal); // < 0 while approaching
    const Real elastic = p.normalModel == NormalModel::Linear
                             ? c.kn * in.overlap
                             : hertzElasticForce(p.effectiveModulus, in.effectiveRadius, in.overlap);
    // Contact transitions. The dashpot force jumps to etaN |vn| at first touch and from it at
    // separation, so the force sampled at t+dt (which acts over the kick window
    // [t+dt/2, t+3dt/2]) would otherwise act for a full step whatever fraction of the window is
    // in contact: an O(zeta omega dt) error in e that depends on where first touch falls between
    // steps. When the neighbouring step (t before first touch, t+2dt after separation) is out of
    // contact, i.e. delta < |vn| dt, the dashpot is weighted by the contact time credited to this
    // window, 1/2 + delta/(|vn| dt) (derivation in docs/models.md).
    const Real travel = std::fabs(normalSpeed) * dt;
    const Real dashpotWeight = in.overlap < travel ? 0.5 + in.overlap / travel : 1.0;
    // The dashpot needs the normal speed at t+dt, but only the half-step speed is known. Solve
    // the pair's own final half kick for it, u = u_half + dt/2 (elastic - eta u)/m*, so that
    // the damping of an isolated contact is integrated to second order (other forces on the two
    // bodies are neglected in this estimate). Written with m* in numerator and denominator,
    // u = (m* u_half + dt/2 elastic) / (m* + dt/2 eta), so that it costs one division.
    const Real dampingWeight = dashpotWeight * c.etaN;
    const Real halfStep = 0.5 * dt;
    const Real normalSpeedEnd =
        (in.effectiveMass * normalSpeed + halfStep * elastic) / (in.effectiveMass + halfStep * dampingWeight);
    const Real normalForce = elastic - dampingWeight * normalSpeedEnd;

    // 2. Tangential force, capped by mu * Fn.
    const Vec3 tangentialVelocity = in.relativeVelocity - normalSpeed * in.normal;
    const TangentialResult t = coulombSpringForce(c.kt, c.etaT, p.mu, normalForce, history.tangentialSpring,
                                                  in.normal, tangentialVelocity, dt);
    history.tangentialSpring = t.spring;

    // 3. Rolling resistance, capped by muR * Fn. It opposes the whole relative angular velocity
    // unless the pair opts out of twist resistance (PairParams::rollingTwist, see materials.h).
    const Vec3 resistedAngularVelocity =
        p.rollingTwist ? in.relativeAngularVelocity
                       : in.relativeAngularVelocity - dot(in.relativeAngularVelocity, in.normal) * in.normal;
    Vec3 rollingTorque{};
    if (p.rollingModel == RollingModel::ConstantTorque)
    {
        rollingTorque = constantRollingTorque(rollingFrictionLength(p, in.effectiveRadius), normalForce,
                                              resistedAngularVelocity, in.spinInertia, dt);
    }
    else if (p.rollingModel == RollingModel::Epsd)
    {
        const Real muR = rollingFrictionLength(p, in.effectiveRadius);
        const Real kr = 2.25 * c.kn * muR * muR;
        const Real cr = p.rollingDampingRatio * 2.0 * std::sqrt(in.rollingInertia * kr);
        const RollingSpringResult r =
            epsdRollingTorque(kr, cr, muR, normalForce, history.rollingSpring, resistedAngularVelocity, dt);
        history.rollingSpring = r.spring;
        rollingTorque = r.torque;
    }
    else if (p.rollingModel == RollingModel::Viscous)
    {
        rollingTorque =
            viscousRollingTorque(p.rollingViscous, in.effectiveRadius, normalForce, resistedAngularVelocity);
    }
    else if (p.rollingModel == RollingModel::ConstantTorqueAbsolute)
    {
        rollingTorque = constantRollingTorque(rollingFrictionLength(p, in.effectiveRadius), normalForce,
                                              in.angularVelocity, in.spinInertia, dt);
    }
    return ContactOutput{normalForce * in.normal + t.force, t.force, rollingTorque, normalForce, t.sliding};
}

} // namespace veridem::dem
