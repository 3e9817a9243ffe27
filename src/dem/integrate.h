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

/// v += dt/2 a; w += dt/2 alpha; records the first non-finite particle in `health`.
inline void kick(ParticleStore& p, const Vec3& gravity, Real dt, StepHealth& health)
{
    const Real half = 0.5 * dt;
    const std::size_t n = p.size();
    const int chunks = std::min(loopThreads(n), 64);
    if (chunks == 1)
    {
        bool finite = true;
        for (std::size_t i = 0; i < n; ++i)
        {
            p.velocity[i] += half * (p.force[i] * p.invMass[i] + gravity);
            p.angularVelocity[i] += (half * p.invInertia[i]) * p.torque[i];
            finite = finite && isFinite(p.position[i]) && isFinite(p.velocity[i]) &&
                     isFinite(p.angularVelocity[i]);
        }
        health.finite = finite;
        if (!finite)
            recordFirstNonFinite(p, health);
        return;
    }
    bool chunkFinite[64];
    parallelChunks(n, chunks,
                   [&](int c, std::size_t begin, std::size_t end)
                   {
                       bool finite = true;
                       for (std::size_t i = begin; i < end; ++i)
                       {
                           p.velocity[i] += half * (p.force[i] * p.invMass[i] + gravity);
                           p.angularVelocity[i] += (half * p.invInertia[i]) * p.torque[i];
                           finite = finite && isFinite(p.position[i]) && isFinite(p.velocity[i]) &&
                                    isFinite(p.angularVelocity[i]);
                       }
                       chunkFinite[c] = finite;
                   });
    const bool finite = std::all_of(chunkFinite, chunkFinite + chunks, [](bool b) { return b; });
    health.finite = finite;
    if (!finite)
        recordFirstNonFinite(p, health);
}

/// Advances prescribed wall motion by dt (rotation about the symmetry axis leaves the geometry
/// unchanged; only translation moves it).
inline void moveWalls(std::vector<Wall>& walls, Real dt)
{
    for (Wall& w : walls)
        w.displacement += dt * w.motion.velocity;
}

} // namespace veridem::dem
