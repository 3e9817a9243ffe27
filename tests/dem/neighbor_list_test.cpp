// The Verlet list finds exactly the pairs a brute-force search finds, stays sorted, and carries
// history over a rebuild by (i, j) and over a new candidate sub-list by slot.
#include "dem/neighbor_list.h"
#include "dem/pair_search.h"
#include "exec/thread_pool.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
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
    ContactHistoryStore history{true};
    list.skin = 0.3e-3;
    list.rebuild(p, history);
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

/// Size classes (dem/pair_search.h): a mixture with a size ratio of 10 (large and small spheres
/// and a spread between them, packed densely, and one sphere far away) gives exactly the
/// brute-force pairs, on one thread and on two.
TEST(NeighborList, SizeRatioTenMatchesBruteForce)
{
    EXPECT_EQ(sizeClassCount(1e-3, 2e-3), 1); // within a factor 2: one grid, as without classes
    EXPECT_EQ(sizeClassCount(0.99e-3, 2e-3), 2);
    EXPECT_EQ(sizeClassCount(0.2e-3, 2e-3), 4); // ratio 10: [1, 2), [0.5, 1), [0.25, 0.5), below
    ParticleStore p;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> x(0, 0.02), spread(0.2e-3, 2e-3);
    for (int i = 0; i < 3000; ++i)
    {
        const double r = i % 3 == 0 ? 2e-3 : i % 3 == 1 ? 0.2e-3 : spread(rng);
        p.add({x(rng), x(rng), x(rng)}, {}, {}, r, 2500, 0);
    }
    p.add({1.0, 1.0, 1.0}, {}, {}, 0.2e-3, 2500, 0);
    std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
    const double skin = 0.1e-3;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        for (std::uint32_t j = i + 1; j < p.size(); ++j)
        {
            const double reach = p.radius[i] + p.radius[j] + skin;
            if (lengthSquared(p.position[i] - p.position[j]) < reach * reach)
                expected.insert({i, j});
        }
    for (const int threads : {1, 2})
    {
        exec::ThreadCountOverride override(threads);
        NeighborList list;
        ContactHistoryStore history{true};
        list.skin = skin;
        list.rebuild(p, history);
        ASSERT_EQ(list.size(), expected.size()) << threads << " threads";
        std::size_t k = 0;
        for (const auto& [i, j] : expected)
        {
            ASSERT_EQ(list.first[k], i);
            ASSERT_EQ(list.second[k], j);
            ++k;
        }
    }
}

/// A value per (i, j) to store as history and find again.
Vec3 keyValue(std::uint32_t i, std::uint32_t j)
{
    return {double(i), double(j), 1.0};
}

TEST(NeighborList, HistorySurvivesRebuild)
{
    ParticleStore p = randomParticles(500, 2);
    NeighborList list;
    ContactHistoryStore history{true};
    list.skin = 0.5e-3;
    list.rebuild(p, history);
    list.refreshActiveSlots(p, history);
    ASSERT_GT(list.activeSlots.size(), 0u);
    std::set<std::pair<std::uint32_t, std::uint32_t>> held;
    for (std::size_t a = 0; a < list.activeSlots.size(); ++a)
    {
        history.spring[a] = keyValue(list.activeFirst[a], list.activeSecond[a]);
        held.insert({list.activeFirst[a], list.activeSecond[a]});
    }
    list.rebuild(p, history);
    // Between the rebuild and the next sub-list, a slot's history is found by (i, j).
    for (std::size_t k = 0; k < list.size(); ++k)
    {
        const bool wasHeld = held.count({list.first[k], list.second[k]}) > 0;
        const std::size_t a = list.candidateOfSlot(k);
        EXPECT_EQ(a == NeighborList::kNotCandidate ? Vec3{} : history.spring[a],
                  wasHeld ? keyValue(list.first[k], list.second[k]) : Vec3{});
    }
    list.refreshActiveSlots(p, history);
    std::size_t carried = 0;
    for (std::size_t a = 0; a < list.activeSlots.size(); ++a)
    {
        const std::uint32_t i = list.activeFirst[a], j = list.activeSecond[a];
        const bool wasHeld = held.count({i, j}) > 0;
        carried += wasHeld ? 1 : 0;
        EXPECT_EQ(history.spring[a], wasHeld ? keyValue(i, j) : Vec3{}) << i << " " << j;
    }
    EXPECT_EQ(carried, held.size()); // same positions: every candidate is one again
}

