// Removal by retirement (dem/particle_changes.h): a particle retired in contact leaves its partner
// moving as if alone (velocity Verlet in free fall, against the formula), exerts and feels nothing,
// never triggers a rebuild; the next rebuild takes it out of the store, after which the pair and
// wall candidates are exactly the brute-force ones and the counts, ids and mass exclude it; the
// bits are the same on one and two threads; an event that retires costs no rebuild.
#include "dem/particle_changes.h"
#include "dem/particle_flow.h"
#include "dem/world.h"
#include "exec/thread_pool.h"
#include "flow_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <utility>

using namespace veridem;
using namespace veridem::dem;
using namespace veridem::dem::flow_test;

namespace
{

/// An outlet taking the particles whose centre is above the plane z = height [m].
Outlet above(Real height)
{
    Outlet o;
    o.name = "top";
    o.region.kind = FlowRegion::Kind::HalfSpace;
    o.region.point = {0, 0, height};
    o.region.normal = {0, 0, 1};
    return o;
}

std::size_t retiredCount(const World& world)
{
    std::size_t n = 0;
    for (std::size_t i = 0; i < world.particles.size(); ++i)
        n += world.particles.retired(i) ? 1 : 0;
    return n;
}

} // namespace

// A (index 0) rests pressed into the floor and sheared against B (index 1), which hangs beside it
// above the floor: after 20 steps both contacts of A carry a normal and a tangential force. A is
// retired. From then on B must move as a free sphere under gravity from the state it had: velocity
// Verlet with the force F0 and torque T0 of the last step in the first half kick and none after
// gives, after n steps of dt,
//   v_n = v_0 + dt/2 F0/m + n dt g,   x_n = x_0 + n dt (v_0 + dt/2 F0/m) + g (n dt)^2 / 2,
//   w_n = w_0 + dt/2 T0/I.
TEST(Removal, RetiredMidSlideItsPartnerMovesAsIfAlone)
{
    World world = emptyBox(); // (a floor at z = 0; skin 0.3 mm)
    world.particles.add({0, 0, 0.99e-3}, {0, -0.02, 0}, {0, 0, 5}, 1e-3, 2500, 0);       // A: in the floor
    world.particles.add({1.98e-3, 0, 1.09e-3}, {0, 0.02, 0}, {0, 0, -5}, 1e-3, 2500, 0); // B: touches A
    prepare(world);
    const Real dt = 1e-6;
    for (int s = 0; s < 20; ++s)
        step(world, dt);
    ASSERT_EQ(world.health.touchingPairs, 1u);
    ASSERT_EQ(world.health.touchingWalls, 1u); // (A's; B is 0.09 mm above the floor)
    ASSERT_GT(length(world.pairHistory.spring[0]), 0);

    ParticleFlow flow;
    Outlet aroundA; // (a box around A's centre only)
    aroundA.region.kind = FlowRegion::Kind::Box;
    aroundA.region.min = {-0.5e-3, -0.5e-3, 0};
    aroundA.region.max = {0.5e-3, 0.5e-3, 1.5e-3};
    flow.outlets.push_back(aroundA);
    const std::size_t rebuilds = world.neighbors.rebuildCount();
    ASSERT_TRUE(flow.apply(world, dt));
    ASSERT_EQ(flow.outlets[0].count, 1u);
    ASSERT_EQ(world.particles.size(), 2u); // still in the store ...
    ASSERT_TRUE(world.particles.retired(0));
    ASSERT_FALSE(world.particles.retired(1));
    EXPECT_EQ(world.neighbors.rebuildCount(), rebuilds); // ... with no rebuild

    const ParticleStore& p = world.particles;
    const Vec3 x0 = p.position[1], v0 = p.velocity[1], w0 = p.angularVelocity[1];
    const Vec3 f0 = p.force[1], t0 = p.torque[1], g = world.gravity;
    const Real invMass = p.invMass[1], invInertia = p.invInertia[1];
    ASSERT_GT(length(f0), 0); // (A pushed B in the last step)
    const Vec3 parked{kParkedCoordinate, kParkedCoordinate, kParkedCoordinate};
    constexpr int kSteps = 200;
    for (int n = 1; n <= kSteps; ++n)
    {
        step(world, dt);
        EXPECT_EQ(world.health.touchingPairs, 0u) << n;
        EXPECT_EQ(world.health.touchingWalls, 0u) << n;
        EXPECT_TRUE(world.health.finite) << n;
        EXPECT_EQ(p.position[0], parked) << n; // A does not move
    }
    EXPECT_EQ(world.neighbors.rebuildCount(), rebuilds); // A never triggered one
    // A's contacts opened: their history is dropped.
    for (const Vec3& s : world.pairHistory.spring)
        EXPECT_EQ(s, Vec3{});
    for (const Vec3& s : world.wallHistory.spring)
        EXPECT_EQ(s, Vec3{});
    // B against the formula. 1e-9 relative: the steps and the formula differ by rounding only
    // (~kSteps ulp of each sum, 1e-13 relative), far below it.
    const Real t = kSteps * dt;
    const Vec3 half = v0 + (0.5 * dt * invMass) * f0;
    const Vec3 v = half + t * g, x = x0 + t * half + (0.5 * t * t) * g;
    const Vec3 w = w0 + (0.5 * dt * invInertia) * t0;
    EXPECT_NEAR(p.velocity[1].x, v.x, 1e-9 * length(v));
    EXPECT_NEAR(p.velocity[1].y, v.y, 1e-9 * length(v));
    EXPECT_NEAR(p.velocity[1].z, v.z, 1e-9 * length(v));
    EXPECT_NEAR(p.position[1].x, x.x, 1e-9 * length(x));
    EXPECT_NEAR(p.position[1].y, x.y, 1e-9 * length(x));
    EXPECT_NEAR(p.position[1].z, x.z, 1e-9 * length(x));
    EXPECT_NEAR(p.angularVelocity[1].x, w.x, 1e-9 * length(w));
    EXPECT_NEAR(p.angularVelocity[1].y, w.y, 1e-9 * length(w));
    EXPECT_NEAR(p.angularVelocity[1].z, w.z, 1e-9 * length(w));
    // (A moved the free sphere's path measurably: v differs from v0 + t g by dt/2 F0/m.)
    EXPECT_GT(length(half - v0), 1e-6 * length(v0));

    compactRetiredParticles(world);
    ASSERT_EQ(world.particles.size(), 1u);
    EXPECT_EQ(world.particles.id[0], 1u);
    EXPECT_GT(world.neighbors.rebuildCount(), rebuilds);
}

