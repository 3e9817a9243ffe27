// Particles in and out (dem/particle_flow.h, dem/particle_changes.h) and frozen particles: the
// radius distributions' moments, insertion counts and rates over a window, no overlaps, the same
// particles on 1 and 2 threads, outlet counts and mass, history carried through a removal, a
// frozen particle held in place and seen as a partner of infinite mass; insertion without a
// rebuild lists exactly the pairs and walls within its search distances, and an inserted
// particle's contact keeps the spring of the law through a removal that renames it.
#include "dem/particle_changes.h"
#include "dem/particle_flow.h"
#include "dem/world.h"
#include "exec/thread_pool.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numeric>

using namespace veridem;
using namespace veridem::dem;

namespace
{

struct Moments
{
    double mean, variance, fourth; // sample mean, variance and fourth central moment
    std::size_t n;
};

Moments sampleMoments(const RadiusDistribution& d, std::size_t n, std::uint64_t seed)
{
    Random random(seed);
    std::vector<double> x(n);
    for (auto& v : x)
        v = d.sample(random);
    const double mean = std::accumulate(x.begin(), x.end(), 0.0) / double(n);
    double m2 = 0, m4 = 0;
    for (const double v : x)
    {
        const double e = (v - mean) * (v - mean);
        m2 += e;
        m4 += e * e;
    }
    return {mean, m2 / double(n - 1), m4 / double(n), n};
}

/// The sample mean and variance against the distribution's, each within 5 standard errors: the
/// error of the mean is sqrt(var / n), that of the variance sqrt((mu4 - var^2) / n) (mu4 the fourth
/// central moment, estimated from the sample). A correct sampler fails with probability < 1e-6.
void expectMoments(const Moments& m, double mean, double variance)
{
    const double n = double(m.n);
    EXPECT_NEAR(m.mean, mean, 5 * std::sqrt(variance / n));
    EXPECT_NEAR(m.variance, variance, 5 * std::sqrt(std::fmax(m.fourth - m.variance * m.variance, 0.0) / n));
}

double phi(double x)
{
    return std::exp(-0.5 * x * x) / std::sqrt(2 * M_PI);
}
double Phi(double x)
{
    return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

} // namespace

TEST(RadiusDistribution, UniformMoments)
{
    RadiusDistribution d;
    d.kind = RadiusDistribution::Kind::Uniform;
    d.min = 1e-3;
    d.max = 3e-3;
    const double w = d.max - d.min;
    expectMoments(sampleMoments(d, 200000, 3), 0.5 * (d.min + d.max), w * w / 12);
}

TEST(RadiusDistribution, TruncatedNormalMoments)
{
    RadiusDistribution d;
    d.kind = RadiusDistribution::Kind::Normal;
    d.mean = 2e-3;
    d.std = 0.5e-3;
    d.min = 1.5e-3;
    d.max = 3.5e-3;
    // Truncated normal on [a, b] (in standard units): mean mu + s (phi(a) - phi(b)) / Z,
    // variance s^2 [1 + (a phi(a) - b phi(b)) / Z - ((phi(a) - phi(b)) / Z)^2], Z = Phi(b) - Phi(a).
    const double a = (d.min - d.mean) / d.std, b = (d.max - d.mean) / d.std, z = Phi(b) - Phi(a);
    const double shift = (phi(a) - phi(b)) / z;
    expectMoments(sampleMoments(d, 200000, 5), d.mean + d.std * shift,
                  d.std * d.std * (1 + (a * phi(a) - b * phi(b)) / z - shift * shift));
}

TEST(RadiusDistribution, LogNormalMoments)
{
    RadiusDistribution d;
    d.kind = RadiusDistribution::Kind::LogNormal;
    d.mu = std::log(1e-3);
    d.sigma = 0.25;
    d.min = 0;
    d.max = std::exp(d.mu + 6 * d.sigma); // as the reader sets it (mass beyond: < 1e-9)
    // mean exp(mu + s^2/2), variance (exp(s^2) - 1) exp(2 mu + s^2)
    const double s2 = d.sigma * d.sigma;
    expectMoments(sampleMoments(d, 200000, 7), std::exp(d.mu + 0.5 * s2),
                  (std::exp(s2) - 1) * std::exp(2 * d.mu + s2));
}

TEST(RadiusDistribution, TableByNumberMoments)
{
    RadiusDistribution d;
    d.kind = RadiusDistribution::Kind::Table;
    d.radii = {1e-3, 2e-3, 4e-3};
    d.cumulative = {0.5, 0.8, 1.0}; // probabilities 0.5, 0.3, 0.2
    const double p[3] = {0.5, 0.3, 0.2};
    double mean = 0, second = 0;
    for (int k = 0; k < 3; ++k)
    {
        mean += p[k] * d.radii[std::size_t(k)];
        second += p[k] * d.radii[std::size_t(k)] * d.radii[std::size_t(k)];
    }
    expectMoments(sampleMoments(d, 200000, 9), mean, second - mean * mean);
}

namespace
{

Material glass()
{
    Material m;
    m.name = "glass";
    m.density = 2500;
    m.normalStiffness = 500;
    m.restitution = 0.5;
    m.friction = 0.4;
    return m;
}

/// An empty world with a floor and a skin for radii of 1-1.5 mm, prepared.
World emptyBox()
{
    World world;
    world.addMaterial(glass());
    Wall floor;
    floor.name = "floor";
    floor.shape = PlaneShape{{0, 0, 0}, {0, 0, 1}};
    world.walls.push_back(floor);
    world.neighbors.skin = 0.3e-3;
    prepare(world);
    return world;
}

Inserter rain(Inserter::Mode mode, Real amount, Real from, Real until)
{
    Inserter in;
    in.name = "rain";
    in.region.kind = FlowRegion::Kind::Box;
    in.region.min = {0, 0, 0};
    in.region.max = {0.05, 0.05, 0.05};
    in.mode = mode;
    (mode == Inserter::Mode::Count ? in.count : in.rate) = amount;
    in.from = from;
    in.until = until;
    in.radius.kind = RadiusDistribution::Kind::Uniform;
    in.radius.min = 1e-3;
    in.radius.max = 1.5e-3;
    in.materials = {0};
    in.materialCumulative = {1};
    in.random = Random(11);
    return in;
}

void expectNoOverlaps(const World& world)
{
    const ParticleStore& p = world.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_GE(p.position[i].z, p.radius[i]); // above the floor
        for (std::size_t j = i + 1; j < p.size(); ++j)
            ASSERT_GE(length(p.position[i] - p.position[j]), p.radius[i] + p.radius[j]) << i << " " << j;
    }
}

} // namespace

