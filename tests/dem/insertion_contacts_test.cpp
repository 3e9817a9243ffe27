// Insertion without a rebuild of the contact lists (dem/particle_changes.h, addInsertedParticles):
// the inserted particles' pairs and wall candidates are exactly those within the search distances,
// the lists are not rebuilt, and an inserted particle's contact keeps the spring of the law
// through a removal that renames it.
#include "dem/particle_changes.h"
#include "dem/particle_flow.h"
#include "dem/world.h"
#include "flow_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace veridem;
using namespace veridem::dem;
using namespace veridem::dem::flow_test;

namespace
{

/// The glass of the two-sphere tests: kn 1000 N/m, a damping rate and friction 0.5.
Material slidingGlass()
{
    Material m = glass();
    m.normalStiffness = 1000;
    m.normalDampingRate = 50;
    m.friction = 0.5;
    return m;
}

/// An inserter of one sphere (r = 1 mm) whose centre is x to 1e-10 m (a box of edge 2 r + 2e-10 m
/// around it), moving at v, at t = 0.
Inserter oneSphereAt(const Vec3& x, const Vec3& v)
{
    Inserter in;
    in.name = "one";
    in.region.kind = FlowRegion::Kind::Box;
    const Real half = 1e-3 + 1e-10;
    in.region.min = x - Vec3{half, half, half};
    in.region.max = x + Vec3{half, half, half};
    in.mode = Inserter::Mode::Count;
    in.count = 1;
    in.radius.kind = RadiusDistribution::Kind::Fixed;
    in.radius.value = 1e-3;
    in.materials = {0};
    in.materialCumulative = {1};
    in.velocity = v;
    in.random = Random(3);
    return in;
}

/// a and b agree to `relative` of `scale` in each component.
void expectClose(const Vec3& a, const Vec3& b, Real scale, Real relative, const char* what, int s)
{
    EXPECT_NEAR(a.x, b.x, relative * scale) << what << " at step " << s;
    EXPECT_NEAR(a.y, b.y, relative * scale) << what << " at step " << s;
    EXPECT_NEAR(a.z, b.z, relative * scale) << what << " at step " << s;
}

} // namespace

