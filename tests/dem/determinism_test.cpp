// Above 500 lines: every determinism check runs on the one jostling-box scene defined here.
// Determinism across thread counts (STYLE 3.4, issue 5): the same input gives the same bits on
// 1, 2 and 3 threads after 1000 steps. Forces are summed per particle in an order fixed by the
// particles' blocks and the slot order (neighbor_list.h), so the schedule cannot change the order
// of any floating-point sum.
#include "dem/forces.h"
#include "dem/integrate.h"
#include "dem/spatial_sort.h"
#include "dem/world.h"
#include "exec/isa.h"
#include "exec/thread_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace veridem::dem
{
namespace
{

/// A jittered lattice of side^3 (default 13^3 = 2197) spheres (above kParallelThreshold, so two threads do
/// split the loops) (r = 1 mm) with random velocities and spins, packed tightly in a box with a floor, so
/// that many contacts open and close and slide within 1000 steps.
World jostlingBox(bool sorted, int side = 13)
{
    World world;
    Material m;
    m.name = "glass";
    m.normalStiffness = 1000;
    m.normalDampingRate = 5955.04;
    m.friction = 0.5;
    world.addMaterial(m);
    world.neighbors.skin = 0.5e-3;
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

/// `adapt`: the threads' shares follow their measured speeds (the default), else the split is by
/// weight alone (reproducible). `speeds`: the speeds to start from (one per thread), if given.
World runOn(int threads, int steps, int side = 13, bool adapt = true, std::vector<double> speeds = {})
{
    const exec::ThreadCountOverride loops(threads);
    World world = jostlingBox(true, side);
    world.exec.pairSchedule.adapt = adapt;
    world.exec.passSchedule.adapt = adapt;
    world.exec.pairSchedule.speed = speeds;
    world.exec.passSchedule.speed = speeds;
    for (int s = 0; s < steps; ++s)
        step(world, 1e-5);
    return world;
}

template <class V> bool sameBits(const std::vector<V>& a, const std::vector<V>& b)
{
    // (memcmp of an empty vector's null data is undefined, even for zero bytes)
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(V)) == 0);
}

TEST(Determinism, OneTwoAndThreeThreadsGiveTheSameBitsAfter1000Steps)
{
    World one = runOn(1, 1000);
    ASSERT_GT(one.neighbors.size(), 0u);
    EXPECT_GT(one.health.maxOverlapRatio, 0.0); // contacts are active at the end
    for (const int threads : {2, 3})
    {
        World other = runOn(threads, 1000);
        EXPECT_TRUE(sameBits(one.particles.position, other.particles.position)) << threads;
        EXPECT_TRUE(sameBits(one.particles.velocity, other.particles.velocity)) << threads;
        EXPECT_TRUE(sameBits(one.particles.angularVelocity, other.particles.angularVelocity)) << threads;
        EXPECT_TRUE(sameBits(one.particles.force, other.particles.force)) << threads;
        EXPECT_EQ(one.neighbors.activeSlots, other.neighbors.activeSlots) << threads;
        EXPECT_TRUE(sameBits(one.pairHistory.spring, other.pairHistory.spring)) << threads; // history
        EXPECT_EQ(one.health.maxOverlapRatio, other.health.maxOverlapRatio) << threads;
        EXPECT_EQ(one.health.worstParticle, other.health.worstParticle) << threads;
    }
}

/// Blocks are independent (block_partition.h), so any split of them among threads gives the same
/// bits. A 17^3 box has five blocks (four of 1024 particles and one of 817): with the split by
/// weight alone, two threads split them 2 + 3, three threads 1 + 2 + 2; with the splits following
/// the threads' speeds, starting from speeds of 1 : 4, the split moves as the threads are timed
/// (300 steps: contacts open, close and slide by then).
TEST(Determinism, AnySplitOfTheBlocksGivesTheSameBits)
{
    constexpr int side = 17, steps = 300;
    World one = runOn(1, steps, side);
    World two = runOn(2, steps, side, false);
    World three = runOn(3, steps, side, false);
    World skewed = runOn(2, steps, side, true, {1e6, 4e6});
    ASSERT_EQ((one.particles.size() + NeighborList::kBlockParticles - 1) / NeighborList::kBlockParticles, 5u);
    ASSERT_EQ(two.exec.pairSchedule.runs.size(), 2u);
    ASSERT_EQ(three.exec.pairSchedule.runs.size(), 3u);
    EXPECT_NE(two.exec.pairSchedule.runs[0].end, three.exec.pairSchedule.runs[1].end) // different boundaries
        << two.exec.pairSchedule.runs[0].end << " " << three.exec.pairSchedule.runs[0].end << " "
        << three.exec.pairSchedule.runs[1].end;
    EXPECT_GT(one.health.touchingPairs, 0u);
    for (const World* w : {&two, &three, &skewed})
    {
        EXPECT_TRUE(sameBits(one.particles.position, w->particles.position));
        EXPECT_TRUE(sameBits(one.particles.velocity, w->particles.velocity));
        EXPECT_TRUE(sameBits(one.particles.angularVelocity, w->particles.angularVelocity));
        EXPECT_TRUE(sameBits(one.pairHistory.spring, w->pairHistory.spring));
        EXPECT_EQ(one.health.maxOverlapRatio, w->health.maxOverlapRatio);
        EXPECT_EQ(one.health.worstParticle, w->health.worstParticle);
        EXPECT_EQ(one.health.touchingPairs, w->health.touchingPairs);
    }
}

/// The lane contact path (pair_kernel.cpp, wall_forces.cpp) performs the scalar contact law's operations lane
/// by lane: the state after 1000 steps is the same to the bit with it and without it, for every
/// instruction-set variant this CPU runs.
TEST(Determinism, BatchedContactPathMatchesScalarPath)
{
    World scalar = jostlingBox(true);
    scalar.exec.batchedContactKernel = false;
    for (int s = 0; s < 1000; ++s)
        step(scalar, 1e-5);
    const std::string initial = exec::isaName();
    int variants = 0;
    for (const char* variant : {"avx2", "portable"})
    {
        if (!exec::selectIsa(variant))
            continue; // this CPU cannot run it
        ++variants;
        World batched = jostlingBox(true);
        batched.exec.batchedContactKernel = true;
        for (int s = 0; s < 1000; ++s)
            step(batched, 1e-5);
        EXPECT_TRUE(sameBits(batched.particles.position, scalar.particles.position)) << variant;
        EXPECT_TRUE(sameBits(batched.particles.velocity, scalar.particles.velocity)) << variant;
        EXPECT_TRUE(sameBits(batched.particles.angularVelocity, scalar.particles.angularVelocity)) << variant;
        EXPECT_EQ(batched.neighbors.activeSlots, scalar.neighbors.activeSlots) << variant;
        EXPECT_TRUE(sameBits(batched.pairHistory.spring, scalar.pairHistory.spring)) << variant;
        EXPECT_TRUE(sameBits(batched.particles.torque, scalar.particles.torque)) << variant;
        EXPECT_EQ(batched.health.maxOverlapRatio, scalar.health.maxOverlapRatio) << variant;
    }
    EXPECT_GE(variants, 1); // the portable variant runs everywhere
    ASSERT_TRUE(exec::selectIsa(initial));
}

/// advance() fuses each step's closing kick with the next step's kick-drift: the same operations,
/// so after any split into calls the state must be bit for bit that of as many step() calls, on
/// one thread and on two.
TEST(Determinism, AdvanceGivesTheBitsOfStepCalls)
{
    for (const int threads : {1, 2})
    {
        const exec::ThreadCountOverride loops(threads);
        World stepped = jostlingBox(true), advanced = jostlingBox(true); // (above kParallelThreshold)
        for (int s = 0; s < 300; ++s)
            step(stepped, 1e-5);
        EXPECT_EQ(advance(advanced, 1e-5, 137), 137u);
        EXPECT_EQ(advance(advanced, 1e-5, 1), 1u);
        EXPECT_EQ(advance(advanced, 1e-5, 162), 162u);
        EXPECT_EQ(advanced.stepCount, stepped.stepCount) << threads;
        EXPECT_EQ(advanced.time, stepped.time) << threads;
        EXPECT_TRUE(sameBits(advanced.particles.position, stepped.particles.position)) << threads;
        EXPECT_TRUE(sameBits(advanced.particles.velocity, stepped.particles.velocity)) << threads;
        EXPECT_TRUE(sameBits(advanced.particles.angularVelocity, stepped.particles.angularVelocity))
            << threads;
        EXPECT_TRUE(sameBits(advanced.pairHistory.spring, stepped.pairHistory.spring)) << threads;
        // The last step is not fused: the rows hold the step's sums, as after step().
        EXPECT_TRUE(sameBits(advanced.particles.force, stepped.particles.force)) << threads;
        EXPECT_TRUE(sameBits(advanced.particles.torque, stepped.particles.torque)) << threads;
        EXPECT_EQ(advanced.neighbors.rebuildCount(), stepped.neighbors.rebuildCount()) << threads;
        EXPECT_EQ(advanced.health.maxOverlapRatio, stepped.health.maxOverlapRatio) << threads;
    }
}

/// The jostling box made periodic in x and y (its four side walls taken away): pairs touch through
/// the faces, particles wrap, and the pairs move between the neighbour list and the periodic pairs
/// (dem/periodic.h). The same bits on one thread with step() and the scalar kernel as on two and
/// three threads with advance() and the lane kernel.
TEST(Determinism, APeriodicBoxGivesTheSameBitsOnOneTwoAndThreeThreads)
{
    const auto run = [](int threads, bool advanced)
    {
        const exec::ThreadCountOverride loops(threads);
        World world = jostlingBox(true);
        world.walls.erase(world.walls.begin(), world.walls.begin() + 4); // the floor stays
        const Real box = 13 * 2.05e-3;
        world.domain.min = {0, 0, 0};
        world.domain.max = {box, box, box};
        world.domain.periodic = {true, true, false};
        world.exec.batchedContactKernel = advanced;
        std::size_t throughFaces = 0;
        for (int s = 0; s < 10; ++s)
        {
            if (advanced)
                advance(world, 1e-5, 100);
            else
                for (int k = 0; k < 100; ++k)
                    step(world, 1e-5);
            for (const std::uint8_t formed : world.periodicPairs.history.formed)
                throughFaces += formed;
        }
        return std::pair{std::move(world), throughFaces};
    };
    const auto [one, throughFaces] = run(1, false);
    EXPECT_GT(throughFaces, 100u); // contacts through the faces took part
    for (const int threads : {2, 3})
    {
        const auto [other, faces] = run(threads, true);
        EXPECT_EQ(faces, throughFaces) << threads;
        EXPECT_TRUE(sameBits(one.particles.position, other.particles.position)) << threads;
        EXPECT_TRUE(sameBits(one.particles.velocity, other.particles.velocity)) << threads;
        EXPECT_TRUE(sameBits(one.particles.angularVelocity, other.particles.angularVelocity)) << threads;
        EXPECT_TRUE(sameBits(one.particles.force, other.particles.force)) << threads;
        EXPECT_TRUE(sameBits(one.particles.torque, other.particles.torque)) << threads;
        EXPECT_TRUE(sameBits(one.pairHistory.spring, other.pairHistory.spring)) << threads;
        EXPECT_EQ(one.periodicPairs.first, other.periodicPairs.first) << threads;
        EXPECT_EQ(one.periodicPairs.second, other.periodicPairs.second) << threads;
        EXPECT_TRUE(sameBits(one.periodicPairs.history.spring, other.periodicPairs.history.spring))
            << threads;
        EXPECT_EQ(one.health.maxOverlapRatio, other.health.maxOverlapRatio) << threads;
        EXPECT_EQ(one.health.touchingPairs, other.health.touchingPairs) << threads;
    }
}

/// advance() stops after the first step whose state is not finite, or whose overlap exceeds the
/// limit, and says how many steps it did.
TEST(Determinism, AdvanceStopsAfterABadStep)
{
    World blowUp = jostlingBox(true, 10);
    blowUp.particles.velocity[7].x = std::numeric_limits<Real>::quiet_NaN();
    EXPECT_EQ(advance(blowUp, 1e-5, 50), 1u);
    EXPECT_FALSE(blowUp.health.finite);
    EXPECT_EQ(blowUp.health.firstNonFinite, 7u);

    World packed = jostlingBox(true, 10); // overlaps of order 1e-3 of the radius within a few steps
    const std::uint64_t done = advance(packed, 1e-5, 200, 1e-9);
    EXPECT_LT(done, 200u);
    EXPECT_GT(packed.health.maxOverlapRatio, 1e-9);
}

/// The plane-wall pass of the lane path (wall_forces.cpp, planeWallForcesBody) takes each wall's part of
/// the gap and surface velocity from a frame made once per call: on a floor that is a finite disk,
/// rotating about its normal and translating, with particles on and off the disk, it must still
/// give the scalar path's bits (jostlingBox's walls are infinite and at rest).
TEST(Determinism, PlaneWallPassMatchesScalarPathOnAMovingDisk)
{
    const auto movingDisk = [](bool batched)
    {
        World world = jostlingBox(true, 10);
        const Real box = 10 * 2.05e-3;
        Wall& floor = world.walls.back();
        floor.shape = PlaneShape{{0.5 * box, 0.5 * box, 0}, {0, 0, 1}, 0.45 * box}; // corners off the disk
        floor.motion.velocity = {0.02, -0.01, 0};
        floor.motion.angularVelocity = {0, 0, 40};
        floor.motion.rotationCentre = {0.5 * box, 0.5 * box, 0};
        world.exec.batchedContactKernel = batched;
        for (int s = 0; s < 500; ++s)
            step(world, 1e-5);
        return world;
    };
    const World scalar = movingDisk(false);
    EXPECT_GT(scalar.health.touchingWalls, 0u);
    const std::string initial = exec::isaName();
    for (const char* variant : {"avx2", "portable"})
    {
        if (!exec::selectIsa(variant))
            continue; // this CPU cannot run it
        const World batched = movingDisk(true);
        EXPECT_TRUE(sameBits(batched.particles.position, scalar.particles.position)) << variant;
        EXPECT_TRUE(sameBits(batched.particles.velocity, scalar.particles.velocity)) << variant;
        EXPECT_TRUE(sameBits(batched.particles.angularVelocity, scalar.particles.angularVelocity)) << variant;
        EXPECT_TRUE(sameBits(batched.wallHistory.spring, scalar.wallHistory.spring)) << variant;
        EXPECT_EQ(batched.health.touchingWalls, scalar.health.touchingWalls) << variant;
        EXPECT_EQ(batched.health.maxOverlapRatio, scalar.health.maxOverlapRatio) << variant;
    }
    ASSERT_TRUE(exec::selectIsa(initial));
}

/// The jostling box (10^3) on a meshed floor instead of the plane: a shallow valley along y (two
/// planes of slope 0.005 meeting at x = box/2, two triangles per 1 mm cell): candidates away from
/// the valley's line are flat (one slot, mesh wall's plane path), those near it are general
/// (kMeshSlots slots, the matching), and balls cross between the two as they jostle.
World jostlingBoxOnAMeshValley(bool batched)
{
    World world = jostlingBox(true, 10);
    const Real box = 10 * 2.05e-3, cell = 1e-3, slope = 0.005;
    const int cells = static_cast<int>(box / cell) + 3;
    const auto at = [&](int i, int j)
    {
        const Real x = -cell + i * cell;
        return Vec3{x, -cell + j * cell, slope * std::fabs(x - 0.5 * box) - slope * 0.5 * box};
    };
    std::vector<Vec3> corners;
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i)
            corners.insert(corners.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                           at(i + 1, j + 1), at(i, j + 1)});
    MeshReport report; // (an open boundary: expected for a floor)
    MeshShape shape;
    shape.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(corners, "valley", report));
    shape.farthestVertex = shape.mesh->farthestVertex(shape.pivot);
    world.walls.back().shape = std::move(shape);
    world.exec.batchedContactKernel = batched;
    return world;
}

