// Bodies that overlap at the start are refused; bodies that touch are not.
#include "core/error.h"
#include "fdem/body_overlap.h"
#include "fdem/mesher.h"

#include <gtest/gtest.h>

using namespace veridem;
using namespace veridem::fdem;

namespace
{
bool overlap(const TriangleMesh& a, const TriangleMesh& b)
{
    try
    {
        checkBodiesApart({&a, &b}, {"a", "b"}, "s.toml");
    }
    catch (const InputError&)
    {
        return true;
    }
    return false;
}
TriangleMesh box(Vec2 origin, Vec2 size, int n = 2)
{
    return meshRectangle(origin, size, n, n, DiagonalPattern::Alternate);
}
} // namespace

TEST(BodyOverlap, TouchingIsAcceptedOverlapIsRefused)
{
    const TriangleMesh ground = box({-1, -0.1}, {2, 0.1}, 8);
    EXPECT_FALSE(overlap(ground, box({0, 0}, {0.1, 0.1})));                     // resting on the top face
    EXPECT_FALSE(overlap(ground, box({1, -0.1}, {0.1, 0.1})));                  // side by side
    EXPECT_FALSE(overlap(ground, box({1, 0}, {0.1, 0.1})));                     // corner to corner
    EXPECT_FALSE(overlap(ground, box({0, 0.5}, {0.1, 0.1})));                   // apart
    EXPECT_TRUE(overlap(ground, box({0, -0.005}, {0.1, 0.1})));                 // sunk 5 mm
    EXPECT_TRUE(overlap(ground, box({-0.5, -0.08}, {0.1, 0.05})));              // inside
    EXPECT_TRUE(overlap(ground, ground));                                       // coincident
    EXPECT_TRUE(overlap(box({0, -1}, {0.1, 2}, 1), box({-1, 0}, {2, 0.1}, 1))); // a cross, no node inside
}
