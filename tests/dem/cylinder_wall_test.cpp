// Cylinder walls (dem/walls/cylinder.h) against the geometry: gap, normal and effective radius on
// both sides, the ends, the surface velocity of a rotating drum, and wallNear's conservativeness.
#include "dem/walls/wall.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace veridem;
using namespace veridem::dem;

namespace
{
const Vec3 kAxis = Vec3{1, 1, 0} / std::sqrt(2.0); // a tilted axis: nothing aligned with x, y, z
const Vec3 kAcross{0, 0, 1};                       // normal to kAxis
const Vec3 kPoint{0.3, -0.2, 0.1};

CylinderShape cylinder(bool inside)
{
    return CylinderShape{kPoint, kAxis, 0.1, 0.2, inside};
}
} // namespace

TEST(CylinderWall, InsideGapNormalAndConcaveRadius)
{
    const Real r = 0.01, overlap = 1e-4, R = 0.1;
    const Vec3 x = kPoint + 0.05 * kAxis + (R - r + overlap) * kAcross;
    const WallGap g = wallGap(cylinder(true), {}, x, r);
    ASSERT_TRUE(g.touching);
    // Rounding of the distance from the axis (~0.09 m) is ~1e-17 m; 1e-15 m is a few ulps of it.
    EXPECT_NEAR(g.overlap, overlap, 1e-15);
    EXPECT_NEAR(length(g.normal - -kAcross), 0, 1e-15);
    EXPECT_NEAR(g.effectiveRadius, r * R / (R - r), 1e-16); // 1/R* = 1/r - 1/R
    // Clear of the wall, and wholly behind it (outside the drum): no contact.
    EXPECT_FALSE(wallGap(cylinder(true), {}, kPoint + 0.05 * kAxis + (R - r - 1e-6) * kAcross, r).touching);
    EXPECT_FALSE(wallGap(cylinder(true), {}, kPoint + 0.05 * kAxis + (R + 1.5 * r) * kAcross, r).touching);
    // On the axis: no contact with a drum wider than the sphere, and no NaN.
    EXPECT_FALSE(wallGap(cylinder(true), {}, kPoint + 0.05 * kAxis, r).touching);
}

TEST(CylinderWall, OutsideGapNormalAndConvexRadius)
{
    const Real r = 0.01, overlap = 2e-4, R = 0.1;
    const Vec3 x = kPoint + 0.15 * kAxis + (R + r - overlap) * kAcross;
    const WallGap g = wallGap(cylinder(false), {}, x, r);
    ASSERT_TRUE(g.touching);
    EXPECT_NEAR(g.overlap, overlap, 1e-15);
    EXPECT_NEAR(length(g.normal - kAcross), 0, 1e-15);
    EXPECT_NEAR(g.effectiveRadius, r * R / (R + r), 1e-16); // 1/R* = 1/r + 1/R
    // A centre inside the post (wholly behind the surface): no contact.
    EXPECT_FALSE(wallGap(cylinder(false), {}, kPoint + 0.15 * kAxis + 0.05 * kAcross, r).touching);
    // A sphere wider than a thin post with its centre on the axis: a finite unit normal across the axis.
    const CylinderShape thin{kPoint, kAxis, 0.005, 0.2, false};
    const WallGap onAxis = wallGap(thin, {}, kPoint + 0.1 * kAxis, r);
    ASSERT_TRUE(onAxis.touching);
    EXPECT_NEAR(onAxis.overlap, r + 0.005, 1e-15);
    EXPECT_NEAR(length(onAxis.normal), 1, 1e-15);
    EXPECT_NEAR(dot(onAxis.normal, kAxis), 0, 1e-15);
}

TEST(CylinderWall, NoSideContactBeyondTheEnds)
{
    const Real r = 0.01;
    const Vec3 across = (0.1 - r + 1e-4) * kAcross; // 0.1 mm overlap with the side
    EXPECT_TRUE(wallGap(cylinder(true), {}, kPoint + 1e-6 * kAxis + across, r).touching);
    EXPECT_FALSE(wallGap(cylinder(true), {}, kPoint - 1e-6 * kAxis + across, r).touching);
    EXPECT_TRUE(wallGap(cylinder(true), {}, kPoint + (0.2 - 1e-6) * kAxis + across, r).touching);
    EXPECT_FALSE(wallGap(cylinder(true), {}, kPoint + (0.2 + 1e-6) * kAxis + across, r).touching);
    // The displacement moves the whole cylinder.
    const Vec3 offset{0.01, 0.02, 0.03};
    EXPECT_TRUE(wallGap(cylinder(true), offset, kPoint + offset + 1e-6 * kAxis + across, r).touching);
}

TEST(CylinderWall, RotatingDrumSurfaceVelocityIsOmegaCrossR)
{
    Wall drum;
    drum.shape = cylinder(true);
    const Real omega = 3.0;
    drum.motion.angularVelocity = omega * kAxis;
    drum.motion.rotationCentre = kPoint;
    // A point of the surface, 0.07 m along the axis (the surface velocity is the rigid field there).
    const Vec3 onSurface = kPoint + 0.07 * kAxis + 0.1 * kAcross;
    const Vec3 v = wallSurfaceVelocity(drum, onSurface);
    const Vec3 expected = cross(omega * kAxis, 0.1 * kAcross); // omega x r from the axis
    EXPECT_NEAR(length(v - expected), 0, 1e-15);
    EXPECT_NEAR(length(v), omega * 0.1, 1e-15);
    EXPECT_NEAR(dot(v, kAcross), 0, 1e-15); // tangent to the surface
}

TEST(CylinderWall, WallNearIsConservative)
{
    // Whenever the sphere touches after a relative motion of at most `reach`, wallNear before the
    // motion is true. 200k random spheres around both kinds of cylinder.
    std::mt19937_64 random(7);
    std::uniform_real_distribution<Real> unit(-1, 1);
    for (const bool inside : {true, false})
    {
        const CylinderShape c = cylinder(inside);
        int touched = 0;
        for (int k = 0; k < 100000; ++k)
        {
            const Real r = 0.002 + 0.01 * std::fabs(unit(random)), reach = 0.005 * std::fabs(unit(random));
            const Vec3 x = kPoint + (0.1 + 0.15 * unit(random)) * kAxis +
                           0.13 * Vec3{unit(random), unit(random), unit(random)};
            Vec3 move{unit(random), unit(random), unit(random)};
            move = (reach * std::fabs(unit(random)) / length(move)) * move;
            if (wallGap(c, move, x, r).touching)
            {
                ++touched;
                EXPECT_TRUE(wallNear(c, {}, x, r, reach)) << "inside " << inside << " sample " << k;
            }
        }
        EXPECT_GT(touched, 1000); // the samples exercise the contact
    }
}
