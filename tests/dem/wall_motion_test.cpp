// Prescribed wall motion tables (dem/walls/motion_table.h, moveWalls), active windows and wall
// loads (WallContactList::recordLoads, wallLoad) against closed forms.
#include "dem/integrate.h"
#include "dem/wall_contacts.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace veridem;
using namespace veridem::dem;

namespace
{
// v(t): x from 0 up to 2 m/s over [0.5, 1.5], held to 3 s, down to 0 at 4 s; z from 0 to -1 over [3, 4].
MotionTable table()
{
    return MotionTable({0.5, 1.5, 3, 4}, {{0, 0, 0}, {2, 0, 0}, {2, 0, 0}, {0, 0, -1}});
}

/// The exact integral of table() from 0 to t (x and z), piece by piece.
Vec3 exactIntegral(Real t)
{
    auto x = [](Real s)
    {
        if (s <= 0.5)
            return 0.0;
        if (s <= 1.5)
            return (s - 0.5) * (s - 0.5); // v = 2 (s - 0.5)
        if (s <= 3)
            return 1 + 2 * (s - 1.5);
        if (s <= 4)
            return 4 + 2 * (s - 3) - (s - 3) * (s - 3); // v = 2 - 2 (s - 3)
        return 5.0;
    };
    auto z = [](Real s)
    {
        if (s <= 3)
            return 0.0;
        if (s <= 4)
            return -0.5 * (s - 3) * (s - 3);
        return -0.5 - (s - 4);
    };
    return {x(t), 0, z(t)};
}

Material steel()
{
    Material m;
    m.name = "steel";
    m.density = 7800;
    m.normalStiffness = 2e5;
    m.restitution = 0.5;
    m.friction = 0.3;
    return m;
}

constexpr Real kRadius = 0.005, kDensity = 7800;
const Real kMass = kDensity * 4.0 / 3.0 * M_PI * kRadius * kRadius * kRadius;
} // namespace

TEST(WallMotion, TableValueAndIntegral)
{
    const MotionTable t = table();
    EXPECT_EQ(t.at(0).x, 0);  // held before the first point
    EXPECT_EQ(t.at(1).x, 1);  // linear between points
    EXPECT_EQ(t.at(9).z, -1); // held after the last
    for (const Real s : {0.0, 0.5, 1.0, 1.5, 2.2, 3.0, 3.5, 4.0, 6.0})
        EXPECT_NEAR(length(t.integralFromZero(s) - exactIntegral(s)), 0, 1e-14) << "t = " << s;
}

TEST(WallMotion, StepDisplacementIsTheExactIntegralAtTablePoints)
{
    // moveWalls sets the displacement to the table's integral at the wall's clock; the clock is a
    // sum of dt, so the error is |v| times its rounding (~1e-13 s after 5000 steps): 1e-12 m.
    std::vector<Wall> walls(1);
    walls[0].shape = PlaneShape{};
    walls[0].motion.velocityTable = table();
    const Real dt = 1e-3;
    for (int n = 1; n <= 5000; ++n)
    {
        moveWalls(walls, dt);
        if (n % 500 == 0)
        {
            EXPECT_NEAR(length(walls[0].displacement - exactIntegral(n * dt)), 0, 1e-12) << n;
        }
    }
    // The velocity is the table's at the half step (the last step ends at 5 s: held at [0, 0, -1]).
    EXPECT_EQ(walls[0].motion.velocity.z, -1);
}

TEST(WallMotion, BallFallsFreelyAfterTheGateSwitchesOff)
{
    World world;
    world.addMaterial(steel());
    world.gravity = {0, 0, -9.81};
    Wall gate;
    gate.name = "gate";
    gate.shape = PlaneShape{{0, 0, 0}, {0, 0, 1}};
    const Real tOff = 0.01, dt = 1e-5;
    gate.activeUntil = tOff;
    world.walls.push_back(gate);
    world.particles.add({0, 0, kRadius}, {}, {}, kRadius, kDensity, 0);
    prepare(world);
    // Start at the resting overlap m g / kn of the linear law.
    const Real rest = kMass * 9.81 / world.pairs(0, 0).kn;
    world.particles.position[0].z = kRadius - rest;
    prepare(world);
    Real z0 = 0;
    bool off = false;
    while (world.time < 0.06)
    {
        step(world, dt);
        if (!off && world.time >= tOff)
        {
            off = true;
            z0 = world.particles.position[0].z;
            EXPECT_EQ(world.wallContacts.size(), 0u); // the list was rebuilt without the gate
        }
        if (off)
        {
            // Velocity Verlet is exact under constant gravity; the switch is seen at the first
            // step at or after tOff, a time shift of at most dt: |dz| <= g (t - tOff) dt + g dt^2.
            const Real t = world.time - tOff, z = z0 - 0.5 * 9.81 * t * t;
            EXPECT_NEAR(world.particles.position[0].z, z, 9.81 * (t + dt) * dt) << "t = " << world.time;
        }
    }
    EXPECT_TRUE(off);
    EXPECT_LT(world.particles.position[0].z, -kRadius); // fell through where the gate was
}

