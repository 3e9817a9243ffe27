// The volume of a sphere inside a box (dem/sphere_box_volume.h) against closed forms: the whole
// sphere, spherical caps, halves, quarters and octants through the centre, disk areas, and
// partitions: the pieces of a sphere cut by a 3 x 3 x 3 grid of arbitrary planes add up to the
// whole sphere.
#include "core/constants.h"
#include "dem/sphere_box_volume.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace veridem::dem
{
namespace
{

constexpr Real kR = 1.3e-3;             // [m]
const Vec3 kC{0.1e-3, -0.2e-3, 0.3e-3}; // centre [m]
constexpr Real kFar = 1.0;              // a face far outside the sphere [m]
const Real kV = 4.0 / 3.0 * kPi * kR * kR * kR;
// The adaptive quadrature stops at 1e-14 of the sphere's volume per piece (kSphereBoxTolerance),
// a few pieces per box; with rounding, 1e-13 of the sphere's volume.
const Real kTolerance = 1e-13 * kV;

TEST(SphereBoxVolume, WholeSphereAndNothing)
{
    EXPECT_EQ(sphereBoxVolume(kC, kR, {-kFar, -kFar, -kFar}, {kFar, kFar, kFar}), kV);
    // Touching the faces from inside: still whole.
    EXPECT_EQ(sphereBoxVolume(kC, kR, kC - Vec3{kR, kR, kR}, kC + Vec3{kR, kR, kR}), kV);
    EXPECT_EQ(sphereBoxVolume(kC, kR, {kC.x + kR, -kFar, -kFar}, {kFar, kFar, kFar}), 0.0);
}

TEST(SphereBoxVolume, CapsAlongEveryAxis)
{
    // The part beyond a plane at distance h from the centre: the cap of height H = r - h,
    // pi H^2 (3r - H) / 3.
    for (const Real h : {-0.95, -0.5, -0.1, 0.0, 0.3, 0.77, 0.999})
    {
        const Real H = kR * (1 - h);
        const Real cap = kPi * H * H * (3 * kR - H) / 3;
        for (int axis = 0; axis < 3; ++axis)
        {
            Vec3 lo{-kFar, -kFar, -kFar};
            (axis == 0   ? lo.x
             : axis == 1 ? lo.y
                         : lo.z) = (axis == 0   ? kC.x
                                    : axis == 1 ? kC.y
                                                : kC.z) +
                                   h * kR;
            EXPECT_NEAR(sphereBoxVolume(kC, kR, lo, {kFar, kFar, kFar}), cap, kTolerance) << h << " " << axis;
        }
    }
}

TEST(SphereBoxVolume, HalvesQuartersAndOctantsThroughTheCentre)
{
    const Vec3 far{kFar, kFar, kFar};
    EXPECT_NEAR(sphereBoxVolume(kC, kR, {kC.x, -kFar, -kFar}, far), kV / 2, kTolerance);
    EXPECT_NEAR(sphereBoxVolume(kC, kR, {kC.x, kC.y, -kFar}, far), kV / 4, kTolerance);
    EXPECT_NEAR(sphereBoxVolume(kC, kR, {-kFar, kC.y, kC.z}, far), kV / 4, kTolerance);
    EXPECT_NEAR(sphereBoxVolume(kC, kR, kC, far), kV / 8, kTolerance);
    EXPECT_NEAR(sphereBoxVolume(kC, kR, -far, kC), kV / 8, kTolerance);
    // A slab |x - x_c| <= h: the sphere minus two caps of height r - h.
    const Real h = 0.4 * kR, H = kR - h;
    EXPECT_NEAR(sphereBoxVolume(kC, kR, {kC.x - h, -kFar, -kFar}, {kC.x + h, kFar, kFar}),
                kV - 2 * kPi * H * H * (3 * kR - H) / 3, kTolerance);
}

TEST(SphereBoxVolume, DiskAreas)
{
    const Real rho = 2.0, full = kPi * rho * rho;
    EXPECT_NEAR(diskRectangleArea(rho, 0, 0, -3, 3, -3, 3), full, 1e-15 * full);
    EXPECT_NEAR(diskRectangleArea(rho, 0, 0, 0, 3, -3, 3), full / 2, 1e-15 * full);
    EXPECT_NEAR(diskRectangleArea(rho, 0, 0, 0, 3, 0, 3), full / 4, 1e-15 * full);
    // A segment beyond x = d: rho^2 acos(d / rho) - d sqrt(rho^2 - d^2).
    for (const Real d : {-1.5, -0.2, 0.5, 1.9})
    {
        const Real segment = rho * rho * std::acos(d / rho) - d * std::sqrt(rho * rho - d * d);
        EXPECT_NEAR(diskRectangleArea(rho, 0, 0, d, 3, -3, 3), segment, 1e-14 * full) << d;
        EXPECT_NEAR(diskRectangleArea(rho, 0, 0, -3, 3, d, 3), segment, 1e-14 * full) << d;
    }
    // A square inside the disk: its area.
    EXPECT_NEAR(diskRectangleArea(rho, 0.1, -0.2, -1, 1, -1, 0.5), 3.0, 1e-14 * full);
}

TEST(SphereBoxVolume, PiecesOfAPartitionAddUpToTheSphere)
{
    // Two random planes per axis within the sphere, and far faces: 27 boxes, the pieces of the
    // sphere, in every configuration of edges and corners inside and outside it.
    std::mt19937_64 random(11);
    std::uniform_real_distribution<Real> offset(-1.05 * kR, 1.05 * kR);
    for (int trial = 0; trial < 100; ++trial)
    {
        Real cuts[3][4];
        const Real centre[3] = {kC.x, kC.y, kC.z};
        for (int axis = 0; axis < 3; ++axis)
        {
            const Real a = centre[axis] + offset(random), b = centre[axis] + offset(random);
            cuts[axis][0] = -kFar;
            cuts[axis][1] = std::min(a, b);
            cuts[axis][2] = std::max(a, b);
            cuts[axis][3] = kFar;
        }
        Real sum = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k)
                    sum += sphereBoxVolume(kC, kR, {cuts[0][i], cuts[1][j], cuts[2][k]},
                                           {cuts[0][i + 1], cuts[1][j + 1], cuts[2][k + 1]});
        EXPECT_NEAR(sum, kV, 27 * kTolerance) << trial;
    }
}

} // namespace
} // namespace veridem::dem
