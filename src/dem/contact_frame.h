// The contact frame: what the contact law needs to know of the geometry and motion of two touching
// bodies (unit normal, overlap, the lever arms from the centres to the contact point, and the
// velocity of one contact point relative to the other), made by pure functions, one for a pair of
// spheres and one for a sphere and a wall (each wall shape gives its gap, walls/wall.h: wallGap).
// Templates over the number type (dem/lanes.h): the scalar path and the lanes run the same source,
// so they give the same bits.
//
// Lever arms ("contact radius convention", docs/models.md):
//  * sphere-sphere: the contact point divides the centre distance d in the ratio of the radii,
//    l_i = r_i d / (r_i + r_j), so l_i + l_j = d and the tangential force conserves the total
//    angular momentum exactly (with r_i alone it would be violated by delta n x Ft).
//  * sphere-wall: the undeformed radius r. The contact-point velocity v + w x (-r n) and the torque
//    (-r n) x Ft use the same arm, so the discrete dynamics are exactly those of a rigid ball of
//    radius r rolling on the wall (v = r w when rolling), which is what the analytical solutions
//    assume (2/7 Omega orbit, 5/7 v0 bowling ball).
#pragma once

#include "dem/lanes.h"
#include "dem/walls/wall.h"

namespace veridem::dem
{

/// The frame of a contact: unit normal (from the partner towards body i), overlap [m], lever arms
/// of the two bodies [m] (pairs; a wall's is -r n), and the velocity of i's contact point relative
/// to the partner's [m/s].
template <class T> struct ContactFrameOf
{
    lanes::Vec3Of<T> normal;
    T overlap;
    T leverI, leverJ;
    lanes::Vec3Of<T> relativeVelocity;
};

/// The frame of spheres i and j (radii ri, rj [m]) at separation x_i - x_j [m], with velocities
/// differing by dv = v_i - v_j [m/s] and angular velocities wi, wj [rad/s]. Coincident centres
/// take the normal +z. One division serves 1/d and d/(r_i + r_j).
template <class T>
VERIDEM_HOT_INLINE ContactFrameOf<T> pairContactFrame(const lanes::Vec3Of<T>& separation, T ri, T rj,
                                                      const lanes::Vec3Of<T>& dv, const lanes::Vec3Of<T>& wi,
                                                      const lanes::Vec3Of<T>& wj)
{
    using namespace lanes;
    const T zero{};
    const T touching = ri + rj;
    const T distance = laneSqrt(lengthSquared(separation));
    const MaskOf<T> positive = distance > zero;
    const T reciprocal = 1.0 / (distance * touching);
    const T inverseDistance = touching * reciprocal;
    ContactFrameOf<T> f;
    f.normal = select(positive, separation * inverseDistance, Vec3Of<T>{zero, zero, zero + 1.0});
    f.overlap = touching - distance;
    const T share = positive ? distance * distance * reciprocal : zero;
    f.leverI = ri * share;
    f.leverJ = rj * share;
    f.relativeVelocity = dv - cross(f.leverI * wi + f.leverJ * wj, f.normal);
    return f;
}

/// The lever arm of a wall contact [m]: centre to contact point (-r n).
VERIDEM_HOT_INLINE Vec3 wallArm(Real r, const Vec3& normal)
{
    return -r * normal;
}

/// The frame of a sphere (centre x [m], velocity v [m/s], angular velocity w [rad/s], radius r [m])
/// touching a wall along `normal` (its gap, wallGap) with overlap [m], the wall moving with
/// `motion` at the half step (surfaceMotion(wall, -dt/2)); halfStep = dt/2 [s]. leverI = r (the
/// arm is -r n), leverJ = 0. The particle's velocities are those of the half step t+dt/2, so the
/// wall's surface velocity is taken at the contact point of the half step too (x - v dt/2). Using
/// x(t+dt) would add a spurious slip Omega |v| dt/2 on a rotating wall, and a ball orbiting on a
/// turntable would lose speed at a rate of order Omega v dt.
VERIDEM_HOT_INLINE ContactFrameOf<Real> wallContactFrame(const Vec3& normal, Real overlap, const Vec3& x,
                                                         const Vec3& v, const Vec3& w, Real r,
                                                         const SurfaceMotion& motion, Real halfStep)
{
    const Vec3 arm = wallArm(r, normal);
    const Vec3 midStepContactPoint = x - halfStep * v + arm;
    return {normal, overlap, r, 0, v + cross(w, arm) - velocityAt(motion, midStepContactPoint)};
}

/// The effective radius R* = ri rj / (ri + rj) [m] of two spheres of radii ri, rj [m] (convex
/// against convex; a sphere inside a concave wall: walls/wall.h).
VERIDEM_HOT_INLINE Real pairEffectiveRadius(Real ri, Real rj)
{
    return ri * rj / (ri + rj);
}

/// The rolling inertia of a pair [kg m^2]: the series combination of each sphere's moment of
/// inertia about its contact point, I + m r^2 (invInertia [1/(kg m^2)], mass [kg], radius [m]).
VERIDEM_HOT_INLINE Real pairRollingInertia(Real invInertiaI, Real massI, Real ri, Real invInertiaJ,
                                           Real massJ, Real rj)
{
    return 1.0 / (1.0 / (1.0 / invInertiaI + massI * ri * ri) + 1.0 / (1.0 / invInertiaJ + massJ * rj * rj));
}

/// The rolling inertia of a sphere on a wall [kg m^2]: about its contact point, I + m r^2
/// (spinInertia I [kg m^2], mass [kg], radius [m]).
VERIDEM_HOT_INLINE Real wallRollingInertia(Real spinInertia, Real mass, Real r)
{
    return spinInertia + mass * r * r;
}

} // namespace veridem::dem
