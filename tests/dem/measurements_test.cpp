// The measurements (docs/measurements.md) against hand-computable configurations: a simple cubic
// lattice of spheres under a known overlap (coordination 6, packing fraction 4 pi r^3 / (3 a^3) in
// any box of whole cells, Love-Weber stress -kn delta / a^2, elastic energy kn delta^2 / 2 per
// contact); the kinetic stress of two free particles; the diagnostic
// pass and the ledger's observer leave the run's bits unchanged; the ledger of a head-on
// collision balances.
#include "dem/contact_diagnostics.h"
#include "dem/energy_ledger.h"
#include "dem/region_measures.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace veridem::dem
{
namespace
{

constexpr Real kR = 1e-3, kKn = 1e4, kDelta = 1e-5; // radius [m], stiffness [N/m], overlap [m]
constexpr Real kA = 2 * kR - kDelta;                // lattice spacing [m]

/// 5 x 5 x 5 spheres on a simple cubic lattice of spacing a = 2r - delta, at rest, no gravity.
World cubicLattice()
{
    World world;
    Material m;
    m.name = "steel";
    m.normalStiffness = kKn;
    world.addMaterial(m);
    world.gravity = {0, 0, 0};
    for (int z = 0; z < 5; ++z)
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 5; ++x)
                world.particles.add({x * kA, y * kA, z * kA}, {}, {}, kR, 7800, 0);
    prepare(world);
    return world;
}

TEST(Measurements, CubicLatticeRegion)
{
    const World world = cubicLattice();
    const std::vector<ContactRecord> contacts = evaluateContacts(world, 0.0);
    ASSERT_EQ(contacts.size(), 3u * 5 * 5 * 4); // 4 bonds per line, 25 lines, 3 directions
    // The box through the contact points around the central 3 x 3 x 3 spheres: three lattice
    // cells a side, so the spheres' parts inside it add up to 27 spheres (periodicity).
    const Vec3 lo{0.5 * kA, 0.5 * kA, 0.5 * kA}, hi{3.5 * kA, 3.5 * kA, 3.5 * kA};
    const RegionMeasures m = measureRegion(world, contacts, lo, hi);
    EXPECT_EQ(m.particles, 27u);
    EXPECT_EQ(m.contacts, 27u * 6);
    EXPECT_EQ(m.coordination, 6.0);
    // The exact volume of each sphere in the box: 1e-13 of a sphere each (sphere_box_volume.h).
    const Real phi = 4.0 / 3.0 * kPi * kR * kR * kR / (kA * kA * kA);
    EXPECT_NEAR(m.packingFraction, phi, 1e-13 * phi);
    EXPECT_NEAR(m.packingFraction, kPi / 6, 2e-2); // touching spheres: pi/6 (delta/r = 1 %)
    const Real sigma = -kKn * kDelta / (kA * kA);  // force kn delta per cell face a^2, compressive
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(m.stress[static_cast<std::size_t>(k)], sigma, 1e-12 * std::abs(sigma));
    for (int k = 3; k < 6; ++k)
        EXPECT_NEAR(m.stress[static_cast<std::size_t>(k)], 0.0, 1e-12 * std::abs(sigma));
    Real elastic = 0;
    for (const ContactRecord& c : contacts)
    {
        elastic += c.storedEnergy();
        EXPECT_NEAR(length(c.normalForce), kKn * kDelta, 1e-9 * kKn * kDelta); // delta from a difference
    }
    const Real expected = static_cast<Real>(contacts.size()) * 0.5 * kKn * kDelta * kDelta;
    EXPECT_NEAR(elastic, expected, 1e-8 * expected); // delta = 2r - |dx| loses ~1e-11 of delta
}

TEST(Measurements, PackingFractionOfAnyBoxOfWholeCells)
{
    // A box of 3 x 3 x 3 cells at any offset holds 27 spheres' worth of volume (the lattice is
    // periodic): phi = 4 pi r^3 / (3 a^3), which is pi/6 (1 + delta/a)^3 with spheres that
    // overlap by delta. The centre rule would count 27 +- 9 whole spheres here.
    const World world = cubicLattice();
    const std::vector<ContactRecord> contacts = evaluateContacts(world, 0.0);
    const Real phi = 4.0 / 3.0 * kPi * kR * kR * kR / (kA * kA * kA);
    for (const Vec3 offset : {Vec3{0.62, 0.81, 0.55}, Vec3{0.5, 0.999, 0.73}, Vec3{0.9, 0.6, 0.95}})
    {
        const Vec3 lo = kA * offset;
        const RegionMeasures m = measureRegion(world, contacts, lo, lo + Vec3{3 * kA, 3 * kA, 3 * kA});
        EXPECT_NEAR(m.packingFraction, phi, 1e-13 * phi) << offset.x;
        EXPECT_NEAR(m.packingFraction, kPi / 6 * std::pow(1 + kDelta / kA, 3), 1e-13 * phi);
    }
}

TEST(Measurements, KineticStressOfFreeParticles)
{
    // Two equal particles in the box with v1 = (1, 2, 0) and v2 = (3, 0, 0) m/s: mean (2, 1, 0),
    // fluctuations +-(-1, 1, 0); sum m v' v'^T = 2m [[1, -1, 0], [-1, 1, 0], [0, 0, 0]], so
    // sigma_k = -(2m / V) on xx and yy, +(2m / V) on xy, zero elsewhere. A third particle outside
    // the box, moving fast, does not count. No contacts: the stress is the kinetic part alone.
    World world;
    Material m;
    m.name = "steel";
    m.normalStiffness = kKn;
    world.addMaterial(m);
    world.particles.add({0.2, 0.2, 0.2}, {1, 2, 0}, {}, kR, 7800, 0);
    world.particles.add({0.6, 0.6, 0.6}, {3, 0, 0}, {}, kR, 7800, 0);
    world.particles.add({2.0, 0.5, 0.5}, {40, -7, 9}, {}, kR, 7800, 0);
    const Real volume = 1.0;
    const RegionMeasures r = measureRegion(world, {}, {0, 0, 0}, {1, 1, 1});
    const Real s = 2 * world.particles.mass[0] / volume;
    const std::array<Real, 6> expected = {-s, -s, 0, s, 0, 0};
    for (std::size_t k = 0; k < 6; ++k)
    {
        // Sums of a few products of exact small numbers: rounding ~1e-16 of s.
        EXPECT_NEAR(r.kineticStress[k], expected[k], 1e-15 * s) << k;
        EXPECT_EQ(r.contactStress[k], 0.0);
        EXPECT_EQ(r.stress[k], r.kineticStress[k]);
    }
    EXPECT_EQ(r.particles, 2u);
}

TEST(Measurements, EmptyRegion)
{
    const World world = cubicLattice();
    const RegionMeasures m = measureRegion(world, evaluateContacts(world, 0.0), {1, 1, 1}, {2, 2, 2});
    EXPECT_EQ(m.particles, 0u);
    EXPECT_EQ(m.coordination, 0.0);
    EXPECT_EQ(m.packingFraction, 0.0);
}

/// 216 spheres falling into a box with friction, EPSD rolling and a moving wall.
World pour()
{
    World world;
    Material m;
    m.name = "glass";
    m.normalStiffness = 1000;
    m.restitution = 0.5;
    m.friction = 0.5;
    m.rollingModel = RollingModel::Epsd;
    m.rollingFrictionLength = 1e-4;
    world.addMaterial(m);
    const auto plane = [&](Vec3 point, Vec3 normal, Vec3 velocity)
    {
        Wall w;
        w.shape = PlaneShape{point, normal};
        w.motion.velocity = velocity;
        world.walls.push_back(w);
    };
    plane({0, 0, 0}, {0, 0, 1}, {});
    plane({0, 0, 0}, {1, 0, 0}, {0.02, 0, 0});
    plane({0.0125, 0, 0}, {-1, 0, 0}, {});
    plane({0, 0, 0}, {0, 1, 0}, {});
    plane({0, 0.0125, 0}, {0, -1, 0}, {});
    std::mt19937_64 random(3);
    std::uniform_real_distribution<Real> speed(-0.2, 0.2);
    for (int z = 0; z < 6; ++z)
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 6; ++x)
                world.particles.add({(x + 0.5) * 2.05e-3, (y + 0.5) * 2.05e-3, (z + 0.6) * 2.05e-3},
                                    {speed(random), speed(random), speed(random)}, {}, 1e-3, 2500, 0);
    return world;
}

