// Velocity-Verlet integration of translation and rotation (spheres: isotropic inertia, so the
// angular velocity needs no orientation). a = F/m + g, dw/dt = T/I.
#pragma once

#include "dem/parallel.h"
#include "dem/particles.h"
#include "dem/walls/wall.h"
#include "dem/world.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace veridem::dem
{

/// v += dt/2 a; w += dt/2 alpha; x += dt v.
inline void kickDrift(ParticleStore& p, const Vec3& gravity, Real dt)
{
    const Real half = 0.5 * dt;
    parallelFor(p.size(),
                [&](std::size_t i)
                {
                    p.velocity[i] += half * (p.force[i] * p.invMass[i] + gravity);
                    p.angularVelocity[i] += (half * p.invInertia[i]) * p.torque[i];
                    p.position[i] += dt * p.velocity[i];
                });
}

inline void recordFirstNonFinite(const ParticleStore& p, StepHealth& health)
{
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!isFinite(p.position[i]) || !isFinite(p.velocity[i]) || !isFinite(p.angularVelocity[i]))
        {
            health.firstNonFinite = static_cast<std::uint32_t>(i);
            return;
        }
}

/// Particles [begin, end): v += dt/2 a; w += dt/2 alpha. Returns false if some position or
/// velocity of the range is not finite (recordFirstNonFinite finds it).
inline bool kick(ParticleStore& p, const Vec3& gravity, Real dt, std::size_t begin, std::size_t end)
{
    const Real half = 0.5 * dt;
    bool finite = true;
    for (std::size_t i = begin; i < end; ++i)
    {
        p.velocity[i] += half * (p.force[i] * p.invMass[i] + gravity);
        p.angularVelocity[i] += (half * p.invInertia[i]) * p.torque[i];
        finite =
            finite && isFinite(p.position[i]) && isFinite(p.velocity[i]) && isFinite(p.angularVelocity[i]);
    }
    return finite;
}

/// Advances prescribed wall motion by dt (rotation about the symmetry axis leaves the geometry
/// unchanged; only translation moves it).
inline void moveWalls(std::vector<Wall>& walls, Real dt)
{
    for (Wall& w : walls)
        w.displacement += dt * w.motion.velocity;
}

} // namespace veridem::dem
