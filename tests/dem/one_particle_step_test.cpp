// The one-particle step (world.cpp, stepOneParticle) keeps a single ball's state in registers
// between the stages; it must give the bits of the general step. The general step runs here on the
// same ball with a distant twin added (two particles take the general path; the twin never comes
// near the ball or a wall, so it adds nothing to the ball's sums), and the ball's state, forces,
// contact history and health are compared bit for bit after thousands of steps.
#include "dem/forces.h"
#include "dem/world.h"
#include "exec/isa.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

namespace veridem::dem
{
namespace
{

bool sameBits(const Vec3& a, const Vec3& b)
{
    return std::memcmp(&a, &b, sizeof(Vec3)) == 0;
}

struct Scene
{
    Material material;
    Wall wall;
    Vec3 position, velocity, angularVelocity; // of the ball [m, m/s, rad/s]
    Real radius = 0.005;                      // [m]
    Real skin = 0;                            // neighbour skin [m]; 0: the default
};

World build(const Scene& scene, bool withTwin)
{
    World world;
    world.addMaterial(scene.material);
    world.walls.push_back(scene.wall);
    world.neighbors.skin = scene.skin;
    world.particles.add(scene.position, scene.velocity, scene.angularVelocity, scene.radius, 7800, 0);
    if (withTwin) // far above everything, falling freely
        world.particles.add({50, 50, 50}, {}, {}, scene.radius, 7800, 0);
    return world;
}

/// Runs the scene alone and with the twin; expects the ball's bits to agree at every checkpoint,
/// and the ball to have touched the wall in at least `minTouchingSteps` steps (so that the
/// contact law, not only free flight, was compared).
void expectSameBitsWithKernel(const Scene& scene, int steps, Real dt, int minTouchingSteps,
                              const std::string& what)
{
    World alone = build(scene, false), paired = build(scene, true);
    int touchingSteps = 0;
    for (int s = 1; s <= steps; ++s)
    {
        step(alone, dt);
        step(paired, dt);
        touchingSteps += alone.health.touchingWalls > 0;
        if (s % 500 != 0 && s != steps)
            continue;
        const ParticleStore &a = alone.particles, &b = paired.particles;
        ASSERT_TRUE(sameBits(a.position[0], b.position[0])) << what << ", step " << s;
        ASSERT_TRUE(sameBits(a.velocity[0], b.velocity[0])) << what << ", step " << s;
        ASSERT_TRUE(sameBits(a.angularVelocity[0], b.angularVelocity[0])) << what << ", step " << s;
        ASSERT_TRUE(sameBits(a.force[0], b.force[0])) << what << ", step " << s;
        ASSERT_TRUE(sameBits(a.torque[0], b.torque[0])) << what << ", step " << s;
        ASSERT_EQ(alone.health.touchingWalls, paired.health.touchingWalls) << what << ", step " << s;
        ASSERT_EQ(alone.health.maxOverlapRatio, paired.health.maxOverlapRatio) << what << ", step " << s;
        ASSERT_EQ(alone.health.finite, paired.health.finite) << what << ", step " << s;
        // The ball's wall slots come first in both lists (particle 0).
        const WallContactList &la = alone.wallContacts, &lb = paired.wallContacts;
        ASSERT_EQ(la.start[1], lb.start[1]) << what << ", step " << s;
        for (std::uint32_t k = 0; k < la.start[1]; ++k)
            ASSERT_TRUE(sameBits(alone.wallHistory.spring[k], paired.wallHistory.spring[k]))
                << what << ", step " << s;
    }
    EXPECT_GE(touchingSteps, minTouchingSteps) << what;
    EXPECT_EQ(alone.stepCount, paired.stepCount);
    EXPECT_EQ(alone.time, paired.time);
}

/// expectSameBitsWithKernel for each instruction-set variant this CPU runs: the one-particle step
/// is compiled in two (world.cpp: portable, and AVX2 encodings when the lane kernel is "avx2").
void expectSameBits(const Scene& scene, int steps, Real dt, int minTouchingSteps, const std::string& what)
{
    const std::string initial = exec::isaName();
    for (const char* variant : {"avx2", "portable"})
        if (exec::selectIsa(variant)) // (false: this CPU cannot run it)
            expectSameBitsWithKernel(scene, steps, dt, minTouchingSteps, what + ", " + variant + " variant");
    ASSERT_TRUE(exec::selectIsa(initial));
}

Material steel()
{
    Material m;
    m.name = "steel";
    m.normalStiffness = 2e5;
    m.restitution = 0.6;
    m.friction = 0.3;
    return m;
}

Wall turntable(Vec3 normal, Real spin)
{
    Wall w;
    w.name = "table";
    w.shape = PlaneShape{{0, 0, 0}, normal, 0.3};
    w.motion.angularVelocity = spin * normal;
    return w;
}

TEST(OneParticleStep, RollingOnATurntableWithTypeARollingFriction)
{
    Scene s;
    s.material = steel();
    s.material.rollingModel = RollingModel::ConstantTorque;
    s.material.rollingFrictionLength = 2e-5;
    s.wall = turntable({0, 0, 1}, 10);
    s.position = {-0.04, 0, s.radius - 1e-6};
    s.velocity = {0, -0.1, 0};
    expectSameBits(s, 6000, 1e-5, 5000, "flat turntable, type A");
}

TEST(OneParticleStep, SlidingDownATiltedTableWithEpsdRollingFriction)
{
    Scene s;
    s.material = steel();
    s.material.rollingModel = RollingModel::Epsd;
    s.material.rollingFrictionDimensionless = 0.02;
    s.wall = turntable(tiltedNormal(0.2, 0.3), 5);
    const Vec3 n = tiltedNormal(0.2, 0.3), q{0.02, 0.01, 0};
    s.position = q - dot(q, n) * n + (s.radius - 1e-6) * n; // resting on the table
    s.angularVelocity = {0, 0, 40};
    expectSameBits(s, 6000, 1e-5, 1000, "tilted table, EPSD");
}

TEST(OneParticleStep, InARotatingDishWithHertzContact)
{
    Scene s;
    s.material = steel();
    s.material.normalModel = NormalModel::Hertz;
    s.material.youngsModulus = 2e11;
    s.material.poissonRatio = 0.3;
    s.material.rollingModel = RollingModel::ConstantTorque;
    s.material.rollingFrictionDimensionless = 0.01;
    s.wall.name = "dish";
    s.wall.shape = DishShape{{0, 0, 0}, 0.5};
    s.wall.motion.angularVelocity = {0, 0, 3};
    const Vec3 centre{0, 0, 0.5}, surface{0.1, 0, 0.5 - std::sqrt(0.25 - 0.01)};
    s.position = centre + (0.5 - s.radius) / 0.5 * (surface - centre); // touching the dish
    s.velocity = {0, 0.3, 0};
    expectSameBits(s, 6000, 1e-6, 5000, "rotating dish, Hertz");
}

TEST(OneParticleStep, BouncingWithTheLaneLawAndListRebuilds)
{
    // Linear law without rolling friction: the general step evaluates the wall contact in lanes
    // (forces.cpp), the one-particle step in the scalar law: the same bits by construction
    // (Determinism.BatchedContactPathMatchesScalarPath). A small skin rebuilds the wall list at
    // each bounce, so its history merge is exercised as well.
    Scene s;
    s.material = steel();
    s.wall = turntable({0, 0, 1}, 0);
    s.position = {0, 0, 0.02};
    s.velocity = {0.2, 0, 0};
    s.angularVelocity = {0, 30, 0};
    s.skin = 1e-4;
    expectSameBits(s, 20000, 1e-5, 100, "bouncing, lane law");
}

} // namespace
} // namespace veridem::dem