namespace
{

/// 2,500 spheres rained at once into the 5 cm box with a floor, 20 more at each later flow event
/// (every 50 steps), an outlet taking those whose centre is below 8 mm in one corner (the outlets
/// act before the inserters at an event: some are inserted while others are retired); on `threads`
/// threads, for `runs` runs of 50 steps, or until the first rebuild that takes retired particles out
/// of the store if `stopAtCompaction`.
struct Pour
{
    World world;
    ParticleFlow flow;
    std::size_t retiredSeen = 0; // the most particles retired at once
    int compactions = 0;         // runs in which a rebuild took retired particles out
};

Pour pourIntoCorner(int threads, int runs, bool stopAtCompaction, bool removeAtOnce = false)
{
    const exec::ThreadCountOverride loops(threads);
    Pour r;
    r.world = emptyBox();
    Inserter in = rain(Inserter::Mode::Count, 2500, 0, 0);
    in.velocity = {0, 0, -0.5};
    r.flow.inserters.push_back(in);
    Inserter more = rain(Inserter::Mode::Rate, 20000, 0, 1); // 20 an event (1 ms)
    more.random = Random(12);
    r.flow.inserters.push_back(more);
    Outlet corner;
    corner.name = "corner";
    corner.region.kind = FlowRegion::Kind::Box;
    corner.region.min = {0, 0, -1};
    corner.region.max = {0.025, 0.025, 8e-3};
    r.flow.outlets.push_back(corner);
    const Real dt = 2e-5;
    for (int run = 0; run < runs; ++run)
    {
        r.flow.apply(r.world, dt);
        if (removeAtOnce) // (as an output would: the store and the lists renumbered now)
            compactRetiredParticles(r.world);
        const std::size_t retired = retiredCount(r.world);
        r.retiredSeen = std::max(r.retiredSeen, retired);
        bool compacted = false;
        for (int s = 0; s < 50 && !(compacted && stopAtCompaction); ++s)
        {
            step(r.world, dt);
            compacted = compacted || (retired > 0 && retiredCount(r.world) == 0);
        }
        r.compactions += compacted ? 1 : 0;
        if (compacted && stopAtCompaction)
            break;
    }
    return r;
}

} // namespace