TEST(Determinism, AMeshFloorWithFlatAndGeneralCandidatesGivesTheSameBitsOnAnyThreadsAndPath)
{
    const auto run = [](int threads, bool batched)
    {
        const exec::ThreadCountOverride loops(threads);
        World world = jostlingBoxOnAMeshValley(batched);
        for (int s = 0; s < 500; ++s)
            step(world, 1e-5);
        return world;
    };
    const World one = run(1, true);
    std::size_t flat = 0, general = 0;
    for (std::size_t k = 0; k < one.wallContacts.size(); ++k)
        if (one.wallContacts.wall[k] == one.walls.size() - 1)
            ++(one.wallContacts.meshFlat[k] != WallContactList::kNotFlat ? flat : general);
    EXPECT_GT(flat, 0u);
    EXPECT_GT(general, 0u);
    EXPECT_GT(one.health.touchingWalls, 0u);
    const std::string initial = exec::isaName();
    std::vector<World> others;
    others.push_back(run(2, true));
    others.push_back(run(3, true));
    others.push_back(run(1, false));
    if (exec::selectIsa("portable"))
        others.push_back(run(2, true));
    ASSERT_TRUE(exec::selectIsa(initial));
    for (const World& other : others)
    {
        EXPECT_TRUE(sameBits(one.particles.position, other.particles.position));
        EXPECT_TRUE(sameBits(one.particles.velocity, other.particles.velocity));
        EXPECT_TRUE(sameBits(one.particles.angularVelocity, other.particles.angularVelocity));
        EXPECT_TRUE(sameBits(one.wallHistory.spring, other.wallHistory.spring));
        EXPECT_TRUE(sameBits(one.wallContacts.meshNormal, other.wallContacts.meshNormal));
        EXPECT_EQ(one.health.touchingWalls, other.health.touchingWalls);
        EXPECT_EQ(one.health.maxOverlapRatio, other.health.maxOverlapRatio);
    }
}

