// Per-species measures (dem/species_measures.h) on particles placed by hand: each material's
// count, mass and centre of mass, and the counts in zones that are boxes, half-spaces (infinite
// bounds) and quadrants, with a centre on a bound counted in (lo <= x <= hi).
#include "dem/species_measures.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <limits>

namespace veridem::dem
{
namespace
{

World twoSpecies()
{
    World world;
    for (const char* name : {"M1", "M2"})
    {
        Material m;
        m.name = name;
        m.normalStiffness = 1e4;
        world.addMaterial(m);
    }
    // M1: radius 1 mm at (1,0,1), (-1,0,-1), (2,0,2) cm; M2: radius 2 mm at (0,0,0) and (-3,0,1) cm.
    world.particles.add({0.01, 0, 0.01}, {}, {}, 0.001, 2500, 0);
    world.particles.add({-0.01, 0, -0.01}, {}, {}, 0.001, 2500, 0);
    world.particles.add({0.02, 0, 0.02}, {}, {}, 0.001, 2500, 0);
    world.particles.add({0, 0, 0}, {}, {}, 0.002, 2000, 1);
    world.particles.add({-0.03, 0, 0.01}, {}, {}, 0.002, 2000, 1);
    return world;
}

TEST(SpeciesMeasures, CountMassAndCentreOfMassPerMaterial)
{
    const World world = twoSpecies();
    const std::vector<SpeciesMeasure> s = measureSpecies(world.particles, 2);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].count, 3u);
    EXPECT_EQ(s[1].count, 2u);
    const Real pi = 3.14159265358979323846;
    const Real m1 = 2500 * 4.0 / 3.0 * pi * 1e-9, m2 = 2000 * 4.0 / 3.0 * pi * 8e-9; // [kg]
    // Sums of a few doubles: equal to 1e-14 relative.
    EXPECT_NEAR(s[0].mass, 3 * m1, 1e-14 * m1);
    EXPECT_NEAR(s[1].mass, 2 * m2, 1e-14 * m2);
    // Equal masses within a species: the centre is the mean position.
    EXPECT_NEAR(s[0].centre.x, 0.02 / 3, 1e-15);
    EXPECT_NEAR(s[0].centre.z, 0.02 / 3, 1e-15);
    EXPECT_NEAR(s[1].centre.x, -0.015, 1e-15);
    EXPECT_NEAR(s[1].centre.z, 0.005, 1e-15);
    // A material with no particles has count 0 and its centre at the origin.
    EXPECT_EQ(measureSpecies(world.particles, 3)[2].count, 0u);
}

TEST(SpeciesMeasures, ZonesAreBoxesWithPossiblyInfiniteBounds)
{
    const World world = twoSpecies();
    constexpr Real inf = std::numeric_limits<Real>::infinity();
    // The DEM8 drum's zone 1 (x > 0 and z > 0) and zone 2 (x < 0 and z < 0) as quadrants.
    const Zone one{"zone1", {0, -inf, 0}, {inf, inf, inf}, {0, 1}};
    const Zone two{"zone2", {-inf, -inf, -inf}, {0, inf, 0}, {1, 0}};
    EXPECT_EQ(countInZone(world.particles, one),
              (std::vector<std::uint64_t>{2, 1})); // (the M2 at 0 is on both bounds)
    EXPECT_EQ(countInZone(world.particles, two), (std::vector<std::uint64_t>{1, 1})); // (M2 first, as listed)
    // A half-space z >= 0.015 holds one M1 only; a box around nothing holds none.
    EXPECT_EQ(countInZone(world.particles, Zone{"top", {-inf, -inf, 0.015}, {inf, inf, inf}, {0, 1}}),
              (std::vector<std::uint64_t>{1, 0}));
    EXPECT_EQ(countInZone(world.particles, Zone{"none", {1, 1, 1}, {2, 2, 2}, {0}}),
              (std::vector<std::uint64_t>{0}));
}

TEST(SpeciesMeasures, ARetiredParticleIsNeitherASpeciesMemberNorInAZone)
{
    // An outlet's particle keeps its slot, with radius 0, until the next list rebuild
    // (ParticleStore::retired): it has left the scene, so no measure counts it.
    World world = twoSpecies();
    world.particles.radius[0] = 0; // the M1 bead at (1, 0, 1) cm, retired
    const std::vector<SpeciesMeasure> s = measureSpecies(world.particles, 2);
    EXPECT_EQ(s[0].count, 2u);
    Zone all;
    all.name = "all";
    all.lo = {-1, -1, -1};
    all.hi = {1, 1, 1};
    all.materials = {0, 1};
    const std::vector<std::uint64_t> counts = countInZone(world.particles, all);
    EXPECT_EQ(counts[0], 2u);
    EXPECT_EQ(counts[1], 2u);
}

} // namespace
} // namespace veridem::dem