template <class V> bool sameBits(const std::vector<V>& a, const std::vector<V>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(V)) == 0;
}

TEST(Measurements, LedgerObserverLeavesTheBitsUnchanged)
{
    World plain = pour(), observed = pour();
    prepare(plain);
    prepare(observed);
    EnergyLedger ledger;
    ledger.start(observed);
    observed.observer = &ledger;
    advance(plain, 2e-5, 3000);
    advance(observed, 2e-5, 3000);
    EXPECT_TRUE(sameBits(plain.particles.position, observed.particles.position));
    EXPECT_TRUE(sameBits(plain.particles.velocity, observed.particles.velocity));
    EXPECT_TRUE(sameBits(plain.particles.angularVelocity, observed.particles.angularVelocity));
    // The ledger saw dissipation of every kind and balances (the bound: energy_ledger case).
    EXPECT_GT(ledger.state.normalDamping, 0);
    EXPECT_GT(ledger.state.friction, 0);
    EXPECT_GT(ledger.state.rolling, 0);
    EXPECT_NE(ledger.state.wallWork, 0);
    EXPECT_LT(std::abs(ledger.residual(observed)), 1e-2 * ledger.dissipated());
}

TEST(Measurements, HeadOnCollisionDissipatesTheKineticEnergyLost)
{
    World world;
    Material m;
    m.name = "glass";
    m.normalStiffness = 1e4;
    m.restitution = 0.7;
    world.addMaterial(m);
    world.gravity = {0, 0, 0};
    world.particles.add({-0.01, 0, 0}, {1, 0, 0}, {}, 5e-3, 2500, 0);
    world.particles.add({0.01, 0, 0}, {-1, 0, 0}, {}, 5e-3, 2500, 0);
    prepare(world);
    EnergyLedger ledger;
    ledger.start(world);
    world.observer = &ledger;
    const Real before = kineticEnergy(world);
    // m* = 0.65 g, kn = 1e4: t_c ~ 8e-4 s; dt = t_c / 100.
    for (int s = 0; s < 3000; ++s)
        step(world, 8e-6);
    const Real after = kineticEnergy(world);
    // Separated: no elastic energy left; the normal dashpot took (1 - e^2) of the energy (e to
    // 0.3 %, BENCHMARKS 2.1), and the ledger's D_normal equals the kinetic energy lost to O(dt^2).
    EXPECT_EQ(ledger.state.elasticEnergy, 0.0);
    EXPECT_NEAR(ledger.state.normalDamping, before - after, 1e-3 * (before - after));
    EXPECT_NEAR(ledger.state.normalDamping, (1 - 0.49) * before, 1e-2 * before);
}

} // namespace
} // namespace veridem::dem
