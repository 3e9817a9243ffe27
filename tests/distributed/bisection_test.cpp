// Recursive coordinate bisection (distributed/bisection.h) in one process: the regions tile space, each
// particle has one owner, the parts' costs are balanced to the bound the cut guarantees, and the
// ghost query equals a brute-force search. The same on MPI ranks: mpi_bisection_check.cpp.
#include "core/error.h"
#include "distributed/bisection.h"
#include "point_clouds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

using namespace veridem;
using namespace veridem::distributed;

namespace
{

bool inside(const Box& b, const Vec3& x)
{
    for (int a = 0; a < 3; ++a)
        if (!(component(x, a) >= component(b.lo, a) && component(x, a) < component(b.hi, a)))
            return false;
    return true;
}

int depth(int parts)
{
    int d = 0;
    while ((1 << d) < parts)
        ++d;
    return d;
}

} // namespace

TEST(Bisection, EveryParticleHasOneOwnerWhoseRegionHoldsIt)
{
    const auto cloud = clouds::makeCloud(5000, 1);
    for (int parts : {1, 2, 3, 5, 8, 13})
    {
        const Decomposition d = bisect(cloud.position, cloud.weight, parts, SerialCollective{});
        ASSERT_EQ(d.parts(), parts);
        for (const Vec3& x : cloud.position)
        {
            int holders = 0;
            for (const Box& r : d.region)
                holders += inside(r, x);
            ASSERT_EQ(holders, 1) << parts << " parts";
            ASSERT_TRUE(inside(d.region[d.owner(x)], x));
        }
        // A point far outside the bounds still has exactly one region.
        const Vec3 far{10, -10, 10};
        int holders = 0;
        for (const Box& r : d.region)
            holders += inside(r, far);
        EXPECT_EQ(holders, 1);
    }
}

TEST(Bisection, PartsCarryTheirShareOfTheWeight)
{
    const auto cloud = clouds::makeCloud(20000, 2);
    const std::uint64_t total = std::accumulate(cloud.weight.begin(), cloud.weight.end(), std::uint64_t{0});
    for (int parts : {2, 3, 4, 7, 16})
    {
        const Decomposition d = bisect(cloud.position, cloud.weight, parts, SerialCollective{});
        // The costs it reports are its owners' weights.
        std::vector<std::uint64_t> owned(parts, 0);
        for (std::size_t i = 0; i < cloud.position.size(); ++i)
            owned[d.owner(cloud.position[i])] += cloud.weight[i];
        EXPECT_EQ(owned, d.cost);
        // Each cut is within the largest weight (8) of its target, plus 1 for the target's
        // rounding down; a part inherits at most one such error per level of the tree.
        const double bound = depth(parts) * (8.0 + 1.0);
        for (int p = 0; p < parts; ++p)
            EXPECT_LE(std::fabs(double(d.cost[p]) - double(total) / parts), bound)
                << parts << " parts, part " << p;
    }
}

TEST(Bisection, GhostQueryEqualsBruteForce)
{
    const auto cloud = clouds::makeCloud(3000, 3);
    const Decomposition d = bisect(cloud.position, cloud.weight, 6, SerialCollective{});
    const auto queries = clouds::makeCloud(2000, 4);
    for (const Real reach : {0.001, 0.01, 0.05})
        for (const Vec3& x : queries.position)
        {
            std::vector<int> found, expected;
            d.forEachPartNear(x, reach, [&](int p) { found.push_back(p); });
            for (int p = 0; p < d.parts(); ++p)
                if (distanceSquared(d.region[p], x) < reach * reach)
                    expected.push_back(p);
            ASSERT_EQ(found, expected);
            ASSERT_FALSE(found.empty()); // the owner at least
        }
}

namespace
{

/// The cloud's box periodic along `periodic`.
dem::PeriodicDomain cloudBox(std::array<bool, 3> periodic)
{
    dem::PeriodicDomain domain;
    domain.min = {0, 0, 0};
    domain.max = {0.2, 0.1, 0.05};
    domain.periodic = periodic;
    return domain;
}

/// The 27 shifts of +-1 box edge or none along each axis (0 along a non-periodic axis).
std::vector<Vec3> allImageShifts(const dem::PeriodicDomain& domain)
{
    std::vector<Vec3> shifts;
    const Vec3 edge = domain.length();
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k)
                shifts.push_back({domain.periodic[0] ? i * edge.x : 0, domain.periodic[1] ? j * edge.y : 0,
                                  domain.periodic[2] ? k * edge.z : 0});
    return shifts;
}

} // namespace

