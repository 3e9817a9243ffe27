// The contact law's input (ContactInput, dem/contact_law.h) of a pair of spheres and of a sphere on
// a wall, built once here from the contact frame (dem/contact_frame.h) for every path that runs the
// law: the pair lanes and the scalar pairs (dem/pair_kernel.cpp), the periodic pairs, every wall
// pass (dem/wall_forces.cpp) and the diagnostics (dem/contact_diagnostics.cpp). R* of a pair is
// pairEffectiveRadius, of a wall contact its gap's (walls/wall.h); m* of a pair is the neighbour
// list's (effectivePairMass), of a wall contact the particle's mass (a wall has infinite mass).
#pragma once

#include "dem/contact_frame.h"
#include "dem/contact_law.h"
#include "dem/particles.h"

#include <cstdint>

namespace veridem::dem
{

/// The rolling inputs of spheres i and j (relative and own angular velocity, R*, spin and rolling
/// inertia) into `in`.
VERIDEM_HOT_INLINE void setPairRollingInput(ContactInput& in, const ParticleStore& p, std::uint32_t i,
                                            std::uint32_t j)
{
    const Real ri = p.radius[i], rj = p.radius[j];
    in.relativeAngularVelocity = p.angularVelocity[i] - p.angularVelocity[j];
    in.angularVelocity = p.angularVelocity[i];
    in.effectiveRadius = pairEffectiveRadius(ri, rj);
    in.spinInertia = 1.0 / (p.invInertia[i] + p.invInertia[j]);
    in.rollingInertia = pairRollingInertia(p.invInertia[i], p.mass[i], ri, p.invInertia[j], p.mass[j], rj);
}

/// The contact input of spheres i and j from their frame (pairContactFrame): every field the law
/// can read, with the effective mass m* [kg] given (the neighbour list keeps it per candidate).
VERIDEM_HOT_INLINE ContactInput pairContactInput(const ParticleStore& p, std::uint32_t i, std::uint32_t j,
                                                 const ContactFrameOf<Real>& frame, Real effectiveMass)
{
    ContactInput in;
    in.normal = frame.normal;
    in.overlap = frame.overlap;
    in.relativeVelocity = frame.relativeVelocity;
    in.effectiveMass = effectiveMass;
    setPairRollingInput(in, p, i, j);
    return in;
}

/// The rolling inputs of a sphere (angular velocity w [rad/s], mass [kg], 1/I [1/(kg m^2)], radius
/// r [m]) on a wall turning at wallAngularVelocity [rad/s] into `in` (R* is the gap's: not set).
VERIDEM_HOT_INLINE void setWallRollingInput(ContactInput& in, const Vec3& w, Real mass, Real invInertia,
                                            Real r, const Vec3& wallAngularVelocity)
{
    in.relativeAngularVelocity = w - wallAngularVelocity;
    in.angularVelocity = w;
    in.spinInertia = 1.0 / invInertia;
    in.rollingInertia = wallRollingInertia(in.spinInertia, mass, r);
}

/// The contact input of a sphere in state s touching a wall moving with `motion` at the half step
/// (surfaceMotion(wall, -dt/2)) with gap `gap` (wallGap), as the contact law takes it.
VERIDEM_HOT_INLINE ContactInput wallContactInput(const ParticleState& s, const SurfaceMotion& motion,
                                                 const WallGap& gap, Real dt)
{
    const ContactFrameOf<Real> frame = wallContactFrame(gap.normal, gap.overlap, s.position, s.velocity,
                                                        s.angularVelocity, s.radius, motion, 0.5 * dt);
    ContactInput in;
    in.normal = gap.normal;
    in.overlap = gap.overlap;
    in.relativeVelocity = frame.relativeVelocity;
    in.effectiveMass = s.mass;
    in.effectiveRadius = gap.effectiveRadius;
    setWallRollingInput(in, s.angularVelocity, s.mass, s.invInertia, s.radius, motion.angularVelocity);
    return in;
}

} // namespace veridem::dem