// After the rebuild that takes the retired particles out, the pair slots are the pairs within
// r_i + r_j + skin and the wall slots the walls within the skin (wallNear), found by brute force:
// the renaming and the rebuild lost nothing and kept nothing stale. The ids, count and mass are
// those of the particles inserted less those the outlet took.
TEST(Removal, ListsAfterTheNextRebuildEqualBruteForce)
{
    Pour r = pourIntoCorner(1, 200, true);
    ASSERT_EQ(r.compactions, 1);
    ASSERT_GT(r.retiredSeen, 0u);
    const World& world = r.world;
    const ParticleStore& p = world.particles;
    std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        for (std::uint32_t j = i + 1; j < p.size(); ++j)
        {
            const Real reach = p.radius[i] + p.radius[j] + world.neighbors.skin + world.neighbors.reach;
            if (lengthSquared(p.position[i] - p.position[j]) < reach * reach)
                expected.insert({i, j});
        }
    std::set<std::pair<std::uint32_t, std::uint32_t>> listed;
    for (std::size_t k = 0; k < world.neighbors.size(); ++k)
        listed.insert({world.neighbors.first[k], world.neighbors.second[k]});
    EXPECT_EQ(listed.size(), world.neighbors.size()); // (no slot twice)
    EXPECT_TRUE(listed == expected) << listed.size() << " slots, " << expected.size() << " by brute force";
    EXPECT_TRUE(world.periodicPairs.empty()); // (the inserted pairs were handed over)

    std::set<std::pair<std::uint32_t, std::uint32_t>> walls, wallsExpected;
    for (std::size_t k = 0; k < world.wallContacts.size(); ++k)
        walls.insert({world.wallContacts.particle[k], world.wallContacts.wall[k]});
    for (std::uint32_t i = 0; i < p.size(); ++i)
        for (std::uint32_t w = 0; w < world.walls.size(); ++w)
            if (wallNear(world.walls[w], p.position[i], p.radius[i], world.neighbors.skin))
                wallsExpected.insert({i, w});
    EXPECT_TRUE(walls == wallsExpected)
        << walls.size() << " wall slots, " << wallsExpected.size() << " by brute force";

    const Outlet& out = r.flow.outlets[0];
    EXPECT_EQ(p.size() + out.count, r.flow.inserters[0].inserted + r.flow.inserters[1].inserted);
    std::set<std::uint32_t> ids(p.id.begin(), p.id.end());
    EXPECT_EQ(ids.size(), p.size());
    Real mass = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_FALSE(p.retired(i));
        EXPECT_LT(p.position[i].z, 1); // (no parked particle)
        mass += p.mass[i];
    }
    // The masses summed in two orders: a few ulp of the total apart (1e-12 relative).
    const Real inserted = r.flow.inserters[0].insertedMass + r.flow.inserters[1].insertedMass;
    EXPECT_NEAR(mass + out.mass, inserted, 1e-12 * inserted);
}

