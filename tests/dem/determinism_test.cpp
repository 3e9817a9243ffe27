// Determinism across thread counts (STYLE 3.4, issue 5): the same input gives the same bits on
// 1 and 2 threads after 1000 steps. Forces are written per contact and summed per particle in a
// fixed order, so the schedule cannot change the order of any floating-point sum.
#include "dem/forces.h"
#include "dem/spatial_sort.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace veridem::dem
{
namespace
{

/// A jittered lattice of 13^3 = 2197 spheres (above kParallelThreshold, so two threads do split the loops) (r
/// = 1 mm) with random velocities and spins, packed tightly in a box with a floor, so that many contacts open
/// and close and slide within 1000 steps.
World jostlingBox(bool sorted)
{
    World world;
    Material m;
    m.name = "glass";
    m.normalStiffness = 1000;
    m.normalDampingRate = 5955.04;
    m.friction = 0.5;
    world.addMaterial(m);
    world.neighbors.skin = 0.5e-3;
    const int side = 13;
    const Real spacing = 2.05e-3, box = side * spacing;
    auto plane = [](Vec3 point, Vec3 normal)
    {
        Wall w;
        w.shape = PlaneShape{point, normal};
        return w;
    };
    world.walls = {plane({0, 0, 0}, {1, 0, 0}), plane({box, 0, 0}, {-1, 0, 0}), plane({0, 0, 0}, {0, 1, 0}),
                   plane({0, box, 0}, {0, -1, 0}), plane({0, 0, 0}, {0, 0, 1})};
    std::mt19937_64 random(42);
    std::uniform_real_distribution<Real> jitter(-0.04e-3, 0.04e-3), speed(-0.3, 0.3), spin(-300, 300);
    for (int z = 0; z < side; ++z)
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
            {
                const Vec3 centre{(x + 0.5) * spacing + jitter(random), (y + 0.5) * spacing + jitter(random),
                                  (z + 0.5) * spacing + jitter(random)};
                world.particles.add(centre, {speed(random), speed(random), speed(random)},
                                    {spin(random), spin(random), spin(random)}, 1e-3, 2500, 0);
            }
    if (sorted)
        sortParticlesSpatially(world);
    return world;
}

World runOn(int threads, int steps)
{
#ifdef _OPENMP
    const int previous = omp_get_max_threads();
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
    World world = jostlingBox(true);
    for (int s = 0; s < steps; ++s)
        step(world, 1e-5);
#ifdef _OPENMP
    omp_set_num_threads(previous);
#endif
    return world;
}

bool sameBits(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

TEST(Determinism, OneAndTwoThreadsGiveTheSameBitsAfter1000Steps)
{
    const World one = runOn(1, 1000);
    const World two = runOn(2, 1000);
    ASSERT_GT(one.neighbors.size(), 0u);
    EXPECT_GT(one.health.maxOverlapRatio, 0.0); // contacts are active at the end
    EXPECT_TRUE(sameBits(one.particles.position, two.particles.position));
    EXPECT_TRUE(sameBits(one.particles.velocity, two.particles.velocity));
    EXPECT_TRUE(sameBits(one.particles.angularVelocity, two.particles.angularVelocity));
    EXPECT_TRUE(sameBits(one.particles.force, two.particles.force));
    EXPECT_TRUE(sameBits(one.neighbors.tangentialSpring, two.neighbors.tangentialSpring));
    EXPECT_EQ(one.health.maxOverlapRatio, two.health.maxOverlapRatio);
    EXPECT_EQ(one.health.worstParticle, two.health.worstParticle);
}

/// The four-lane contact path (forces.cpp) performs the scalar contact law's operations lane by
/// lane: the state after 1000 steps is the same to the bit with it and without it.
TEST(Determinism, BatchedContactPathMatchesScalarPath)
{
    World batched = jostlingBox(true), scalar = jostlingBox(true);
    batched.batchedContactKernel = true;
    scalar.batchedContactKernel = false;
    for (int s = 0; s < 1000; ++s)
    {
        step(batched, 1e-5);
        step(scalar, 1e-5);
    }
    EXPECT_TRUE(sameBits(batched.particles.position, scalar.particles.position));
    EXPECT_TRUE(sameBits(batched.particles.velocity, scalar.particles.velocity));
    EXPECT_TRUE(sameBits(batched.particles.angularVelocity, scalar.particles.angularVelocity));
    EXPECT_TRUE(sameBits(batched.neighbors.tangentialSpring, scalar.neighbors.tangentialSpring));
    EXPECT_TRUE(sameBits(batched.neighbors.tangentialTorque, scalar.neighbors.tangentialTorque));
    EXPECT_TRUE(sameBits(batched.particles.torque, scalar.particles.torque));
    EXPECT_EQ(batched.health.maxOverlapRatio, scalar.health.maxOverlapRatio);
}

/// The gather sums each particle's slots in ascending slot order, pairs then walls: exactly the
/// order of a serial scatter loop over the slots (the pre-OpenMP force loop).
TEST(Determinism, GatherMatchesSerialScatterOrder)
{
    World world = jostlingBox(false);
    prepare(world);
    for (int s = 0; s < 50; ++s)
        step(world, 1e-5);
    std::vector<Vec3> force(world.particles.size()), torque(world.particles.size());
    const NeighborList& pairs = world.neighbors;
    for (std::size_t k = 0; k < pairs.size(); ++k)
    {
        force[pairs.first[k]] += pairs.force[k];
        force[pairs.second[k]] -= pairs.force[k];
        // The pre-OpenMP loop: torque_i += rolling - l_i (n x Ft), torque_j += -rolling - l_j (n x Ft).
        torque[pairs.first[k]] += Vec3{} - pairs.leverFirst[k] * pairs.tangentialTorque[k];
        torque[pairs.second[k]] += -Vec3{} - pairs.leverSecond[k] * pairs.tangentialTorque[k];
    }
    const WallContactList& walls = world.wallContacts;
    for (std::size_t k = 0; k < walls.size(); ++k)
    {
        force[walls.particle[k]] += walls.force[k];
        torque[walls.particle[k]] += walls.torque[k];
    }
    gatherContactForces(world);
    EXPECT_TRUE(sameBits(force, world.particles.force));
    EXPECT_TRUE(sameBits(torque, world.particles.torque));
}

} // namespace
} // namespace veridem::dem
