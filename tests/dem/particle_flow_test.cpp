// Particles in and out (dem/particle_flow.h, dem/particle_changes.h) and frozen particles: the
// radius distributions' moments, insertion counts and rates over a window, no overlaps, the same
// particles on 1 and 2 threads, outlet counts and mass, history carried through a removal, a
// frozen particle held in place and seen as a partner of infinite mass. Insertion without a
// rebuild of the contact lists: insertion_contacts_test.cpp.
#include "dem/particle_changes.h"
#include "dem/particle_flow.h"
#include "dem/world.h"
#include "exec/thread_pool.h"
#include "flow_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numeric>

using namespace veridem;
using namespace veridem::dem;
using namespace veridem::dem::flow_test;

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
    ASSERT_EQ(world.particles.size(), 10u);           // retired, in the store until the next rebuild
    for (std::size_t i = 0; i < 10; ++i)
        EXPECT_EQ(world.particles.retired(i), i >= 5) << i;
    compactRetiredParticles(world);
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