/// Random particle state for the integration loops: n particles with velocities, spins, forces
/// and torques of mixed signs and magnitudes.
ParticleStore randomParticles(std::size_t n, std::mt19937& rng)
{
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    const auto vec = [&](Real scale) { return Vec3{scale * u(rng), scale * u(rng), scale * u(rng)}; };
    ParticleStore p;
    for (std::size_t i = 0; i < n; ++i)
    {
        p.add(vec(0.05), vec(0.3), vec(200.0), 1e-3 * (1.0 + 0.5 * u(rng)), 2500, 0);
        p.force.back() = vec(1e-3);
        p.torque.back() = vec(1e-7);
    }
    return p;
}

/// The AVX2 integration loops (integrate.cpp) perform the scalar loops' operations: the same
/// bits for every particle, including ranges that do not start or end on a group of four, the
/// same largest displacements for the neighbour list's motion check, and the same verdict on a
/// non-finite state.
TEST(Determinism, IntegrationLanesMatchScalarLoops)
{
    const std::string variant = exec::isaName();
    if (!exec::selectIsa("avx2")) // (only to ask whether this CPU runs AVX2)
        GTEST_SKIP() << "this CPU has no AVX2";
    ASSERT_TRUE(exec::selectIsa(variant));
    std::mt19937 rng(7);
    const std::size_t n = 23, begin = 3, end = 22; // 19 particles: four groups and 3 left over
    const ParticleStore initial = randomParticles(n, rng);
    std::vector<Vec3> built = initial.position, activeBuilt = initial.position;
    std::uniform_real_distribution<Real> offset(-1e-4, 1e-4); // components of similar size
    for (std::size_t i = 0; i < n; ++i)
    {
        built[i] += Vec3{offset(rng), offset(rng), offset(rng)};
        activeBuilt[i] += Vec3{offset(rng), offset(rng), offset(rng)};
    }
    const NeighborList::MotionReference reference{built.data(), activeBuilt.data()};
    const Vec3 gravity{0.3, -0.2, -9.81};
    const Real dt = 1e-5;

    ParticleStore scalar = initial, lanes = initial;
    const Motion scalarMotion = kickDriftRange(scalar, gravity, dt, reference, begin, end, Motion{});
    const Motion lanesMotion = kickDriftLanes(lanes, gravity, dt, reference, begin, end);
    EXPECT_TRUE(sameBits(lanes.position, scalar.position));
    EXPECT_TRUE(sameBits(lanes.velocity, scalar.velocity));
    EXPECT_TRUE(sameBits(lanes.angularVelocity, scalar.angularVelocity));
    EXPECT_EQ(lanesMotion.sinceBuild2, scalarMotion.sinceBuild2);
    EXPECT_EQ(lanesMotion.sinceActiveBuild2, scalarMotion.sinceActiveBuild2);
    EXPECT_GT(scalarMotion.sinceBuild2, 0.0);

    // Both rewrite the (x, y, z, r) rows of the particles they moved, and only those.
    EXPECT_TRUE(sameBits(lanes.positionRadius, scalar.positionRadius));
    for (std::size_t i = 0; i < n; ++i)
    {
        EXPECT_EQ(lanes.positionRadius[i], lanes.position[i]) << i; // (x, y, z)
        EXPECT_EQ(lanes.positionRadius[i].pad, lanes.radius[i]) << i;
    }

    EXPECT_TRUE(kickRange(scalar, gravity, dt, begin, end));
    EXPECT_TRUE(kickLanes(lanes, gravity, dt, begin, end));
    EXPECT_TRUE(sameBits(lanes.velocity, scalar.velocity));
    EXPECT_TRUE(sameBits(lanes.angularVelocity, scalar.angularVelocity));

    // The fused closing kick and next kick-drift (advance()): the bits of the two loops in turn.
    ParticleStore fused = lanes;
    Motion fusedMotion, twoLoopsMotion;
    EXPECT_TRUE(kickThenKickDriftLanes(fused, gravity, dt, reference, begin, end, fusedMotion));
    EXPECT_TRUE(kickThenKickDriftRange(lanes, gravity, dt, reference, begin, end, twoLoopsMotion));
    EXPECT_TRUE(sameBits(fused.position, lanes.position));
    EXPECT_TRUE(sameBits(fused.velocity, lanes.velocity));
    EXPECT_TRUE(sameBits(fused.angularVelocity, lanes.angularVelocity));
    EXPECT_TRUE(sameBits(fused.positionRadius, lanes.positionRadius));
    EXPECT_EQ(fusedMotion.sinceBuild2, twoLoopsMotion.sinceBuild2);
    EXPECT_EQ(fusedMotion.sinceActiveBuild2, twoLoopsMotion.sinceActiveBuild2);

    // A non-finite component, inside a group of four and in the part left over.
    for (const std::size_t bad : {std::size_t{9}, std::size_t{20}})
    {
        ParticleStore a = initial, b = initial;
        a.torque[bad].y = b.torque[bad].y = std::numeric_limits<Real>::infinity();
        EXPECT_FALSE(kickRange(a, gravity, dt, begin, end)) << bad;
        EXPECT_FALSE(kickLanes(b, gravity, dt, begin, end)) << bad;
    }
}