// The same pour on one and two threads: the same bits, retired particles and compaction included
// (the compaction happens at a rebuild, which the largest displacement decides: the same on any
// thread count).
TEST(Removal, SameBitsOnOneAndTwoThreads)
{
    const Pour a = pourIntoCorner(1, 8, false), b = pourIntoCorner(2, 8, false);
    ASSERT_GE(a.compactions, 2);
    EXPECT_EQ(a.compactions, b.compactions);
    EXPECT_GT(a.world.particles.size(), 2048u); // above kParallelThreshold: the loops do split
    ASSERT_EQ(a.world.particles.size(), b.world.particles.size());
    EXPECT_EQ(a.world.particles.id, b.world.particles.id);
    EXPECT_EQ(0, std::memcmp(a.world.particles.position.data(), b.world.particles.position.data(),
                             a.world.particles.size() * sizeof(Vec3)));
    EXPECT_EQ(0, std::memcmp(a.world.particles.velocity.data(), b.world.particles.velocity.data(),
                             a.world.particles.size() * sizeof(Vec3)));
    EXPECT_EQ(0,
              std::memcmp(a.world.particles.angularVelocity.data(), b.world.particles.angularVelocity.data(),
                          a.world.particles.size() * sizeof(Vec3)));
}

// Retiring changes when the store is renumbered, not the physics: the same pour with the retired
// particles taken out at each event (a removal at once, as before retirement) ends with the same
// particles in the same states to round-off grown by the flow (a particle's force sum runs in
// another order while a removal at once has moved the last particle into a retired one's slot).
// 1e-9 of the box and of the fall speed: a particle that felt a retired one for a step, or lost
// a contact a step late, would be off by ~dt^2 F/m, 1e-6 of them. (Observed: the same bits here,
// as the particles the removal at once moves, the last inserted, touch nothing before the
// compaction; in a packed silo they do, and the bits differ.)
TEST(Removal, SamePhysicsAsRemovalAtOnce)
{
    const Pour a = pourIntoCorner(1, 8, false), b = pourIntoCorner(1, 8, false, true);
    Pour& retired = const_cast<Pour&>(a);
    compactRetiredParticles(retired.world);
    const ParticleStore &p = a.world.particles, &q = b.world.particles;
    ASSERT_EQ(p.size(), q.size());
    ASSERT_GT(a.flow.outlets[0].count, 0u);
    EXPECT_EQ(a.flow.outlets[0].count, b.flow.outlets[0].count);
    std::vector<std::uint32_t> slotOf(p.size() + 100000, 0xffffffffu);
    for (std::uint32_t i = 0; i < q.size(); ++i)
        slotOf[q.id[i]] = i;
    Real worstX = 0, worstV = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const std::uint32_t j = slotOf[p.id[i]];
        ASSERT_NE(j, 0xffffffffu);
        worstX = std::max(worstX, length(p.position[i] - q.position[j]));
        worstV = std::max(worstV, length(p.velocity[i] - q.velocity[j]));
    }
    EXPECT_LT(worstX, 1e-9 * 0.05) << worstX; // (the 5 cm box)
    EXPECT_LT(worstV, 1e-9 * 0.5) << worstV;  // (the 0.5 m/s of the rain)
}

// Where retiring is not possible (an observer reads every particle each step), the event removes
// at once and rebuilds, as without retirement.
TEST(Removal, WithAnObserverTheEventRemovesAtOnce)
{
    struct Quiet : StepObserver
    {
        void beforeForces(const World&, Real) override {}
        void afterStep(const World&, Real) override {}
    } quiet;
    World world = emptyBox();
    world.particles.add({0.01, 0.01, 0.01}, {}, {}, 1e-3, 2500, 0);
    world.particles.add({0.02, 0.01, 0.03}, {}, {}, 1e-3, 2500, 0);
    prepare(world);
    world.observer = &quiet;
    EXPECT_FALSE(retiresWithoutRebuild(world));
    ParticleFlow flow;
    flow.outlets.push_back(above(0.02));
    ASSERT_TRUE(flow.apply(world, 1e-4));
    ASSERT_EQ(world.particles.size(), 1u);
    EXPECT_EQ(world.particles.id[0], 0u);
    world.observer = nullptr;
    EXPECT_TRUE(retiresWithoutRebuild(world));
}