TEST(Insertion, RateOverAWindow)
{
    World world = emptyBox();
    ParticleFlow flow;
    flow.inserters.push_back(rain(Inserter::Mode::Rate, 10000, 0.01, 0.03)); // 10,000/s for 20 ms
    const Real dt = 1e-4;
    for (int k = 0; k <= 500; ++k) // t = 0 .. 0.05 s, every step
    {
        world.time = k * dt;
        flow.apply(world, dt);
        // floor(rate (min(t, until) - from)) once past `from` (to rounding of t: +-1)
        const Real due = std::floor(10000 * std::fmax(0.0, std::fmin(world.time, 0.03) - 0.01));
        EXPECT_NEAR(Real(world.particles.size()), due, 1.0) << "t = " << world.time;
    }
    EXPECT_EQ(world.particles.size(), 200u);
    EXPECT_FALSE(flow.inserters[0].warnedFull);
    expectNoOverlaps(world);
    EXPECT_EQ(world.particles.id.back(), 199u); // ids in insertion order
}

TEST(Insertion, CountAndMassRate)
{
    World world = emptyBox();
    ParticleFlow flow;
    flow.inserters.push_back(rain(Inserter::Mode::Count, 300, 0, 0)); // all at once
    Inserter massive = rain(Inserter::Mode::MassRate, 0.01, 0, 0.1);  // 10 g/s for 0.1 s
    massive.region.min = {0, 0, 0.06};
    massive.region.max = {0.05, 0.05, 0.11};
    flow.inserters.push_back(massive);
    world.time = 0;
    flow.apply(world, 1e-4);
    EXPECT_EQ(flow.inserters[0].inserted, 300u);
    for (int k = 1; k <= 10; ++k)
    {
        world.time = 0.01 * k;
        flow.apply(world, 1e-4);
    }
    // The mass inserted reaches 1 g and exceeds it by less than one particle's mass.
    const Real largest = 2500 * 4.0 / 3.0 * M_PI * std::pow(1.5e-3, 3);
    EXPECT_GE(flow.inserters[1].insertedMass, 0.01 * 0.1);
    EXPECT_LT(flow.inserters[1].insertedMass, 0.01 * 0.1 + largest);
    expectNoOverlaps(world);
}