/// The block sums (forces.cpp, exec/cross_block_sums.cpp) add every touching contact exactly once, +F on i
/// and -F on j, with the torques -l_i (n x Ft) and -l_j (n x Ft): they equal a plain serial loop over the
/// slots that calls the contact law on a copy of each slot's history. Only the order of the sums and the
/// rounding of 1/d differ, so the tolerance is round-off: 1e-12 of the largest force (torque) in
/// the box (a sum of ~10 terms of double precision, relative error ~1e-15 each).
TEST(Determinism, BlockSumsEqualAPlainSerialLoopOverSlots)
{
    World world = jostlingBox(false);
    prepare(world);
    for (int s = 0; s < 50; ++s)
        step(world, 1e-5);
    const Real dt = 1e-5;
    World reference = world;
    computeForces(world, dt); // stages 3 and 4

    // Reference: walls alone through computeWallForces, then the pairs in a plain loop.
    ParticleStore& p = reference.particles;
    std::fill(p.force.begin(), p.force.end(), Vec3{});
    std::fill(p.torque.begin(), p.torque.end(), Vec3{});
    computeWallForces(reference, dt, 0, p.size());
    const NeighborList& list = reference.neighbors;
    std::size_t touching = 0;
    for (std::size_t k = 0; k < list.size(); ++k)
    {
        const std::uint32_t i = list.first[k], j = list.second[k];
        const Vec3 separation = p.position[i] - p.position[j];
        const Real distance = length(separation), sum = p.radius[i] + p.radius[j];
        if (distance >= sum)
            continue;
        ++touching;
        ContactInput in;
        in.normal = separation / distance;
        in.overlap = sum - distance;
        const Real leverI = p.radius[i] * distance / sum, leverJ = p.radius[j] * distance / sum;
        in.relativeVelocity = p.velocity[i] - p.velocity[j] -
                              cross(leverI * p.angularVelocity[i] + leverJ * p.angularVelocity[j], in.normal);
        in.relativeAngularVelocity = p.angularVelocity[i] - p.angularVelocity[j];
        in.effectiveMass = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
        const std::size_t candidate = list.candidateOfSlot(k);
        ContactHistory history =
            candidate == NeighborList::kNotCandidate ? ContactHistory{} : reference.pairHistory.at(candidate);
        const ContactOutput out = evaluateContact(reference.pairs(0, 0), in, history, dt);
        const Vec3 tt = cross(in.normal, out.tangentialForce);
        p.force[i] += out.force;
        p.force[j] -= out.force;
        p.torque[i] -= leverI * tt;
        p.torque[j] -= leverJ * tt;
    }
    ASSERT_GT(touching, 1000u);
    EXPECT_EQ(world.health.touchingPairs, touching);
    ASSERT_GT(world.neighbors.deferred.size(), 0u); // the box spans several blocks
    Real maxForce = 0, maxTorque = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        maxForce = std::max(maxForce, length(p.force[i]));
        maxTorque = std::max(maxTorque, length(p.torque[i]));
    }
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        ASSERT_LE(length(world.particles.force[i] - p.force[i]), 1e-12 * maxForce) << "particle " << i;
        ASSERT_LE(length(world.particles.torque[i] - p.torque[i]), 1e-12 * maxTorque) << "particle " << i;
    }
}

} // namespace
} // namespace veridem::dem