TEST(WallMotion, LoadOfARestingBallIsItsWeight)
{
    // A ball at its resting overlap on a floor, alone (the one-particle step) and with a distant
    // free-falling twin (the general step): the wall carries -m g along z, and its torque about
    // the origin is -(x cross f) with f = m g z on the ball.
    for (const bool twin : {false, true})
    {
        World world;
        world.addMaterial(steel());
        Wall floor;
        floor.shape = PlaneShape{{0, 0, 0}, {0, 0, 1}};
        world.walls.push_back(floor);
        const Real x0 = 0.03, y0 = -0.02;
        world.particles.add({x0, y0, kRadius}, {}, {}, kRadius, kDensity, 0);
        if (twin)
            world.particles.add({5, 5, 5}, {}, {}, kRadius, kDensity, 0);
        prepare(world);
        world.particles.position[0].z = kRadius - kMass * 9.81 / world.pairs(0, 0).kn;
        prepare(world);
        world.wallContacts.setRecordLoads(true);
        for (int s = 0; s < 3000; ++s)
            step(world, 1e-5);
        const WallLoad load = wallLoad(world.wallContacts, 0, {0, 0, 0});
        const Real weight = kMass * 9.81;
        // At rest the spring force equals the weight. The first step starts from the force of the
        // first prepare() (before the ball was put at its resting overlap), so the ball rings; with
        // e = 0.5 the amplitude halves each half period (~0.5 ms): after 30 ms it is below 1e-12
        // of the overlap, and the damping force is zero at zero velocity. 1e-9 covers rounding.
        EXPECT_NEAR(load.force.z, -weight, 1e-9 * weight) << "twin " << twin;
        EXPECT_NEAR(load.force.x, 0, 1e-12 * weight);
        EXPECT_NEAR(load.torque.x, -y0 * weight, 1e-9 * weight * std::fabs(y0));
        EXPECT_NEAR(load.torque.y, x0 * weight, 1e-9 * weight * x0);
    }
}

TEST(WallMotion, DrumDrivesABallAndFeelsAResistingTorque)
{
    // A ball at the bottom of a drum turning about +x: friction drags it along the surface, so the
    // torque on the drum about its axis opposes the rotation (the drive torque -tx is positive).
    World world;
    world.addMaterial(steel());
    Wall drum;
    const Real R = 0.1;
    drum.shape = CylinderShape{{-0.05, 0, 0}, {1, 0, 0}, R, 0.1, true};
    drum.motion.angularVelocity = {2, 0, 0};
    drum.motion.rotationCentre = {-0.05, 0, 0};
    world.walls.push_back(drum);
    world.particles.add({0, 0, -R + kRadius}, {}, {}, kRadius, kDensity, 0);
    prepare(world);
    world.particles.position[0].z = -R + kRadius - kMass * 9.81 / world.pairs(0, 0).kn;
    prepare(world);
    world.wallContacts.setRecordLoads(true);
    for (int s = 0; s < 1000; ++s)
        step(world, 1e-5);
    const WallLoad load = wallLoad(world.wallContacts, 0, {-0.05, 0, 0});
    EXPECT_LT(load.torque.x, 0);
    // Only the tangential force has a moment about the axis, with a lever of at most R + r (the
    // contact point), and Coulomb bounds it: |tx| <= (R + r) mu N <= (R + r) mu |F|.
    EXPECT_LE(-load.torque.x, (R + kRadius) * 0.3 * length(load.force));
    // Still sliding after 0.01 s (the slip 0.2 m/s decays at 3.5 mu g ~ 10 m/s^2): |f_t| = mu N,
    // N = |F| / sqrt(1 + mu^2), lever R + overlap: -tx = R mu N to the overlap/R ~ 1e-5.
    EXPECT_NEAR(-load.torque.x, R * 0.3 * length(load.force) / std::sqrt(1 + 0.09),
                1e-4 * R * 0.3 * length(load.force));
    EXPECT_GT(world.particles.velocity[0].y, 0); // dragged along +y at the bottom (omega x r)
}