TEST(Insertion, FullRegionSaysSoAndCarriesOn)
{
    World world = emptyBox();
    ParticleFlow flow;
    Inserter in = rain(Inserter::Mode::Count, 100000, 0, 0);
    in.region.max = {0.01, 0.01, 0.01}; // room for a few hundred
    flow.inserters.push_back(in);
    flow.apply(world, 1e-4);
    EXPECT_TRUE(flow.inserters[0].warnedFull);
    EXPECT_GT(world.particles.size(), 20u); // (random sequential addition, 200 tries a sphere)
    EXPECT_LT(world.particles.size(), 1000u);
    expectNoOverlaps(world);
}

namespace
{

/// 2,500 spheres inserted at once into a box with a floor and an outlet below a hole-free floor
/// level, stepped 300 steps with 20 more inserted at every event (every 50 steps, without a
/// rebuild of the contact lists); on `threads` threads.
World pour(int threads)
{
    const exec::ThreadCountOverride loops(threads);
    World world = emptyBox();
    ParticleFlow flow;
    flow.inserters.push_back(rain(Inserter::Mode::Count, 2500, 0, 0));
    Inserter more = rain(Inserter::Mode::Rate, 20000, 0, 1); // 20 an event (1 ms)
    more.random = Random(12);
    flow.inserters.push_back(more);
    Outlet o;
    o.region.kind = FlowRegion::Kind::Box;
    o.region.min = {0, 0, 0};
    o.region.max = {0.01, 0.01, 0.005};
    flow.outlets.push_back(o);
    const Real dt = 2e-5;
    for (int run = 0; run < 6; ++run)
    {
        flow.apply(world, dt);
        advance(world, dt, 50);
    }
    return world;
}

} // namespace

TEST(Insertion, SameParticlesOnOneAndTwoThreads)
{
    const World a = pour(1), b = pour(2);
    ASSERT_EQ(a.particles.size(), b.particles.size());
    EXPECT_GT(a.particles.size(), 2048u); // above kParallelThreshold: the loops do split
    EXPECT_EQ(a.particles.id, b.particles.id);
    EXPECT_EQ(0, std::memcmp(a.particles.position.data(), b.particles.position.data(),
                             a.particles.size() * sizeof(Vec3)));
    EXPECT_EQ(0, std::memcmp(a.particles.velocity.data(), b.particles.velocity.data(),
                             a.particles.size() * sizeof(Vec3)));
}

TEST(Outlet, CountsAndMass)
{
    World world = emptyBox();
    for (int k = 0; k < 10; ++k)
        world.particles.add({0.01 * k + 0.005, 0.01, 0.01}, {}, {}, 1e-3 * (1 + 0.1 * k), 2500, 0);
    prepare(world);
    ParticleFlow flow;
    Outlet half;
    half.region.kind = FlowRegion::Kind::HalfSpace;
    half.region.point = {0.05, 0, 0};
    half.region.normal = {1, 0, 0}; // x > 0.05: particles 5..9
    flow.outlets.push_back(half);
    Real expected = 0;
    for (int k = 5; k < 10; ++k)
        expected += world.particles.mass[std::size_t(k)];
    EXPECT_TRUE(flow.apply(world, 1e-4));
    EXPECT_EQ(flow.outlets[0].count, 5u);
    EXPECT_DOUBLE_EQ(flow.outlets[0].mass, expected); // (summed in another order: a rounding apart)
    ASSERT_EQ(world.particles.size(), 5u);
    std::vector<std::uint32_t> ids = world.particles.id;
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
    EXPECT_FALSE(flow.apply(world, 1e-4)); // nothing left there
}