namespace veridem::dem
{
namespace
{

/// The jostling box with the given materials, particle i of material i % count, a floor disk that
/// moves and turns (the plane-wall pass) and, if `dish`, a concave dish below it (the general wall
/// pass: not every wall is a plane).
World modelBox(const std::vector<Material>& materials, bool dish)
{
    World world = jostlingBox(true, 10);
    world.materials.clear();
    for (const Material& m : materials)
        world.addMaterial(m);
    for (std::size_t i = 0; i < world.particles.size(); ++i)
        world.particles.material[i] = static_cast<std::uint32_t>(i % materials.size());
    const Real box = 10 * 2.05e-3;
    Wall& floor = world.walls.back();
    floor.shape = PlaneShape{{0.5 * box, 0.5 * box, 0}, {0, 0, 1}, 0.45 * box};
    floor.motion.velocity = {0.02, -0.01, 0};
    floor.motion.angularVelocity = {0, 0, 40};
    floor.motion.rotationCentre = {0.5 * box, 0.5 * box, 0};
    if (dish)
    {
        Wall bowl;
        bowl.shape = DishShape{{0.5 * box, 0.5 * box, -0.02e-3}, 0.3}; // below the floor's centre
        world.walls.push_back(bowl);
    }
    for (Wall& wall : world.walls) // (the last material: see EveryModelInLanesMatchesScalarPath)
        wall.material = static_cast<std::uint32_t>(materials.size() - 1);
    return world;
}

Material modelMaterial(const std::string& name, NormalModel normal, RollingModel rolling,
                       Real surfaceEnergy = 0)
{
    Material m;
    m.name = name;
    m.normalStiffness = 1000;
    m.restitution = 0.6; // damping from restitution (not a damping rate)
    m.friction = 0.4;
    m.normalModel = normal;
    if (isHertzian(normal))
    {
        m.youngsModulus = 1e7;
        m.poissonRatio = 0.3;
        // [J/m^2] (JKR, DMT). 1 J/m^2 makes |delta_c| ~ 6 um, more than a step's travel at the box's
        // speeds, so separating JKR contacts pass through the formed, pulling state.
        m.surfaceEnergy = surfaceEnergy;
    }
    m.rollingModel = rolling;
    if (rolling == RollingModel::ConstantTorque || rolling == RollingModel::ConstantTorqueAbsolute)
        m.rollingFrictionLength = 5e-5;
    else if (rolling == RollingModel::Epsd)
        m.rollingFrictionDimensionless = 0.05;
    else if (rolling == RollingModel::Viscous)
        m.rollingViscousCoefficient = 2; // stable: c Fn R^2 dt / I << 1
    return m;
}

/// Every contact model in the lane path gives the bits of the scalar path (the law written once,
/// contact_law.h), for pairs and walls, plane and general, one material or several mixed in one
/// batch (per-lane parameters and models), on every instruction-set variant.
TEST(Determinism, EveryModelInLanesMatchesScalarPath)
{
    using N = NormalModel;
    using R = RollingModel;
    const std::vector<std::vector<Material>> cases = {
        {modelMaterial("linear", N::Linear, R::None)},
        {modelMaterial("hertz", N::Hertz, R::None)},
        {modelMaterial("linearA", N::Linear, R::ConstantTorque)},
        {modelMaterial("hertzEpsd", N::Hertz, R::Epsd)},
        {modelMaterial("viscous", N::Linear, R::Viscous)},
        {modelMaterial("absolute", N::Hertz, R::ConstantTorqueAbsolute)},
        {modelMaterial("a", N::Linear, R::None), modelMaterial("b", N::Linear, R::Epsd),
         modelMaterial("c", N::Linear, R::ConstantTorque), modelMaterial("d", N::Linear, R::Viscous),
         modelMaterial("e", N::Linear, R::ConstantTorqueAbsolute)},
        {modelMaterial("f", N::Hertz, R::None), modelMaterial("g", N::Hertz, R::Epsd),
         modelMaterial("h", N::Hertz, R::Viscous)},
        // Adhesion. The last material is the floor's: a JKR wall must not pull (no formed state
        // is kept for wall contacts), so its surface energy is 0 there; DMT walls pull.
        {modelMaterial("jkrA", N::Jkr, R::ConstantTorque, 1.0), modelMaterial("jkrWall", N::Jkr, R::None)},
        {modelMaterial("jkr", N::Jkr, R::None, 1.0), modelMaterial("jkrEpsd", N::Jkr, R::Epsd, 0.5),
         modelMaterial("jkrWall", N::Jkr, R::Viscous)},
        {modelMaterial("dmtEpsd", N::Dmt, R::Epsd, 1.0), modelMaterial("dmt", N::Dmt, R::None, 1.0)}};
    const std::string initial = exec::isaName();
    for (std::size_t c = 0; c < cases.size(); ++c)
        for (bool dish : {false, true})
        {
            const auto run = [&](bool batched)
            {
                World world = modelBox(cases[c], dish);
                world.exec.batchedContactKernel = batched;
                for (int s = 0; s < 300; ++s)
                    step(world, 1e-5);
                return world;
            };
            const World scalar = run(false);
            ASSERT_GT(scalar.health.touchingPairs, 0u);
            ASSERT_GT(scalar.health.touchingWalls, 0u);
            ASSERT_TRUE(scalar.health.finite)
                << c; // a comparison of bits is meaningful only for finite states
            for (const char* variant : {"avx2", "portable"})
            {
                if (!exec::selectIsa(variant))
                    continue; // this CPU cannot run it
                const World batched = run(true);
                const std::string what = "case " + std::to_string(c) + (dish ? " with dish " : " ") + variant;
                EXPECT_TRUE(sameBits(batched.particles.position, scalar.particles.position)) << what;
                EXPECT_TRUE(sameBits(batched.particles.velocity, scalar.particles.velocity)) << what;
                EXPECT_TRUE(sameBits(batched.particles.angularVelocity, scalar.particles.angularVelocity))
                    << what;
                EXPECT_TRUE(sameBits(batched.pairHistory.spring, scalar.pairHistory.spring)) << what;
                EXPECT_TRUE(sameBits(batched.pairHistory.rolling, scalar.pairHistory.rolling)) << what;
                EXPECT_TRUE(sameBits(batched.pairHistory.formed, scalar.pairHistory.formed))
                    << what; // (the JKR formed states)
                EXPECT_TRUE(sameBits(batched.wallHistory.spring, scalar.wallHistory.spring)) << what;
                EXPECT_TRUE(sameBits(batched.wallHistory.rolling, scalar.wallHistory.rolling)) << what;
                EXPECT_EQ(batched.health.maxOverlapRatio, scalar.health.maxOverlapRatio) << what;
            }
        }
    ASSERT_TRUE(exec::selectIsa(initial));
}

} // namespace
} // namespace veridem::dem
