// The Verlet list finds exactly the pairs a brute-force search finds, stays sorted, and carries
// history over a rebuild by (i, j).
#include "dem/neighbor_list.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace veridem;
using namespace veridem::dem;

namespace
{
ParticleStore randomParticles(std::size_t n, unsigned seed)
{
    ParticleStore p;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(0, 0.05), r(0.5e-3, 1.5e-3);
    for (std::size_t i = 0; i < n; ++i)
        p.add({x(rng), x(rng), x(rng)}, {}, {}, r(rng), 2500, 0);
    return p;
}
} // namespace

TEST(NeighborList, MatchesBruteForce)
{
    const ParticleStore p = randomParticles(2000, 1);
    NeighborList list;
    list.skin = 0.3e-3;
    list.rebuild(p);
    std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        for (std::uint32_t j = i + 1; j < p.size(); ++j)
        {
            const double reach = p.radius[i] + p.radius[j] + list.skin;
            if (lengthSquared(p.position[i] - p.position[j]) < reach * reach)
                expected.insert({i, j});
        }
    ASSERT_EQ(list.size(), expected.size());
    std::size_t k = 0;
    for (const auto& [i, j] : expected)
    {
        EXPECT_EQ(list.first[k], i);
        EXPECT_EQ(list.second[k], j);
        ++k;
    }
}

TEST(NeighborList, HistorySurvivesRebuild)
{
    ParticleStore p = randomParticles(500, 2);
    NeighborList list;
    list.skin = 0.5e-3;
    list.rebuild(p);
    ASSERT_GT(list.size(), 0u);
    for (std::size_t k = 0; k < list.size(); ++k)
        list.tangentialSpring[k] = {double(list.first[k]), double(list.second[k]), 0};
    list.rebuild(p);
    for (std::size_t k = 0; k < list.size(); ++k)
    {
        EXPECT_EQ(list.tangentialSpring[k].x, double(list.first[k]));
        EXPECT_EQ(list.tangentialSpring[k].y, double(list.second[k]));
    }
}

TEST(NeighborList, RebuildNeededAfterHalfSkin)
{
    ParticleStore p = randomParticles(10, 3);
    NeighborList list;
    list.skin = 1e-3;
    list.rebuild(p);
    EXPECT_FALSE(list.needsRebuild(p));
    p.position[3].x += 0.6e-3;
    EXPECT_TRUE(list.needsRebuild(p));
}