TEST(ParticleChanges, HistoryFollowsThePairThroughARemoval)
{
    // Two touching spheres sheared against each other (the tangential spring loads), a third far
    // away; the first is removed, so the last moves into its place and the pair is renamed.
    World world;
    world.addMaterial(glass());
    world.gravity = {0, 0, 0};
    world.particles.add({0, 0, 0}, {}, {}, 1e-3, 2500, 0);                    // 0: removed
    world.particles.add({0.1, 0, 0}, {0, 0.01, 0}, {}, 1e-3, 2500, 0);        // 1
    world.particles.add({0.1, 0, 1.99e-3}, {0, -0.01, 0}, {}, 1e-3, 2500, 0); // 2: touches 1
    const Real dt = 1e-6;
    for (int s = 0; s < 20; ++s)
        step(world, dt);
    World reference = world; // the same without the removal
    ASSERT_EQ(world.pairHistory.size(), 1u);
    const Vec3 spring = world.pairHistory.spring[0];
    ASSERT_GT(length(spring), 0);
    removeParticles(world, {0});
    rebuildAfterParticleChange(world);
    // Now (0, 1) is the pair (2, 1) renamed: the order flipped, so the spring is negated.
    ASSERT_EQ(world.pairHistory.size(), 1u);
    EXPECT_EQ(world.pairHistory.spring[0].x, -spring.x);
    EXPECT_EQ(world.pairHistory.spring[0].y, -spring.y);
    EXPECT_EQ(world.pairHistory.spring[0].z, -spring.z);
    for (int s = 0; s < 20; ++s)
    {
        step(world, dt);
        step(reference, dt);
    }
    // The pair evolves as without the removal (one sum order within the pair: 1e-12 relative).
    EXPECT_NEAR(world.particles.velocity[1].y, reference.particles.velocity[1].y,
                1e-12 * std::fabs(reference.particles.velocity[1].y));
    EXPECT_NEAR(world.particles.velocity[0].y, reference.particles.velocity[2].y,
                1e-12 * std::fabs(reference.particles.velocity[2].y));
}

TEST(FixedParticle, StaysPutUnderGravityAndLoad)
{
    World world;
    world.addMaterial(glass());
    world.particles.add({0, 0, 0}, {0.1, 0, 0}, {0, 0, 1}, 1e-3, 2500, 0);
    world.particles.fixed.back() = 1;
    world.particles.add({0, 0, 2.5e-3}, {}, {}, 1e-3, 2500, 0); // falls onto it
    prepare(world);
    const Vec3 home = world.particles.position[0];
    advance(world, 1e-5, 2000);
    EXPECT_EQ(world.particles.position[0].x, home.x);
    EXPECT_EQ(world.particles.position[0].y, home.y);
    EXPECT_EQ(world.particles.position[0].z, home.z);
    EXPECT_EQ(length(world.particles.velocity[0]), 0);
    EXPECT_EQ(length(world.particles.angularVelocity[0]), 0);
    EXPECT_GT(world.particles.position[1].z, 1.9e-3); // resting on it, not through it
}

namespace
{

/// The rebound speed of a ball (r = 1 mm) thrown at 0.5 m/s, without gravity, at a frozen sphere
/// of radius `partnerRadius` [m], or at a plane wall if partnerRadius is 0.
Real reboundSpeed(Real partnerRadius)
{
    World world;
    Material m = glass();
    m.friction = 0;
    world.addMaterial(m);
    world.gravity = {0, 0, 0};
    if (partnerRadius > 0)
    {
        world.particles.add({0, 0, -partnerRadius}, {}, {}, partnerRadius, 2500, 0);
        world.particles.fixed.back() = 1;
    }
    else
    {
        Wall floor;
        floor.name = "floor";
        floor.shape = PlaneShape{{0, 0, 0}, {0, 0, 1}};
        world.walls.push_back(floor);
    }
    world.particles.add({0, 0, 1.2e-3}, {0, 0, -0.5}, {}, 1e-3, 2500, 0);
    const std::size_t ball = world.particles.size() - 1;
    // The linear contact lasts pi sqrt(m* / kn) = 0.72 ms for m* = m: dt = 1e-7 s resolves it by
    // 7,000 steps.
    const Real dt = 1e-7;
    for (int s = 0; s < 20000; ++s)
        step(world, dt);
    return world.particles.velocity[ball].z;
}

} // namespace

TEST(FixedParticle, IsAPartnerOfInfiniteMass)
{
    // Head-on, the contact sees m* = m of the ball (the frozen sphere's mass infinite) as a wall
    // does: the linear law's restitution is exactly the material's, so the ball rebounds at
    // e v = 0.25 m/s as from a plane, to the time discretisation (dt / tc = 1.4e-4: 1e-3 relative
    // covers it). With m* = m/2 (a free partner of equal mass) the same damping coefficient would
    // give a different restitution; the free-sphere speed is not compared here.
    const Real wall = reboundSpeed(0), sphere = reboundSpeed(1e-3), big = reboundSpeed(5e-3);
    EXPECT_NEAR(wall, 0.25, 1e-3 * 0.25);
    EXPECT_NEAR(sphere, 0.25, 1e-3 * 0.25);
    EXPECT_NEAR(big, 0.25, 1e-3 * 0.25);
}

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