TEST(ParticleChanges, AnInsertedParticleKeepsItsSpringThroughARemovalWhileItSlides)
{
    // Sphere P is inserted next to sphere Q, touching nothing (gap 0.09 mm), moving towards it and
    // sliding; a third sphere N, far from both, is removed by an outlet while P and Q slide on each
    // other. Indices: N 0, Q 1, P 2 (inserted); after the removal P takes index 0, so the pair
    // (1, 2) becomes (0, 1) with its order flipped: its spring is negated with it. The reference
    // world holds only Q (0) and P (1) from the start, in the neighbour list: the same pair under
    // the same law. The spring is what the law gives that pair, step by step.
    //
    // Tolerance: the inserted pair is evaluated through pairContactAt after the pair stage, the
    // reference's in the pair kernel: the same law, with the flipped pair's separation and
    // relative velocity negated exactly, so the two agree to rounding (~1e-16 relative a step);
    // 1e-9 relative to the force's and spring's scale bounds its growth over the ~250 steps of
    // contact (as the periodic tests, periodic_test.cpp).
    const Real dt = 1e-6, skin = 2e-3;
    const Vec3 xq{0.01, 0.01, 0.01}, xp = xq + Vec3{0.0004, 0, 0.00205}, vp{0.05, 0.02, -0.2};
    World flowing;
    flowing.addMaterial(slidingGlass());
    flowing.gravity = {0, 0, 0};
    flowing.neighbors.skin = skin;
    flowing.particles.add({0.05, 0.05, 0.05}, {}, {}, 1e-3, 2500, 0); // N
    flowing.particles.add(xq, {}, {}, 1e-3, 2500, 0);                 // Q
    prepare(flowing);
    ParticleFlow flow;
    flow.nextId = 2; // (ids 0 and 1 are N's and Q's)
    flow.inserters.push_back(oneSphereAt(xp, vp));
    const std::size_t rebuildsBefore = flowing.neighbors.rebuildCount();
    ASSERT_TRUE(flow.apply(flowing, dt));
    ASSERT_EQ(flowing.particles.size(), 3u);
    ASSERT_LT(length(flowing.particles.position[2] - xp), 1e-9); // P where meant
    EXPECT_EQ(flowing.neighbors.rebuildCount(), rebuildsBefore); // inserted without a rebuild
    ASSERT_EQ(flowing.periodicPairs.size(), 1u);                 // (Q, P), evaluated after the pair stage
    EXPECT_EQ(flowing.periodicPairs.first[0], 1u);
    EXPECT_EQ(flowing.periodicPairs.second[0], 2u);

    World reference;
    reference.addMaterial(slidingGlass());
    reference.gravity = {0, 0, 0};
    reference.neighbors.skin = skin;
    reference.particles.add(xq, {}, {}, 1e-3, 2500, 0);
    reference.particles.add(flowing.particles.position[2], flowing.particles.velocity[2], {}, 1e-3, 2500, 0);
    prepare(reference);

    Outlet outlet; // around N only
    outlet.region.kind = FlowRegion::Kind::Box;
    outlet.region.min = {0.04, 0.04, 0.04};
    outlet.region.max = {0.06, 0.06, 0.06};
    int touching = 0, touchingBeforeRemoval = 0;
    bool removed = false;
    Real largestSpring = 0;
    for (int s = 1; s <= 900; ++s)
    {
        step(flowing, dt);
        step(reference, dt);
        const std::size_t p = removed ? 0 : 2, q = 1;
        const bool inContact = reference.health.touchingPairs == 1;
        ASSERT_EQ(flowing.health.touchingPairs, reference.health.touchingPairs) << s;
        touching += inContact;
        const Real scale = length(reference.particles.force[1]) + 1e-30;
        expectClose(flowing.particles.force[p], reference.particles.force[1], scale, 1e-9, "force on P", s);
        expectClose(flowing.particles.force[q], reference.particles.force[0], scale, 1e-9, "force on Q", s);
        expectClose(flowing.particles.torque[p], reference.particles.torque[1], scale * 1e-3, 1e-9,
                    "torque on P", s);
        // The spring of (Q, P): the inserted pair's, or after the removal the candidate (P, Q)'s negated.
        if (inContact)
        {
            ASSERT_EQ(reference.pairHistory.size(), 1u);
            const Vec3 expected = reference.pairHistory.spring[0];
            largestSpring = std::max(largestSpring, length(expected));
            Vec3 spring;
            if (!flowing.periodicPairs.empty())
                spring = flowing.periodicPairs.history.spring[0];
            else
            {
                ASSERT_EQ(flowing.pairHistory.size(), 1u) << s;
                spring = -1.0 * flowing.pairHistory.spring[0];
            }
            expectClose(spring, expected, length(expected) + 1e-30, 1e-9, "spring", s);
        }
        // Remove N while P slides on Q (the 60th step of contact).
        if (!removed && touching == 60)
        {
            touchingBeforeRemoval = touching;
            ASSERT_NE(length(flowing.periodicPairs.history.spring[0]), 0); // loaded spring
            flow.outlets.push_back(outlet);
            flow.inserters.clear();
            ASSERT_TRUE(flow.apply(flowing, dt));
            ASSERT_TRUE(flowing.particles.retired(0));
            compactRetiredParticles(flowing); // (N leaves the store now, as before an output)
            ASSERT_EQ(flowing.particles.size(), 2u);
            ASSERT_EQ(flowing.particles.id[0], 2u);     // P, moved into N's place
            EXPECT_TRUE(flowing.periodicPairs.empty()); // the rebuild took the pair into the list
            removed = true;
        }
    }
    EXPECT_EQ(touchingBeforeRemoval, 60);
    EXPECT_GT(touching, 120); // in contact well after the removal
    EXPECT_GT(largestSpring, 0);
}

