// Wall geometry (gap, normal) and surface velocity against geometry.
#include "core/constants.h"
#include "dem/walls/wall.h"

#include <gtest/gtest.h>

using namespace veridem;
using namespace veridem::dem;

TEST(Walls, PlaneGapAndNormal)
{
    const PlaneShape plane{{0, 0, 1}, {0, 0, 1}};
    const WallGap g = wallGap(plane, {}, {3, 4, 1.004}, 0.005);
    EXPECT_TRUE(g.touching);
    EXPECT_NEAR(g.overlap, 0.001, 1e-15);
    EXPECT_EQ(g.normal, (Vec3{0, 0, 1}));
    EXPECT_FALSE(wallGap(plane, {}, {0, 0, 1.006}, 0.005).touching);
}

TEST(Walls, DiskHasFiniteRadius)
{
    const PlaneShape disk{{0, 0, 0}, {0, 0, 1}, 0.2};
    EXPECT_TRUE(wallGap(disk, {}, {0.19, 0, 0.004}, 0.005).touching);
    EXPECT_FALSE(wallGap(disk, {}, {0.21, 0, 0.004}, 0.005).touching);
}

TEST(Walls, DishIsInsideOfSphere)
{
    const DishShape dish{{0, 0, 0}, 20.0};
    // A ball of radius a resting at the bottom: centre at height a - overlap.
    const WallGap bottom = wallGap(dish, {}, {0, 0, 0.003 - 1e-6}, 0.003);
    EXPECT_TRUE(bottom.touching);
    EXPECT_NEAR(bottom.overlap, 1e-6, 1e-12);
    EXPECT_NEAR(bottom.normal.z, 1.0, 1e-15);
    // On the side: the normal points to the sphere centre.
    const double theta = 0.5, rs = 20.0 - 0.003 + 1e-6; // 1 micrometre overlap
    const Vec3 x{rs * std::sin(theta), 0, 20.0 - rs * std::cos(theta)};
    const WallGap side = wallGap(dish, {}, x, 0.003);
    EXPECT_NEAR(side.overlap, 1e-6, 1e-12);
    EXPECT_NEAR(side.normal.x, -std::sin(theta), 1e-12);
    EXPECT_NEAR(side.effectiveRadius, 0.003 * 20 / (20 - 0.003), 1e-15);
}

TEST(Walls, TiltedNormalPointsDownhillInPlane)
{
    const double tilt = degToRad(10), azimuth = degToRad(135);
    const Vec3 k = tiltedNormal(tilt, azimuth);
    EXPECT_NEAR(length(k), 1, 1e-15);
    // Gravity's in-plane part points towards the azimuth.
    const Vec3 g{0, 0, -1};
    const Vec3 inPlane = g - dot(g, k) * k;
    EXPECT_NEAR(std::atan2(inPlane.y, inPlane.x), azimuth, 1e-12);
    EXPECT_NEAR(length(inPlane), std::sin(tilt), 1e-15);
}

TEST(Walls, RotatingSurfaceVelocity)
{
    Wall table;
    table.shape = PlaneShape{};
    table.motion.angularVelocity = {0, 0, 10};
    const Vec3 v = wallSurfaceVelocity(table, {-0.04, 0, 0});
    EXPECT_NEAR(v.y, -0.4, 1e-15);
    EXPECT_NEAR(v.x, 0, 1e-15);
}
