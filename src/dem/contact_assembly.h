// The assembly of one contact's loads, written once: from the contact law's output (signed normal
// force Fn, tangential force Ft, rolling torque M_r; dem/contact_law.h) and the contact frame (unit
// normal n from the partner towards body i, lever arms; dem/contact_frame.h) to the force and the
// torques on both partners. Templates over the number type (dem/lanes.h): the pair lanes, the scalar
// pairs, the periodic pairs and every wall pass run this source, so they give the same bits.
//
//   force on i       F   = Fn n + Ft                 (-F on the partner)
//   pair, torque i   T_i = M_r - l_i (n x Ft)        (lever arms l_i + l_j = d: pairContactFrame)
//   pair, torque j   T_j = -M_r - l_j (n x Ft)
//   wall, torque i   T_i = M_r + (-r n) x Ft         (arm -r n: wallArm; the wall takes no torque)
//
// (The wall's torque is written with its arm vector, as the wall loads record it; the pair's with
// the lever lengths: the two forms are equal in exact arithmetic, not in rounding.)
#pragma once

#include "core/hot.h"
#include "dem/lanes.h"

namespace veridem::dem
{

/// Force on body i [N] (F = Fn n + Ft) of a contact with unit normal n, signed normal force Fn
/// [N] (> 0 repulsive) and tangential force Ft [N].
template <class T>
VERIDEM_HOT_INLINE lanes::Vec3Of<T> contactForceOf(const lanes::Vec3Of<T>& normal, T normalForce,
                                                   const lanes::Vec3Of<T>& tangentialForce)
{
    return normalForce * normal + tangentialForce;
}

/// The torques [N m] of a pair contact on i and j from the rolling torque on i [N m], the
/// tangential force on i [N] and the lever arms l_i, l_j [m] (pairContactFrame).
template <class T> struct PairTorquesOf
{
    lanes::Vec3Of<T> onI, onJ;
};
template <class T>
VERIDEM_HOT_INLINE PairTorquesOf<T>
pairContactTorques(const lanes::Vec3Of<T>& normal, const lanes::Vec3Of<T>& tangentialForce,
                   const lanes::Vec3Of<T>& rollingTorque, T leverI, T leverJ)
{
    using namespace lanes;
    const Vec3Of<T> tangentialTorque = cross(normal, tangentialForce); // n x Ft
    return {rollingTorque - leverI * tangentialTorque, -rollingTorque - leverJ * tangentialTorque};
}

/// The torque [N m] of a wall contact on the particle, from the rolling torque [N m], the lever
/// arm (wallArm: -r n) [m] and the tangential force on the particle [N].
VERIDEM_HOT_INLINE Vec3 wallContactTorque(const Vec3& rollingTorque, const Vec3& arm,
                                          const Vec3& tangentialForce)
{
    return rollingTorque + cross(arm, tangentialForce);
}

} // namespace veridem::dem