TEST(ParticleChanges, InsertionWithoutARebuildListsEveryPairAndWallWithinReach)
{
    // A bed poured and stepped (the particles move, the lists are rebuilt as they fall), then an
    // insertion event: the contact lists are not rebuilt, and the inserted particles' pairs and
    // wall candidates are exactly those within the search distances of particle_changes.h
    // (1.5 skin beyond touching), found here by testing every pair and every wall.
    World world = emptyBox();
    ParticleFlow flow;
    flow.inserters.push_back(rain(Inserter::Mode::Count, 2000, 0, 0));
    const Real dt = 2e-5;
    flow.apply(world, dt);
    advance(world, dt, 1000); // 20 ms: a fall of 2 mm, many times skin/2
    Inserter more = rain(Inserter::Mode::Count, 300, 0, 0);
    more.random = Random(5);
    flow.inserters = {more};
    const std::size_t before = world.particles.size(), rebuilds = world.neighbors.rebuildCount();
    const std::size_t pairsBefore = world.periodicPairs.size(), slotsBefore = world.wallContacts.size();
    ASSERT_TRUE(flow.apply(world, dt));
    const ParticleStore& p = world.particles;
    ASSERT_EQ(p.size(), before + 300);
    EXPECT_EQ(world.neighbors.rebuildCount(), rebuilds);
    EXPECT_EQ(pairsBefore, 0u); // (the lists were rebuilt since the first insertion)
    const Real search = 1.5 * world.neighbors.skin;
    std::vector<std::uint64_t> expected, listed;
    for (std::size_t i = before; i < p.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
        {
            const Real within = p.radius[i] + p.radius[j] + search;
            if (lengthSquared(p.position[i] - p.position[j]) < within * within)
                expected.push_back((std::uint64_t(j) << 32) | i);
        }
    for (std::size_t k = 0; k < world.periodicPairs.size(); ++k)
    {
        EXPECT_EQ(length(world.periodicPairs.shift[k]), 0);
        listed.push_back((std::uint64_t(world.periodicPairs.first[k]) << 32) | world.periodicPairs.second[k]);
    }
    ASSERT_FALSE(expected.empty());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(listed, expected); // the same pairs, sorted by (i, j)
    std::vector<std::uint64_t> walls, slots;
    for (std::size_t i = before; i < p.size(); ++i)
        for (std::size_t w = 0; w < world.walls.size(); ++w)
            if (wallNear(world.walls[w], p.position[i], p.radius[i], search))
                walls.push_back((std::uint64_t(i) << 32) | w);
    for (std::size_t k = slotsBefore; k < world.wallContacts.size(); ++k)
        slots.push_back((std::uint64_t(world.wallContacts.particle[k]) << 32) | world.wallContacts.wall[k]);
    EXPECT_EQ(slots, walls);
    ASSERT_EQ(world.wallContacts.start.size(), p.size() + 1);
    EXPECT_EQ(world.wallContacts.start.back(), world.wallContacts.size());
    for (std::size_t i = before; i < p.size(); ++i) // the new ones overlap nothing
    {
        EXPECT_GE(p.position[i].z, p.radius[i]);
        for (std::size_t j = 0; j < p.size(); ++j)
        {
            if (j == i)
                continue;
            ASSERT_GE(length(p.position[i] - p.position[j]), p.radius[i] + p.radius[j]) << i << " " << j;
        }
    }
    // The next steps run on the appended lists, and a rebuild takes the pairs into the neighbour list.
    advance(world, dt, 200);
    EXPECT_GT(world.neighbors.rebuildCount(), rebuilds);
    EXPECT_TRUE(world.periodicPairs.empty());
}

namespace
{

/// Every image shift s of a box periodic in x and y with edges (lx, ly): {-1, 0, 1} x the edges.
std::vector<Vec3> imageShifts(Real lx, Real ly)
{
    std::vector<Vec3> shifts;
    for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
            shifts.push_back({a * lx, b * ly, 0});
    return shifts;
}

} // namespace

TEST(ParticleChanges, InsertionIntoAPeriodicBoxListsThePairsThroughTheFacesWithoutARebuild)
{
    // A 2 x 2 cm cell periodic in x and y with a floor, filled by rain over its whole section and
    // stepped, then 200 more spheres rained in: the lists are not rebuilt; the new particles'
    // pairs are exactly those within the search distance (1.5 skin beyond touching) of some image
    // of their partner, each listed once with the shift of that image (as PeriodicPairs stores a
    // pair (j, i): x_j near the image x_i + s), found here by testing every pair under every
    // image; no new sphere overlaps another or another's image.
    World world = emptyBox();
    const Real lx = 0.02, ly = 0.02;
    world.domain.min = {0, 0, 0};
    world.domain.max = {lx, ly, 0.1};
    world.domain.periodic = {true, true, false};
    prepare(world);
    ParticleFlow flow;
    Inserter first = rain(Inserter::Mode::Count, 350, 0, 0);
    first.region.min = {-0.005, -0.005, 0}; // (across the faces: wrapped into the box)
    first.region.max = {lx + 0.005, ly + 0.005, 0.05};
    flow.inserters.push_back(first);
    const Real dt = 2e-5;
    flow.apply(world, dt);
    advance(world, dt, 1000); // 20 ms: a fall of 2 mm, the lists rebuilt and the positions wrapped
    Inserter more = rain(Inserter::Mode::Count, 200, 0, 0); // above and among the falling ones
    more.region.min = {-0.005, -0.005, 0.04};
    more.region.max = {lx + 0.005, ly + 0.005, 0.08};
    more.random = Random(5);
    flow.inserters = {more};
    const std::size_t before = world.particles.size(), rebuilds = world.neighbors.rebuildCount();
    ASSERT_TRUE(flow.apply(world, dt));
    const ParticleStore& p = world.particles;
    ASSERT_EQ(p.size(), before + 200);
    EXPECT_EQ(world.neighbors.rebuildCount(), rebuilds);

    const Real search = 1.5 * world.neighbors.skin;
    const std::vector<Vec3> shifts = imageShifts(lx, ly);
    for (std::size_t i = before; i < p.size(); ++i) // wrapped into the box
    {
        EXPECT_GE(p.position[i].x, 0);
        EXPECT_LT(p.position[i].x, lx);
        EXPECT_GE(p.position[i].y, 0);
        EXPECT_LT(p.position[i].y, ly);
    }
    struct Listed
    {
        std::uint32_t first, second;
        Vec3 shift;
        bool operator<(const Listed& o) const
        {
            return first != o.first ? first < o.first : second < o.second;
        }
    };
    std::vector<Listed> expected, listed;
    int throughFaces = 0;
    for (std::size_t i = before; i < p.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
        {
            const Real within = p.radius[i] + p.radius[j] + search;
            int images = 0;
            for (const Vec3& s : shifts)
                if (lengthSquared(p.position[j] - (p.position[i] + s)) < within * within)
                {
                    expected.push_back({std::uint32_t(j), std::uint32_t(i), s});
                    ++images;
                    throughFaces += length(s) > 0;
                }
            ASSERT_LE(images, 1) << j << " " << i; // (the box holds the search twice)
            for (const Vec3& s : shifts)           // overlapping no sphere and no image of one
                ASSERT_GE(length(p.position[j] - (p.position[i] + s)), p.radius[i] + p.radius[j])
                    << i << " " << j;
        }
    for (std::size_t k = 0; k < world.periodicPairs.size(); ++k)
        if (world.periodicPairs.second[k] >= before)
            listed.push_back(
                {world.periodicPairs.first[k], world.periodicPairs.second[k], world.periodicPairs.shift[k]});
    std::sort(expected.begin(), expected.end());
    ASSERT_GE(throughFaces, 5); // the check sees pairs through the faces (14 with these seeds)
    ASSERT_EQ(listed.size(), expected.size());
    for (std::size_t k = 0; k < listed.size(); ++k)
    {
        EXPECT_EQ(listed[k].first, expected[k].first) << k;
        EXPECT_EQ(listed[k].second, expected[k].second) << k;
        EXPECT_EQ(listed[k].shift, expected[k].shift) << k; // (exact multiples of the edges)
    }
    // The next steps run on the appended lists; a rebuild then takes the direct pairs into the
    // neighbour list and keeps those through a face, and nothing overlaps beyond the law's scale.
    advance(world, dt, 300);
    EXPECT_GT(world.neighbors.rebuildCount(), rebuilds);
    EXPECT_TRUE(world.health.finite);
    EXPECT_LT(world.health.maxOverlapRatio, 0.05); // (kn 500 N/m: m g / kn ~ 3e-4 of r per layer)
}

TEST(ParticleChanges, JkrInsertionSkipsTheRebuildWhileTheTouchReachHolds)
{
    // JKR spheres (their contacts act apart, to |delta_c|: the list's touch reach): a sphere of
    // the radius already present joins the lists without a rebuild, its pair with a sphere at a
    // separation inside the reach listed; a larger sphere would widen the reach (|delta_c| grows
    // as R*^(1/3)), so its insertion rebuilds the lists, with the reach recomputed.
    Material jkr = glass();
    jkr.normalModel = NormalModel::Jkr;
    jkr.youngsModulus = 1e7;
    jkr.poissonRatio = 0.3;
    jkr.surfaceEnergy = 0.05;
    World world;
    world.addMaterial(jkr);
    world.gravity = {0, 0, 0};
    world.neighbors.skin = 0.2e-3;
    const Vec3 xq{0.01, 0.01, 0.01};
    world.particles.add(xq, {}, {}, 1e-3, 2500, 0);
    world.particles.add({0.03, 0.03, 0.03}, {}, {}, 1e-3, 2500, 0);
    prepare(world);
    const Real reach = world.neighbors.reach;
    ASSERT_GT(reach, 0);
    ParticleFlow flow;
    flow.nextId = 2;
    // 1 mm sphere whose surface is reach/2 from Q's: apart, but within the adhesive reach.
    const Vec3 xp = xq + Vec3{2e-3 + 0.5 * reach, 0, 0};
    flow.inserters.push_back(oneSphereAt(xp, {}));
    std::size_t rebuilds = world.neighbors.rebuildCount();
    ASSERT_TRUE(flow.apply(world, 1e-6));
    EXPECT_EQ(world.neighbors.rebuildCount(), rebuilds);
    ASSERT_EQ(world.periodicPairs.size(), 1u);
    EXPECT_EQ(world.periodicPairs.first[0], 0u);
    EXPECT_EQ(world.periodicPairs.second[0], 2u);
    EXPECT_EQ(world.neighbors.reach, reach);

    Inserter larger = oneSphereAt({0.02, 0.02, 0.02}, {}); // r = 2 mm, far from the others
    larger.radius.value = 2e-3;
    larger.region.min = Vec3{0.02, 0.02, 0.02} - Vec3{2e-3 + 1e-10, 2e-3 + 1e-10, 2e-3 + 1e-10};
    larger.region.max = Vec3{0.02, 0.02, 0.02} + Vec3{2e-3 + 1e-10, 2e-3 + 1e-10, 2e-3 + 1e-10};
    flow.inserters = {larger};
    rebuilds = world.neighbors.rebuildCount();
    ASSERT_TRUE(flow.apply(world, 1e-6));
    EXPECT_GT(world.neighbors.rebuildCount(), rebuilds);
    EXPECT_GT(world.neighbors.reach, reach);
}
