// Velocity-Verlet integration of translation and rotation (spheres: isotropic inertia, so the
// angular velocity needs no orientation). a = F/m + g, dw/dt = T/I.
#pragma once

#include "core/hot.h"
#include "dem/parallel.h"
#include "dem/particles.h"
#include "dem/walls/wall.h"
#include "dem/world.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace veridem::dem
{

/// Largest squared displacements [m^2] of a kickDrift against the neighbour list's two
/// reference positions (NeighborList::MotionReference).
struct Motion
{
    Real sinceBuild2 = 0, sinceActiveBuild2 = 0;
};

/// The arrays the integration loops read and write, their bases held in locals (GCC would reload
/// them from the vectors after every store through one of them).
struct IntegrationArrays
{
    Vec3* position;             // [m]
    Vec3* velocity;             // [m/s]
    Vec3* angularVelocity;      // [rad/s]
    const PaddedVec3* force;    // [N]
    const PaddedVec3* torque;   // [N m]
    const Real* invMass;        // [1/kg]
    const Real* invInertia;     // [1/(kg m^2)]
    PaddedVec3* positionRadius; // (x, y, z, r) rows, rewritten with each drift; null if not sized
    const Real* radius;         // [m]

    explicit IntegrationArrays(ParticleStore& p)
        : position(p.position.data()), velocity(p.velocity.data()), angularVelocity(p.angularVelocity.data()),
          force(p.force.data()), torque(p.torque.data()), invMass(p.invMass.data()),
          invInertia(p.invInertia.data()),
          positionRadius(p.positionRadius.size() == p.size() ? p.positionRadius.data() : nullptr),
          radius(p.radius.data())
    {
    }
};

/// One particle's first half kick and drift: v += dt/2 (F/m + g); w += dt/2 T/I; x += dt v.
/// force [N], torque [N m], invMass [1/kg], invInertia [1/(kg m^2)], gravity [m/s^2], dt [s].
VERIDEM_HOT_INLINE void kickDriftOne(Vec3& position, Vec3& velocity, Vec3& angularVelocity, const Vec3& force,
                                     const Vec3& torque, Real invMass, Real invInertia, const Vec3& gravity,
                                     Real dt)
{
    const Real half = 0.5 * dt;
    velocity += half * (force * invMass + gravity);
    angularVelocity += (half * invInertia) * torque;
    position += dt * velocity;
}

/// Particles [begin, end): kickDriftOne, folding each one's squared displacement from the two
/// `reference` positions into `m` (skipped if reference.built is null).
inline Motion kickDriftRange(ParticleStore& p, const Vec3& gravity, Real dt,
                             NeighborList::MotionReference reference, std::size_t begin, std::size_t end,
                             Motion m)
{
    const bool rows = p.positionRadius.size() == p.size();
    for (std::size_t i = begin; i < end; ++i)
    {
        kickDriftOne(p.position[i], p.velocity[i], p.angularVelocity[i], p.force[i], p.torque[i],
                     p.invMass[i], p.invInertia[i], gravity, dt);
        if (rows)
            p.positionRadius[i] = p.positionRadiusRow(i);
        if (reference.built)
        {
            m.sinceBuild2 = std::max(m.sinceBuild2, lengthSquared(p.position[i] - reference.built[i]));
            m.sinceActiveBuild2 =
                std::max(m.sinceActiveBuild2, lengthSquared(p.position[i] - reference.activeBuilt[i]));
        }
    }
    return m;
}

/// kickDriftRange in four AVX2 lanes (integrate.cpp): the same operations in the same order, so
/// the same bits. Only on a CPU with AVX2 (exec::isaName() == "avx2").
Motion kickDriftLanes(ParticleStore& p, const Vec3& gravity, Real dt, NeighborList::MotionReference reference,
                      std::size_t begin, std::size_t end);

/// v += dt/2 a; w += dt/2 alpha; x += dt v for all particles. Measures, as it writes x, how far
/// the particles are from `reference` (the neighbour list's motion check, without a second pass
/// over the positions and a second parallel region); if reference.built is null, returns zero
/// motion. `lanes`: the loop runs in AVX2 lanes (kickDriftLanes).
inline Motion kickDrift(ParticleStore& p, const Vec3& gravity, Real dt,
                        NeighborList::MotionReference reference, bool lanes)
{
    const std::size_t n = p.size();
    const auto range = [&](std::size_t begin, std::size_t end)
    {
        return lanes ? kickDriftLanes(p, gravity, dt, reference, begin, end)
                     : kickDriftRange(p, gravity, dt, reference, begin, end, Motion{});
    };
    const int chunks = std::min(loopThreads(n), 64);
    if (chunks == 1)
        return range(0, n);
    Motion chunk[64];
    parallelChunks(n, chunks,
                   [&](int c, std::size_t begin, std::size_t end) { chunk[c] = range(begin, end); });
    Motion m; // a maximum: the same for any chunking
    for (int c = 0; c < chunks; ++c)
        m = {std::max(m.sinceBuild2, chunk[c].sinceBuild2),
             std::max(m.sinceActiveBuild2, chunk[c].sinceActiveBuild2)};
    return m;
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

/// One particle's second half kick: v += dt/2 (F/m + g); w += dt/2 T/I (arguments as
/// kickDriftOne). Returns false if its position or velocities are not finite.
VERIDEM_HOT_INLINE bool kickOne(const Vec3& position, Vec3& velocity, Vec3& angularVelocity,
                                const Vec3& force, const Vec3& torque, Real invMass, Real invInertia,
                                const Vec3& gravity, Real dt)
{
    const Real half = 0.5 * dt;
    const Real halfInvInertia = half * invInertia;
    const Real vx = velocity.x + half * (force.x * invMass + gravity.x),
               vy = velocity.y + half * (force.y * invMass + gravity.y),
               vz = velocity.z + half * (force.z * invMass + gravity.z);
    const Real wx = angularVelocity.x + halfInvInertia * torque.x,
               wy = angularVelocity.y + halfInvInertia * torque.y,
               wz = angularVelocity.z + halfInvInertia * torque.z;
    velocity = {vx, vy, vz};
    angularVelocity = {wx, wy, wz};
    // 0 * a is 0 for every finite a and NaN for inf and NaN: one sum of nine such products
    // is 0 exactly when all nine components are finite (no branch per component).
    const Vec3 x = position;
    const Real probe = (0.0 * x.x + 0.0 * x.y + 0.0 * x.z) + (0.0 * vx + 0.0 * vy + 0.0 * vz) +
                       (0.0 * wx + 0.0 * wy + 0.0 * wz);
    return probe == 0.0;
}

/// Particles [begin, end): kickOne. Returns false if some position or velocity of the range is
/// not finite (recordFirstNonFinite finds it).
inline bool kickRange(ParticleStore& p, const Vec3& gravity, Real dt, std::size_t begin, std::size_t end)
{
    const Vec3 g = gravity; // (a copy: a store to a particle could alias the reference)
    const IntegrationArrays a(p);
    bool finite = true;
    for (std::size_t i = begin; i < end; ++i)
        finite = kickOne(a.position[i], a.velocity[i], a.angularVelocity[i], a.force[i], a.torque[i],
                         a.invMass[i], a.invInertia[i], g, dt) &
                 finite;
    return finite;
}

/// kickRange in four AVX2 lanes (integrate.cpp): the same operations and bits. Only on a CPU
/// with AVX2.
bool kickLanes(ParticleStore& p, const Vec3& gravity, Real dt, std::size_t begin, std::size_t end);

/// kickRange, in AVX2 lanes if `lanes` (kickLanes).
inline bool kick(ParticleStore& p, const Vec3& gravity, Real dt, std::size_t begin, std::size_t end,
                 bool lanes)
{
    return lanes ? kickLanes(p, gravity, dt, begin, end) : kickRange(p, gravity, dt, begin, end);
}

/// Particles [begin, end): the closing half kick of one step (kickOne), then the next step's
/// kick-drift (kickDriftOne), in one pass: the operations of kickRange followed by kickDriftRange,
/// so the same bits, with each particle's rows loaded and stored once (advance(), world.cpp).
/// Folds the displacements from `reference` into `m` as kickDriftRange; returns false if some
/// state after the kick (x(t), v(t), w(t)) is not finite. Leaves the range's force and torque rows
/// zero, ready for the next step's sums (computePairForces, sumsAreZero).
inline bool kickThenKickDriftRange(ParticleStore& p, const Vec3& gravity, Real dt,
                                   NeighborList::MotionReference reference, std::size_t begin,
                                   std::size_t end, Motion& m)
{
    const bool finite = kickRange(p, gravity, dt, begin, end);
    m = kickDriftRange(p, gravity, dt, reference, begin, end, m);
    for (std::size_t i = begin; i < end; ++i)
        p.force[i] = p.torque[i] = PaddedVec3{};
    return finite;
}

/// kickThenKickDriftRange in four AVX2 lanes (integrate.cpp): the same operations and bits. Only
/// on a CPU with AVX2.
bool kickThenKickDriftLanes(ParticleStore& p, const Vec3& gravity, Real dt,
                            NeighborList::MotionReference reference, std::size_t begin, std::size_t end,
                            Motion& m);

/// kickThenKickDriftRange, in AVX2 lanes if `lanes`.
inline bool kickThenKickDrift(ParticleStore& p, const Vec3& gravity, Real dt,
                              NeighborList::MotionReference reference, std::size_t begin, std::size_t end,
                              bool lanes, Motion& m)
{
    return lanes ? kickThenKickDriftLanes(p, gravity, dt, reference, begin, end, m)
                 : kickThenKickDriftRange(p, gravity, dt, reference, begin, end, m);
}

/// Advances prescribed wall motion by dt (rotation about the symmetry axis leaves an analytic
/// shape unchanged; only translation moves it; a mesh's frame turns with its rotation). An
/// oscillating wall is put at its exact position A sin(Omega (t+dt)), and its velocity is set to
/// A Omega cos(Omega (t+dt/2)): the contact law pairs it with the particles' half-step velocities,
/// and it is the displacement over the step divided by dt to O(dt^2). A wall with a velocity table
/// is put at the table's exact integral and takes its velocity at t+dt/2; with an angular-velocity
/// table, its angular velocity at t+dt/2.
inline void moveWalls(std::vector<Wall>& walls, Real dt)
{
    for (Wall& w : walls)
    {
        w.clock += dt;
        const Real omega = w.motion.oscillationAngularFrequency;
        if (!w.motion.angularVelocityTable.empty()) [[unlikely]]
            w.motion.angularVelocity = w.motion.angularVelocityTable.at(w.clock - 0.5 * dt);
        if (!w.motion.velocityTable.empty()) [[unlikely]]
        {
            w.displacement = w.motion.velocityTable.integralFromZero(w.clock);
            w.motion.velocity = w.motion.velocityTable.at(w.clock - 0.5 * dt);
        }
        else if (omega > 0)
        {
            w.displacement = std::sin(omega * w.clock) * w.motion.oscillationAmplitude;
            w.motion.velocity =
                (omega * std::cos(omega * (w.clock - 0.5 * dt))) * w.motion.oscillationAmplitude;
        }
        else
            w.displacement += dt * w.motion.velocity;
        if (auto* mesh = std::get_if<MeshShape>(&w.shape))
            rotateMesh(*mesh, dt * w.motion.angularVelocity);
    }
}

} // namespace veridem::dem