// A domain periodic along all three axes is cut across them (there is no other axis), and the
// ghost query looks through the faces: every part that owns a point of the box within `reach` of
// the query point or of one of its images is found (brute force over the 27 images and the parts'
// regions clipped to the box), and nothing beyond a region within `reach` of some image (the query
// may over-include a region near an image just outside the box: a ghost too many, never too few).
TEST(Bisection, PeriodicGhostQueryLooksThroughTheFaces)
{
    const dem::PeriodicDomain domain = cloudBox({true, true, true});
    EXPECT_EQ(cuttableAxes(domain), (std::array<bool, 3>{true, true, true}));
    const auto cloud = clouds::makeCloud(3000, 5);
    const Decomposition d = bisect(cloud.position, cloud.weight, 6, SerialCollective{}, domain);
    std::array<int, 3> cutsAlong{0, 0, 0};
    for (const Decomposition::Node& n : d.nodes)
        ++cutsAlong[static_cast<std::size_t>(n.axis)];
    EXPECT_GT(cutsAlong[0], 0); // the longest axis, x (0.2 m), is cut
    const std::vector<Vec3> shifts = allImageShifts(domain);
    const auto queries = clouds::makeCloud(2000, 6); // (in the box: wrapped, as RankStep leaves them)
    std::size_t throughFaces = 0;
    for (const Real reach : {0.001, 0.01, 0.02})
        for (const Vec3& x : queries.position)
        {
            std::vector<int> found, direct;
            d.forEachPartNear(x, reach, [&](int p) { found.push_back(p); });
            ASSERT_TRUE(std::is_sorted(found.begin(), found.end()));
            ASSERT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()); // each once
            for (int p = 0; p < d.parts(); ++p)
            {
                Box inBox = d.region[p]; // the part's points in the box
                for (int a = 0; a < 3; ++a)
                {
                    component(inBox.lo, a) = std::max(component(inBox.lo, a), component(domain.min, a));
                    component(inBox.hi, a) = std::min(component(inBox.hi, a), component(domain.max, a));
                }
                bool needed = false, nearSomeImage = false;
                for (const Vec3& s : shifts)
                {
                    needed = needed || distanceSquared(inBox, x + s) < reach * reach;
                    nearSomeImage = nearSomeImage || distanceSquared(d.region[p], x + s) < reach * reach;
                }
                const bool listed = std::find(found.begin(), found.end(), p) != found.end();
                ASSERT_TRUE(!needed || listed) << "part " << p << " missed, reach " << reach;
                ASSERT_TRUE(!listed || nearSomeImage) << "part " << p << " listed, reach " << reach;
                if (distanceSquared(d.region[p], x) < reach * reach)
                    direct.push_back(p);
            }
            throughFaces += found.size() > direct.size();
        }
    EXPECT_GT(throughFaces, 100u); // (the check saw parts found through the faces)
}

// With a non-periodic axis the periodic axes are not cut: each region spans them whole, so the
// images add no part and the query is the plain one (a chute's decomposition is unchanged).
TEST(Bisection, UncutPeriodicAxesAddNoGhosts)
{
    const dem::PeriodicDomain domain = cloudBox({true, true, false});
    EXPECT_EQ(cuttableAxes(domain), (std::array<bool, 3>{false, false, true}));
    const auto cloud = clouds::makeCloud(3000, 7);
    const Decomposition d = bisect(cloud.position, cloud.weight, 4, SerialCollective{}, domain);
    for (const Decomposition::Node& n : d.nodes)
        EXPECT_EQ(n.axis, 2);
    const Decomposition plain = [&]
    {
        Decomposition copy = d;
        copy.domain = {};
        return copy;
    }();
    const auto queries = clouds::makeCloud(2000, 8);
    for (const Vec3& x : queries.position)
    {
        std::vector<int> found, expected;
        d.forEachPartNear(x, 0.01, [&](int p) { found.push_back(p); });
        plain.forEachPartNear(x, 0.01, [&](int p) { expected.push_back(p); });
        ASSERT_EQ(found, expected);
    }
}

TEST(Bisection, DegenerateInputs)
{
    // No particles at all: one region per part still tiles space.
    const Decomposition empty = bisect({}, {}, 4, SerialCollective{});
    EXPECT_EQ(empty.parts(), 4);
    EXPECT_EQ(empty.owner({1, 2, 3}), empty.owner({1, 2, 3}));
    // Every particle at one point: one part takes them all, the others none.
    const std::vector<Vec3> same(10, Vec3{0.1, 0.2, 0.3});
    const std::vector<std::uint32_t> ones(10, 1);
    const Decomposition one = bisect(same, ones, 3, SerialCollective{});
    std::uint64_t sum = 0;
    for (std::uint64_t c : one.cost)
        sum += c;
    EXPECT_EQ(sum, 10u);
    EXPECT_EQ(one.cost[one.owner(same[0])], 10u);
    // More parts than particles.
    const Decomposition many = bisect(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}},
                                      std::vector<std::uint32_t>{1, 1}, 5, SerialCollective{});
    EXPECT_EQ(many.parts(), 5);
    EXPECT_NE(many.owner({0, 0, 0}), many.owner({1, 0, 0}));
}

TEST(Bisection, RefusesBadArguments)
{
    EXPECT_THROW(bisect({}, {}, 0, SerialCollective{}), InputError);
    const std::vector<Vec3> x(2);
    const std::vector<std::uint32_t> w(1, 1);
    EXPECT_THROW(bisect(x, w, 2, SerialCollective{}), InputError);
}
