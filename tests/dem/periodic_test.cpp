// Periodic boundaries (dem/periodic.h): a sphere leaving through a periodic face comes back at the
// other; a pair touching through a face feels the contact of the same pair placed in the interior,
// and keeps its history when a particle wraps during the contact; a fully periodic box of colliding
// spheres conserves linear momentum.
//
// Tolerances. Moving a configuration by a box edge L changes its separations by rounding only: a
// coordinate of ~1e-2 m carries an error of ~1e-18 m (half an ulp), against overlaps of ~1e-5 m, so
// the contact inputs agree to ~1e-13 relative; the tests allow 1e-9 relative to the force's scale
// for the growth of that difference over a few hundred steps of a stable contact.
#include "core/error.h"
#include "dem/particle_changes.h"
#include "dem/periodic.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>

namespace veridem::dem
{
namespace
{

Material glass(Real kn = 1000)
{
    Material m;
    m.name = "glass";
    m.normalStiffness = kn;
    m.normalDampingRate = 50;
    m.friction = 0.5;
    return m;
}

World emptyWorld(Real kn = 1000)
{
    World world;
    world.addMaterial(glass(kn));
    world.gravity = {0, 0, 0};
    return world;
}

PeriodicDomain box(Real edge, std::array<bool, 3> periodic)
{
    PeriodicDomain d;
    d.min = {0, 0, 0};
    d.max = {edge, edge, edge};
    d.periodic = periodic;
    return d;
}

TEST(WrapPosition, WrapsAlongPeriodicAxesOnlyAndKeepsInsidePointsBitForBit)
{
    const PeriodicDomain d = box(2, {true, false, true});
    const Vec3 inside{0.5, 7, 1.999};
    EXPECT_EQ(wrapPosition(d, inside), inside);
    const Vec3 w = wrapPosition(d, {2.25, -3, -0.5});
    EXPECT_EQ(w.x, 0.25); // 2.25 - 2 is exact in binary
    EXPECT_EQ(w.y, -3);   // not periodic: unchanged
    EXPECT_EQ(w.z, 1.5);
    EXPECT_EQ(wrapPosition(d, {2, 0, 0}).x, 0); // the top face belongs to the bottom one
}

TEST(PeriodicBox, RefusesABoxShorterThanTwiceTheSearchCutoff)
{
    World world = emptyWorld();
    world.domain = box(0.01, {true, false, false});
    world.neighbors.skin = 0.002;
    world.particles.add({0.005, 0.005, 0.005}, {}, {}, 0.0014, 2500, 0);
    // 2 x (2 r + skin) = 0.0096 m fits in 0.01 m; with a sphere of 1.6 mm it is 0.0104 m: refused.
    EXPECT_NO_THROW(prepare(world));
    world.particles.add({0.005, 0.005, 0.009}, {}, {}, 0.0016, 2500, 0);
    EXPECT_THROW(prepare(world), InputError);
}

/// (i) A sphere crossing a periodic face at constant velocity re-enters at the other face with the
/// same velocity, bit for bit; its position is x0 + v t - L up to the rounding of the wrap. Run on
/// the one-particle step and on the general stages.
TEST(PeriodicBoundary, ASphereLeavingThroughAFaceComesBackAtTheOtherWithTheSameVelocity)
{
    for (const bool fused : {true, false})
    {
        World world = emptyWorld();
        world.exec.fusedSteps = fused;
        const Real edge = 0.02, dt = 1e-5;
        world.domain = box(edge, {true, true, true});
        const Vec3 v{1.0, -0.5, 0.25}, w{3, -2, 1}; // [m/s], [rad/s]
        world.particles.add({0.019, 0.001, 0.01}, v, w, 0.001, 2500, 0);
        const int steps = 600; // 6 mm in x, -3 mm in y: out through x = L and y = 0
        for (int s = 0; s < steps; ++s)
            step(world, dt);
        const Vec3 x = world.particles.position[0];
        EXPECT_EQ(world.particles.velocity[0], v) << fused;
        EXPECT_EQ(world.particles.angularVelocity[0], w) << fused;
        // x0 + v t wrapped: (0.019 + 0.006 - 0.02, 0.001 - 0.003 + 0.02, 0.01 + 0.0015); the drift
        // adds 600 rounded increments of ~1e-5 m to ~1e-2 m (each within 1.7e-18 m, 1.0e-15 m in
        // all) and the wrap one rounding more: 2e-15 m.
        EXPECT_NEAR(x.x, 0.005, 2e-15) << fused;
        EXPECT_NEAR(x.y, 0.018, 2e-15) << fused;
        EXPECT_NEAR(x.z, 0.0115, 2e-15) << fused;
        EXPECT_GT(world.neighbors.rebuildCount(), 1u) << fused; // it was wrapped at a list rebuild
    }
}

struct PairState
{
    Vec3 force0, torque0, force1, torque1, spring;
    bool touching;
};

/// The contact of the world's only pair (through an image or direct) and its tangential spring.
PairState pairState(const World& world)
{
    PairState s{world.particles.force[0],
                world.particles.torque[0],
                world.particles.force[1],
                world.particles.torque[1],
                {},
                world.health.touchingPairs == 1};
    if (!world.periodicPairs.empty())
        s.spring = world.periodicPairs.history.spring[0];
    else if (world.pairHistory.size() == 1)
        s.spring = world.pairHistory.spring[0];
    return s;
}

/// A number in scientific notation, for RecordProperty.
std::string scientific(Real value)
{
    std::ostringstream s;
    s << std::scientific << std::setprecision(2) << value;
    return s.str();
}

Real largestRelativeDifference = 0; // over the expectClose calls of a test (reported)

void expectClose(const Vec3& a, const Vec3& b, Real scale, const char* what, int stepIndex)
{
    largestRelativeDifference = std::max(largestRelativeDifference, length(a - b) / scale);
    EXPECT_LE(length(a - b), 1e-9 * scale) << what << " at step " << stepIndex << ": " << a.x << " " << a.y
                                           << " " << a.z << " vs " << b.x << " " << b.y << " " << b.z;
}

/// Two spheres, their initial positions, velocities and spins.
struct TwoSpheres
{
    Vec3 x0, x1, v0, v1, w0, w1;
};

World twoSphereWorld(const TwoSpheres& t, const PeriodicDomain* domain, Real skin, Real kn)
{
    World world = emptyWorld(kn);
    if (domain)
        world.domain = *domain;
    world.neighbors.skin = skin;
    world.particles.add(t.x0, t.v0, t.w0, 0.001, 2500, 0);
    world.particles.add(t.x1, t.v1, t.w1, 0.001, 2500, 0);
    return world;
}

/// (ii) A sliding pair touching through the face x = 0 gives, step after step, the force, torques
/// and tangential spring of the same pair moved by L/2 into the interior of a box without periodic
/// axes.
TEST(PeriodicBoundary, APairAcrossAFaceFeelsTheContactOfTheSamePairInTheInterior)
{
    const Real edge = 0.02, dt = 1e-7;
    largestRelativeDifference = 0;
    const PeriodicDomain periodic = box(edge, {true, true, true});
    // Sphere 0 just inside x = 0, sphere 1 just inside x = L: 1.99 mm apart through the face
    // (overlap 10 um), approaching along x and sliding in y and z.
    TwoSpheres across{{0.0006, 0.01, 0.01}, {edge - 0.00139, 0.0101, 0.0099},
                      {-0.02, 0.1, 0.05},   {0.02, -0.1, -0.05},
                      {0, 0, 30},           {10, 0, 0}};
    TwoSpheres inside = across;
    inside.x0.x += edge / 2;
    inside.x1.x += edge / 2 - edge;
    World a = twoSphereWorld(across, &periodic, 0.0005, 1000);
    World b = twoSphereWorld(inside, nullptr, 0.0005, 1000);
    int touching = 0;
    Real largestSpring = 0;
    for (int s = 1; s <= 300; ++s)
    {
        step(a, dt);
        step(b, dt);
        const PairState pa = pairState(a), pb = pairState(b);
        ASSERT_EQ(pa.touching, pb.touching) << s;
        touching += pa.touching;
        const Real scale = length(pb.force0) + 1e-30;
        expectClose(pa.force0, pb.force0, scale, "force on 0", s);
        expectClose(pa.force1, pb.force1, scale, "force on 1", s);
        expectClose(pa.torque0, pb.torque0, scale * 0.001, "torque on 0", s); // lever ~ r = 1 mm
        expectClose(pa.torque1, pb.torque1, scale * 0.001, "torque on 1", s);
        expectClose(pa.spring, pb.spring, length(pb.spring) + 1e-30, "spring", s);
        largestSpring = std::max(largestSpring, length(pb.spring));
    }
    EXPECT_FALSE(a.periodicPairs.empty()); // the pair was through an image
    EXPECT_EQ(b.periodicPairs.size(), 0u); // and direct in the other world
    EXPECT_EQ(touching, 300);              // in contact throughout
    EXPECT_GT(largestSpring, 0);           // with a tangential spring
    ::testing::Test::RecordProperty("largest_relative_difference", scientific(largestRelativeDifference));
}

/// (iii) A sliding contact carried across the face x = L by the pair's common motion: one sphere
/// wraps at one list rebuild, the other at a later one, so the pair goes from the neighbour list to
/// the periodic pairs and back while it touches. Its force and spring follow those of the same pair
/// in a world without periodic axes, continuously (no reset of the spring at a wrap).
TEST(PeriodicBoundary, ASlidingContactKeepsItsSpringWhenAParticleWraps)
{
    const Real edge = 0.02, dt = 1e-6;
    largestRelativeDifference = 0;
    const PeriodicDomain periodic = box(edge, {true, false, false});
    // 1.99 mm apart: 0.9 mm in x, 1.775 mm in y; both moving at 10 m/s in x, sliding in z.
    const Real dy = std::sqrt(0.00199 * 0.00199 - 0.0009 * 0.0009);
    TwoSpheres t{{edge - 0.0001, 0.01, 0.01},
                 {edge - 0.001, 0.01 + dy, 0.01},
                 {10, 0.01, 0.05},
                 {10, -0.01, -0.05},
                 {0, 0, 0},
                 {0, 0, 0}};
    World a = twoSphereWorld(t, &periodic, 0.0002, 100);
    World b = twoSphereWorld(t, nullptr, 0.0002, 100);
    int touching = 0, throughImage = 0, directAfterImage = 0;
    for (int s = 1; s <= 250; ++s)
    {
        step(a, dt);
        step(b, dt);
        const PairState pa = pairState(a), pb = pairState(b);
        ASSERT_TRUE(pa.touching && pb.touching) << s; // in contact throughout
        ++touching;
        throughImage += !a.periodicPairs.empty();
        directAfterImage += throughImage > 0 && a.periodicPairs.empty();
        const Real scale = length(pb.force0);
        expectClose(pa.force0, pb.force0, scale, "force on 0", s);
        expectClose(pa.torque0, pb.torque0, scale * 0.001, "torque on 0", s);
        expectClose(pa.spring, pb.spring, length(pb.spring), "spring", s);
        EXPECT_GT(length(pa.spring), 0) << s;
        // Positions: a's are b's wrapped (to rounding of the wrap, ~1e-18 m).
        const Vec3 expected = wrapPosition(periodic, b.particles.position[0]);
        EXPECT_NEAR(length(wrapPosition(periodic, a.particles.position[0]) - expected), 0, 1e-15) << s;
    }
    EXPECT_GT(throughImage, 0);     // the pair went through an image
    EXPECT_GT(directAfterImage, 0); // and came back to the neighbour list
    ::testing::Test::RecordProperty("largest_relative_difference", scientific(largestRelativeDifference));
}

/// A pair touching through a face keeps its contact when a particle is removed and the pair's
/// order flips ((1, 2) becomes (0, 1) with particle 2 moved to index 0): its spring and image shift
/// are negated with it, so the contact goes on as in a world that never had the third particle.
TEST(PeriodicBoundary, APairThroughAFaceKeepsItsContactWhenRenamed)
{
    const Real edge = 0.02, dt = 1e-7;
    largestRelativeDifference = 0;
    const PeriodicDomain periodic = box(edge, {true, true, true});
    const TwoSpheres across{{0.0006, 0.01, 0.01}, {edge - 0.00139, 0.0101, 0.0099},
                            {-0.02, 0.1, 0.05},   {0.02, -0.1, -0.05},
                            {0, 0, 30},           {10, 0, 0}};
    World pair = twoSphereWorld(across, &periodic, 0.0005, 1000);
    World three = emptyWorld(1000);
    three.domain = periodic;
    three.neighbors.skin = 0.0005;
    three.particles.add({0.01, 0.01, 0.01}, {}, {}, 0.001, 2500, 0); // far from both, at rest
    three.particles.add(across.x0, across.v0, across.w0, 0.001, 2500, 0);
    three.particles.add(across.x1, across.v1, across.w1, 0.001, 2500, 0);
    for (int s = 0; s < 100; ++s)
    {
        step(pair, dt);
        step(three, dt);
    }
    ASSERT_EQ(three.periodicPairs.size(), 1u);
    ASSERT_EQ(three.periodicPairs.second[0], 2u);
    removeParticles(three, {0}); // particle 2 takes index 0: the pair is (0, 1), its order flipped
    rebuildAfterParticleChange(three);
    ASSERT_EQ(three.periodicPairs.size(), 1u);
    EXPECT_EQ(three.periodicPairs.first[0], 0u);
    EXPECT_NE(length(three.periodicPairs.history.spring[0]), 0);
    for (int s = 1; s <= 200; ++s)
    {
        step(pair, dt);
        step(three, dt);
        ASSERT_EQ(three.health.touchingPairs, 1u) << s;
        // three's particle 0 is pair's 1 and its 1 is pair's 0; the spring is that of (1, 0).
        const Real scale = length(pair.particles.force[0]);
        expectClose(three.particles.force[1], pair.particles.force[0], scale, "force", s);
        expectClose(three.particles.force[0], pair.particles.force[1], scale, "force", s);
        expectClose(three.particles.torque[1], pair.particles.torque[0], scale * 0.001, "torque", s);
        expectClose(three.periodicPairs.history.spring[0], -pair.periodicPairs.history.spring[0],
                    length(pair.periodicPairs.history.spring[0]), "spring", s);
    }
    ::testing::Test::RecordProperty("largest_relative_difference", scientific(largestRelativeDifference));
}

/// (iv) A fully periodic box of colliding spheres: the pair forces are equal and opposite, also
/// through the faces, so the total momentum stays at its initial value to rounding. Each step adds
/// to each particle's momentum m (dt/2 F/m) twice, rounded to ~1e-16 of the particle's momentum,
/// so after 2000 steps the drift is ~1e-16 sqrt(N steps) of sum m|v|: 1e-12 of it is the bound.
TEST(PeriodicBoundary, AFullyPeriodicBoxConservesMomentum)
{
    World world = emptyWorld(1000);
    const Real edge = 0.016, spacing = 0.0021;
    world.domain = box(edge, {true, true, true});
    world.neighbors.skin = 0.0004;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<Real> speed(-0.5, 0.5), jitter(-0.00004, 0.00004);
    const int side = 7; // 343 spheres, 7 x 2.1 mm = 14.7 mm of a 16 mm box
    for (int z = 0; z < side; ++z)
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                world.particles.add({(x + 0.5) * spacing + jitter(random),
                                     (y + 0.5) * spacing + jitter(random),
                                     (z + 0.5) * spacing + jitter(random)},
                                    {speed(random), speed(random), speed(random)}, {}, 0.001, 2500, 0);
    const auto momentum = [&]
    {
        Vec3 total{};
        Real scale = 0;
        for (std::size_t i = 0; i < world.particles.size(); ++i)
        {
            total += world.particles.mass[i] * world.particles.velocity[i];
            scale += world.particles.mass[i] * length(world.particles.velocity[i]);
        }
        return std::pair{total, scale};
    };
    const auto [initial, scale] = momentum();
    std::size_t throughFaces = 0;
    for (int s = 0; s < 2000; ++s)
    {
        step(world, 1e-5);
        for (std::size_t k = 0; k < world.periodicPairs.size(); ++k)
            throughFaces += world.periodicPairs.history.formed[k];
    }
    const auto [after, afterScale] = momentum();
    EXPECT_LE(length(after - initial), 1e-12 * scale) << length(after - initial) / scale;
    ::testing::Test::RecordProperty("relative_momentum_drift", scientific(length(after - initial) / scale));
    EXPECT_GT(throughFaces, 100u);                 // contacts through the faces took part
    for (const Vec3& x : world.particles.position) // within skin/2 of the box
        for (const Real c : {x.x, x.y, x.z})
        {
            EXPECT_GT(c, -0.0002);
            EXPECT_LT(c, edge + 0.0002);
        }
}

} // namespace
} // namespace veridem::dem
