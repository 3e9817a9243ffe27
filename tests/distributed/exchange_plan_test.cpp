// The exchange plan (distributed/exchange_plan.h): after it, every rank holds, as owned particles or
// ghosts, both particles of every pair that can touch one of its own (brute force over all
// pairs), ghosts go only where a region is within range, and migrants go to their owner.
#include "core/error.h"
#include "distributed/exchange_plan.h"
#include "point_clouds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace veridem;
using namespace veridem::distributed;

TEST(ExchangePlan, EveryRankHoldsBothParticlesOfEachOfItsPairs)
{
    const auto cloud = clouds::makeCloud(2000, 9);
    const std::size_t n = cloud.position.size();
    std::vector<Real> radius(n);
    for (std::size_t i = 0; i < n; ++i)
        radius[i] = 0.5e-3 + 0.25e-3 * (cloud.weight[i] % 3); // 0.5-1 mm
    const Real search = 0.2e-3, rMax = 1e-3, halo = rMax + search;
    for (int parts : {2, 3, 5})
    {
        const Decomposition d = bisect(cloud.position, cloud.weight, parts, SerialCollective{});
        // Before the exchange, rank q holds the particles i with i % parts == q (any split).
        std::vector<std::set<std::uint32_t>> holds(parts), owns(parts);
        for (int q = 0; q < parts; ++q)
        {
            std::vector<std::uint32_t> mine;
            std::vector<Vec3> x;
            std::vector<Real> r;
            for (std::size_t i = q; i < n; i += parts)
            {
                mine.push_back(std::uint32_t(i));
                x.push_back(cloud.position[i]);
                r.push_back(radius[i]);
            }
            const ExchangePlan plan = planExchange(d, q, x, r, halo);
            ASSERT_TRUE(plan.migrate[q].empty());
            ASSERT_TRUE(plan.ghost[q].empty());
            std::vector<char> leaves(mine.size(), 0);
            for (int b = 0; b < parts; ++b)
                for (std::uint32_t k : plan.migrate[b])
                {
                    ASSERT_EQ(d.owner(x[k]), b); // to its owner
                    leaves[k] = 1;
                }
            for (std::size_t k = 0; k < mine.size(); ++k)
                if (!leaves[k])
                {
                    ASSERT_EQ(d.owner(x[k]), q); // the others are this rank's own
                    owns[q].insert(mine[k]);
                    holds[q].insert(mine[k]);
                }
            // Ghosts: exactly where another region is within r + halo (brute force over regions).
            for (int b = 0; b < parts; ++b)
            {
                std::vector<std::uint32_t> expected;
                for (std::size_t k = 0; k < mine.size(); ++k)
                    if (!leaves[k] && b != q &&
                        distanceSquared(d.region[b], x[k]) < (r[k] + halo) * (r[k] + halo))
                        expected.push_back(std::uint32_t(k));
                ASSERT_EQ(plan.ghost[b], expected);
                for (std::uint32_t k : plan.ghost[b])
                    holds[b].insert(mine[k]);
            }
        }
        // Migrants' ghosts are sent by their new owner (a second plan there); here: each rank
        // also holds the ghosts its owned particles need, so complete the picture with the
        // plans of the owners over what they own.
        for (int q = 0; q < parts; ++q)
        {
            std::vector<Vec3> x;
            std::vector<Real> r;
            std::vector<std::uint32_t> ids(owns[q].begin(), owns[q].end());
            for (std::uint32_t i = 0; i < n; ++i)
                if (d.owner(cloud.position[i]) == q && !owns[q].count(i))
                    ids.push_back(i); // arrived by migration
            for (std::uint32_t i : ids)
            {
                x.push_back(cloud.position[i]);
                r.push_back(radius[i]);
                holds[q].insert(i);
            }
            const ExchangePlan plan = planExchange(d, q, x, r, halo);
            for (int b = 0; b < parts; ++b)
            {
                ASSERT_TRUE(plan.migrate[b].empty()); // all its particles are its own now
                for (std::uint32_t k : plan.ghost[b])
                    holds[b].insert(ids[k]);
            }
        }
        int pairs = 0, acrossRanks = 0;
        for (std::uint32_t i = 0; i < n; ++i)
            for (std::uint32_t j = i + 1; j < n; ++j)
            {
                const Real within = radius[i] + radius[j] + search;
                if (lengthSquared(cloud.position[i] - cloud.position[j]) >= within * within)
                    continue;
                ++pairs;
                const int a = d.owner(cloud.position[i]), b = d.owner(cloud.position[j]);
                acrossRanks += a != b;
                ASSERT_TRUE(holds[a].count(j)) << parts << " parts: rank " << a << " lacks " << j;
                ASSERT_TRUE(holds[b].count(i)) << parts << " parts: rank " << b << " lacks " << i;
            }
        EXPECT_GT(pairs, 100);
        EXPECT_GT(acrossRanks, 0); // (the check sees pairs across a boundary)
    }
}

TEST(ExchangePlan, RefusesBadArguments)
{
    const Decomposition d = bisect({}, {}, 2, SerialCollective{});
    EXPECT_THROW(planExchange(d, 2, {}, {}, 1e-3), InputError);
    EXPECT_THROW(planExchange(d, 0, {}, {}, 0), InputError);
    const std::vector<Vec3> x(1);
    EXPECT_THROW(planExchange(d, 0, x, {}, 1e-3), InputError);
}