/// A new candidate sub-list over the same slots (particles moved less than skin/2) carries each
/// continuing candidate's history and flag to its new place, moving entries both towards the
/// front and towards the back of the arrays (in place), starts new candidates at zero, and zeroes
/// the deferred entry of a candidate left out while it may have been in contact.
TEST(NeighborList, HistoryFollowsItsSlotToANewSubList)
{
    ParticleStore p = randomParticles(3000, 4); // three blocks: cross-block slots
    NeighborList list;
    ContactHistoryStore history{true};
    list.skin = 0.5e-3;
    list.rebuild(p, history);
    list.refreshActiveSlots(p, history);
    ASSERT_GT(list.deferred.size(), 0u);
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> oldIndex;
    for (std::size_t a = 0; a < list.activeSlots.size(); ++a)
    {
        const std::uint32_t i = list.activeFirst[a], j = list.activeSecond[a];
        history.spring[a] = keyValue(i, j);
        history.formed[a] = static_cast<std::uint8_t>(a % 2); // half may be in contact
        if (list.activeDeferred[a] != NeighborList::kInBlock)
            list.deferred[list.activeDeferred[a]].force = Vec3{1, 2, 3};
        oldIndex[{i, j}] = a;
    }
    const std::vector<std::uint32_t> oldDeferred = list.activeDeferred;
    const std::vector<std::uint8_t> oldFlag = history.formed;

    // Let the sub-list age past 128 steps (its inner skin is then halved: candidates leave), jitter
    // by up to 0.1 mm (< skin/2, so the slots stay valid: candidates join), then a new sub-list.
    for (int s = 0; s < 128; ++s)
        list.refreshActiveSlots(p, history);
    ASSERT_EQ(list.activeRebuildCount(), 1u);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.1e-3 / std::sqrt(3.0), 0.1e-3 / std::sqrt(3.0));
    for (Vec3& x : p.position)
        x += Vec3{jitter(rng), jitter(rng), jitter(rng)};
    ASSERT_FALSE(list.checkMotion(p.size(), 0.0, 1.0)); // the sub-list is stale, the slots are not
    list.refreshActiveSlots(p, history);

    std::size_t forward = 0, backward = 0, fresh = 0;
    std::set<std::size_t> continued;
    for (std::size_t a = 0; a < list.activeSlots.size(); ++a)
    {
        const std::uint32_t i = list.activeFirst[a], j = list.activeSecond[a];
        const auto found = oldIndex.find({i, j});
        if (found == oldIndex.end())
        {
            ++fresh;
            EXPECT_EQ(history.spring[a], Vec3{});
            EXPECT_EQ(history.formed[a], 0);
            continue;
        }
        const std::size_t b = found->second;
        continued.insert(b);
        forward += b > a ? 1 : 0; // the entry moved towards the front
        backward += b < a ? 1 : 0;
        EXPECT_EQ(history.spring[a], keyValue(i, j));
        EXPECT_EQ(history.formed[a], oldFlag[b]);
    }
    EXPECT_GT(forward, 0u);
    EXPECT_GT(backward, 0u);
    EXPECT_GT(fresh, 0u);
    std::size_t zeroed = 0;
    for (const auto& [key, b] : oldIndex)
        if (!continued.count(b) && oldDeferred[b] != NeighborList::kInBlock)
        {
            const Vec3 expected = oldFlag[b] ? Vec3{} : Vec3{1, 2, 3};
            EXPECT_EQ(list.deferred[oldDeferred[b]].force, expected);
            zeroed += oldFlag[b];
        }
    EXPECT_GT(zeroed, 0u);
}

/// A contact whose pair leaves the list altogether (no slots left, so no sub-list is rebuilt until
/// slots return) must not hand its old history to the pair when it comes back.
TEST(NeighborList, HistoryOfAPairThatLeftTheListIsForgotten)
{
    ParticleStore p;
    p.add({0, 0, 0}, {}, {}, 1e-3, 2500, 0);
    p.add({1.9e-3, 0, 0}, {}, {}, 1e-3, 2500, 0); // touching
    NeighborList list;
    ContactHistoryStore history{true};
    list.skin = 0.5e-3;
    list.rebuild(p, history);
    list.refreshActiveSlots(p, history);
    ASSERT_EQ(list.activeSlots.size(), 1u);
    history.spring[0] = {1e-6, 0, 0};
    history.formed[0] = 1;
    p.position[1] = {10e-3, 0, 0}; // far apart: no slot
    list.rebuild(p, history);
    ASSERT_EQ(list.size(), 0u);
    p.position[1] = {1.9e-3, 0, 0}; // back in contact
    list.rebuild(p, history);
    list.refreshActiveSlots(p, history);
    ASSERT_EQ(list.activeSlots.size(), 1u);
    EXPECT_EQ(history.spring[0], Vec3{});
    EXPECT_EQ(history.formed[0], 0);
}

TEST(NeighborList, RebuildNeededAfterHalfSkin)
{
    ParticleStore p = randomParticles(10, 3);
    NeighborList list;
    ContactHistoryStore history{true};
    list.skin = 1e-3;
    list.rebuild(p, history);
    EXPECT_FALSE(list.needsRebuild(p));
    p.position[3].x += 0.6e-3;
    EXPECT_TRUE(list.needsRebuild(p));
}
