// The paper's flat rotating turntable (section 4.1, Tests 1-5) as a reusable set-up.
// Conventions (BENCHMARKS 1b): angles in the table plane from east (+x) counter-clockwise;
// the table spins at Omega about its normal k (counter-clockwise seen from above); the initial
// velocity is lab-frame; "no slipping initial condition" sets w = k x (v0 - Omega k x r0) / a,
// with no spin about k; the ball starts at its equilibrium overlap m g cos(alpha) / kn with the
// tangential spring carrying the rolling solution's friction force.
#pragma once

#include "dem/walls/wall.h"
#include "mesh_floors.h"
#include "support.h"

namespace veridem::verify
{

struct TurntableSetup
{
    Real omega = 10.0;             // table angular velocity [rad/s]
    Real tiltDegrees = 0.0;        // tilt angle alpha [deg]
    Real downhillDegrees = 0.0;    // azimuth of the downhill direction [deg]
    Real rollingFriction = 1.5e-6; // muR [m]
    Real initialRadius = 0.04;     // r0 [m]
    Real initialAngleDegrees = 180;
    Real initialSpeed = 0.0; // |v0| lab frame [m/s]
    Real initialDirectionDegrees = 270;
    Real stiffness = 1e5;     // kn [N/m]
    Real tableRadius = 0.2;   // [m]
    bool meshedTable = false; // the table as an irregular triangle mesh (mesh_floors.h: meshedDisk)
};

/// In-plane orthonormal basis (e1, e2) and normal k of the (possibly tilted) table.
struct TableFrame
{
    Vec3 e1, e2, k;
    Vec3 toLab(Real u, Real v) const { return u * e1 + v * e2; }
    Real u(const Vec3& x) const { return dot(x, e1); }
    Real v(const Vec3& x) const { return dot(x, e2); }
};

inline TableFrame tableFrame(const TurntableSetup& s)
{
    const Vec3 k = dem::tiltedNormal(degToRad(s.tiltDegrees), degToRad(s.downhillDegrees));
    const Vec3 e1 = normalizedOrZero(Vec3{1, 0, 0} - k.x * k);
    return {e1, cross(k, e1), k};
}

inline World turntableWorld(const TurntableSetup& s)
{
    Material ball = flatTurntableBall();
    ball.normalStiffness = s.stiffness;
    ball.rollingFrictionLength = s.rollingFriction;
    ball.rollingModel = s.rollingFriction > 0 ? dem::RollingModel::ConstantTorque : dem::RollingModel::None;
    World world = worldWith(ball, {0, 0, -kG});
    const TableFrame f = tableFrame(s);

    dem::Wall table = s.meshedTable ? meshedDisk(s.tableRadius, f.e1, f.e2, 12, 40) : dem::Wall{};
    table.name = "turntable";
    if (!s.meshedTable)
        table.shape = dem::PlaneShape{{0, 0, 0}, f.k, s.tableRadius};
    table.motion.angularVelocity = s.omega * f.k;
    world.walls.push_back(table);

    const Real a = kFlatBallRadius;
    const Real m = sphereMass(ball.density, a);
    const Real overlap = m * kG * f.k.z / s.stiffness;
    const Real angle = degToRad(s.initialAngleDegrees), direction = degToRad(s.initialDirectionDegrees);
    const Vec3 r0 = f.toLab(s.initialRadius * std::cos(angle), s.initialRadius * std::sin(angle));
    const Vec3 v0 = f.toLab(s.initialSpeed * std::cos(direction), s.initialSpeed * std::sin(direction));
    const Vec3 slip = v0 - s.omega * cross(f.k, r0);
    world.particles.add(r0 + (a - overlap) * f.k, v0, cross(f.k, slip) / a, a, ball.density, 0);

    // Start in the rolling solution's contact state: the tangential spring carries the friction
    // force that rigid rolling needs at t = 0, F = m dv/dt - m g_plane with dv/dt from (T1):
    // F = (2/7) m (Omega k x v0 - g_plane). Without it the ball flies straight for the first
    // microseconds while the spring loads, which shifts the orbit by ~1e-4 of its radius.
    dem::prepare(world);
    const Vec3 gravityInPlane = world.gravity - dot(world.gravity, f.k) * f.k;
    const Vec3 friction = (2.0 / 7.0) * m * (s.omega * cross(f.k, v0) - gravityInPlane);
    world.wallHistory.spring[world.wallContacts.slotOf(0, 0)] =
        -friction / (ball.tangentialStiffnessRatio * s.stiffness);
    dem::prepare(world);
    return world;
}

/// Test 1b (turntable_t1.cpp): the pushed ball's set-up, and its orbit checked against theory
/// (rate 2/7 Omega, radius, centre) on the table `s` describes.
TurntableSetup orbitSetup();
CaseResult turntableOrbit(const CaseContext& context, const TurntableSetup& s);

} // namespace veridem::verify
