// The volume of a sphere inside a box (dem/sphere_box_volume.h) against closed forms: the whole
// sphere, spherical caps, halves, quarters and octants through the centre, disk areas, and
// partitions: the pieces of a sphere cut by a 3 x 3 x 3 grid of arbitrary planes add up to the
// whole sphere; at and near every face, edge and corner of a box (the position that once made an
// adaptive quadrature recurse without end among them) against an independent quadrature of the
// sphere's slices; random spheres and boxes against Monte Carlo.
#include "core/constants.h"
#include "dem/sphere_box_volume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace veridem::dem
{
namespace
{

constexpr Real kR = 1.3e-3;             // [m]
const Vec3 kC{0.1e-3, -0.2e-3, 0.3e-3}; // centre [m]
constexpr Real kFar = 1.0;              // a face far outside the sphere [m]
const Real kV = 4.0 / 3.0 * kPi * kR * kR * kR;
// The closed form's only error is rounding: eight corner terms of up to ~10 elementary functions
// each, every term of the size of the sphere's volume, ~1e-15 relative each: 1e-13 of the
// sphere's volume bounds their sum with a margin.
const Real kTolerance = 1e-13 * kV;

/// An independent reference: the integral over the height of the sphere's slices inside the box
/// (diskRectangleArea, exact per slice), with z = z_c - r cos(theta) (smooth at the poles), cut at
/// every height where a slice's circle meets an edge's line or a corner (kinks of the area), each
/// piece mapped to be smooth at its ends, and 200 panels of 5-point Gauss-Legendre per piece: the
/// error is far below 1e-13 of the sphere's volume.
Real slicedVolume(const Vec3& c, Real r, const Vec3& lo, const Vec3& hi)
{
    const Real za = std::max(lo.z, c.z - r), zb = std::min(hi.z, c.z + r);
    if (!(za < zb))
        return 0;
    std::vector<Real> cuts = {za, zb};
    const Real dx[2] = {lo.x - c.x, hi.x - c.x}, dy[2] = {lo.y - c.y, hi.y - c.y};
    const auto addDistance = [&](Real d2)
    {
        if (d2 < r * r)
            for (const Real z : {c.z - std::sqrt(r * r - d2), c.z + std::sqrt(r * r - d2)})
                if (z > za && z < zb)
                    cuts.push_back(z);
    };
    for (int a = 0; a < 2; ++a)
    {
        addDistance(dx[a] * dx[a]);
        addDistance(dy[a] * dy[a]);
        for (int b = 0; b < 2; ++b)
            addDistance(dx[a] * dx[a] + dy[b] * dy[b]);
    }
    std::sort(cuts.begin(), cuts.end());
    const std::array<Real, 5> node = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                      0.9061798459386640};
    const std::array<Real, 5> weight = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                        0.2369268850561891, 0.2369268850561891};
    const auto theta = [&](Real z) { return std::acos(std::clamp((c.z - z) / r, Real(-1), Real(1))); };
    Real volume = 0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
    {
        // theta = t0 + L (3s^2 - 2s^3): the area's (theta - theta_b)^(3/2) kinks at the piece's
        // ends become smooth in s (s^3).
        const Real t0 = theta(cuts[k]), L = theta(cuts[k + 1]) - t0;
        constexpr int kPanels = 200;
        const Real h = 1.0 / kPanels;
        for (int panel = 0; panel < kPanels; ++panel)
            for (std::size_t q = 0; q < node.size(); ++q)
            {
                const Real u = h * (panel + 0.5 * (1 + node[q]));
                const Real t = t0 + L * u * u * (3 - 2 * u);
                const Real rho = r * std::sin(t);
                volume += 0.5 * h * weight[q] * 6 * L * u * (1 - u) * r * std::sin(t) *
                          diskRectangleArea(rho, c.x, c.y, lo.x, hi.x, lo.y, hi.y);
            }
    }
    return volume;
}

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

TEST(SphereBoxVolume, FacesAtVanishingDistancesFromTheCentre)
{
    // Faces d = 5e-324 (the least subnormal) to 1e-30 m from the centre of a 1 mm sphere: products like
    // d * z underflow to zero there (a fuzz input: a quarter sphere counted as a half). The sphere
    // keeps a half, a quarter or an eighth, less at most pi r^2 d per face (the largest section).
    const Real r = 1e-3, V = 4.0 / 3.0 * kPi * r * r * r, tolerance = 1e-13 * V;
    const Vec3 c{0, 0, 0};
    for (const Real d : {5e-324, 1e-322, 1e-320, 1e-310, 1e-300, 1e-200, 1e-100, 1e-30})
    {
        const Real slack = tolerance + 3 * kPi * r * r * d;
        EXPECT_NEAR(sphereBoxVolume(c, r, {d, -1, -1}, {1, 1, 1}), V / 2, slack) << d;
        EXPECT_NEAR(sphereBoxVolume(c, r, {d, 0, -1}, {1, 1, 1}), V / 4, slack) << d;
        EXPECT_NEAR(sphereBoxVolume(c, r, {d, -1, -1}, {1, 0, 1}), V / 4, slack) << d;
        EXPECT_NEAR(sphereBoxVolume(c, r, {d, d, -1}, {1, 1, 1}), V / 4, slack) << d;
        EXPECT_NEAR(sphereBoxVolume(c, r, {d, d, d}, {1, 1, 1}), V / 8, slack) << d;
        EXPECT_NEAR(sphereBoxVolume(c, r, {-1, -1, -1}, {-d, 1, 1}), V / 2, slack) << d;
        EXPECT_NEAR(sphereBoxVolume(c, r, {-1, -1, -1}, {-d, -d, -d}), V / 8, slack) << d;
    }
}

TEST(SphereBoxVolume, ASmallSphereFarFromTheOriginSplitsConsistently)
{
    // r = 2.6e-9 m at 950 m (the fuzz target's extremes): c - r rounds by ~1e-4 r, so a face a
    // few ulps from c - r must be judged by the same rounded numbers as the corner terms, or the
    // whole and the sum of its two halves differ by a cap of height ~1e-4 r (~1e-8 of the sphere;
    // rounding alone leaves ~1e-15). Faces at up to 40 ulps of 950 m (~5e-12 m) on either side.
    const Real r = 2.6070051098621164e-9, V = 4.0 / 3.0 * kPi * r * r * r;
    const Vec3 c{949.81958650643969, 0, 0};
    const Vec3 far{c.x + 1, 1, 1};
    int cases = 0;
    Real x = c.x - r;
    for (int k = 0; k < 40; ++k)
        x = std::nextafter(x, Real(0));
    for (int k = -40; k <= 40; ++k, x = std::nextafter(x, Real(2e3)))
        for (const Real fraction : {-0.999, -0.5, 0.0, 0.7})
        {
            const Vec3 lo{x, -1, -1};
            const Real cut = std::max(x, c.x + fraction * r);
            const Real whole = sphereBoxVolume(c, r, lo, far);
            const Real parts = sphereBoxVolume(c, r, lo, {cut, far.y, far.z}) +
                               sphereBoxVolume(c, r, {cut, lo.y, lo.z}, far);
            EXPECT_NEAR(whole, parts, 1e-13 * V) << k << " " << fraction;
            ++cases;
        }
    EXPECT_EQ(cases, 81 * 4);
}

TEST(SphereBoxVolume, AtAndNearEveryFaceEdgeAndCorner)
{
    // A 1 cm box and a 1 mm sphere whose centre lies on each of the box's 26 features (6 faces,
    // 12 edges, 8 corners) and just off them, by 1e-12 to 1e-4 m on either side (1e-7 m off a
    // face: the position of issue 49, [0.005, 0.0099999, 0.005], included). On a feature the
    // sphere keeps a half, a quarter or an eighth (exact by symmetry; the box is 5 radii from the
    // other faces); off it, the independent slice quadrature; the volume moves by at most
    // pi r^2 per metre of a face's displacement (the largest section) per face crossed.
    const Real r = 1e-3, V = 4.0 / 3.0 * kPi * r * r * r, tolerance = 1e-13 * V;
    const Vec3 lo{0, 0, 0}, hi{0.01, 0.01, 0.01};
    const Real place[3] = {0.0, 0.005, 0.01};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
            {
                const int onFaces = (i != 1) + (j != 1) + (k != 1);
                if (onFaces == 0)
                    continue;
                const Vec3 c{place[i], place[j], place[k]};
                const Real share = V / (1 << onFaces);
                EXPECT_NEAR(sphereBoxVolume(c, r, lo, hi), share, tolerance)
                    << c.x << " " << c.y << " " << c.z;
                for (const Real offset : {1e-12, 1e-9, 1e-7, 1e-5, 1e-4})
                    for (const Real sign : {-1.0, 1.0})
                    {
                        // Off the feature along the diagonal of the faces it lies on.
                        const Real d = sign * offset;
                        const Vec3 p{c.x + (i != 1 ? d : 0), c.y + (j != 1 ? d : 0), c.z + (k != 1 ? d : 0)};
                        const Real v = sphereBoxVolume(p, r, lo, hi);
                        EXPECT_NEAR(v, slicedVolume(p, r, lo, hi), tolerance)
                            << p.x << " " << p.y << " " << p.z;
                        EXPECT_LE(std::abs(v - share), onFaces * kPi * r * r * offset + tolerance);
                    }
            }
    // The issue's position, exactly.
    const Vec3 issue{0.005, 0.0099999, 0.005};
    const Real H = r - 1e-7; // one face 1e-7 m beyond the centre: all but a cap of height H
    EXPECT_NEAR(sphereBoxVolume(issue, r, lo, hi), V - kPi * H * H * (3 * r - H) / 3, tolerance);
    // Bounded cost: the closed form has no loop whose length depends on the position (at most
    // 8 corner terms, each reflected at most three levels deep); a hang would be caught by the
    // test's timeout, not by a clock here (timings belong in benchmarks).
}

TEST(SphereBoxVolume, RandomSpheresAndBoxesAgainstMonteCarloAndSlices)
{
    // 300 random spheres and boxes (sides from 0.2 to 4 radii, the centre up to 1.5 radii outside
    // the box): the closed form against the slice quadrature (to 1e-13 of the sphere's volume)
    // and against N uniform points in the sphere, to 5 standard errors of the Monte Carlo
    // estimate, V sqrt(p (1 - p) / N) (a false alarm once in ~3.5 million trials), plus one point's
    // share for a fraction near 0 or 1.
    std::mt19937_64 random(49);
    std::uniform_real_distribution<Real> unit(0, 1);
    const Real r = 0.7e-3, V = 4.0 / 3.0 * kPi * r * r * r;
    constexpr int kPoints = 20000;
    for (int trial = 0; trial < 300; ++trial)
    {
        const Vec3 c{unit(random) * 1e-3, unit(random) * 1e-3, unit(random) * 1e-3};
        const Vec3 size{(0.2 + 3.8 * unit(random)) * r, (0.2 + 3.8 * unit(random)) * r,
                        (0.2 + 3.8 * unit(random)) * r};
        const Vec3 lo = c - Vec3{(unit(random) * 1.5 + 0.5 * unit(random)) * size.x - 0.75 * r,
                                 (unit(random) * 1.5 + 0.5 * unit(random)) * size.y - 0.75 * r,
                                 (unit(random) * 1.5 + 0.5 * unit(random)) * size.z - 0.75 * r};
        const Vec3 hi = lo + size;
        const Real v = sphereBoxVolume(c, r, lo, hi);
        EXPECT_NEAR(v, slicedVolume(c, r, lo, hi), 1e-13 * V) << trial;
        int inside = 0, drawn = 0;
        while (drawn < kPoints)
        {
            const Vec3 p{(2 * unit(random) - 1) * r, (2 * unit(random) - 1) * r, (2 * unit(random) - 1) * r};
            if (dot(p, p) > r * r)
                continue;
            ++drawn;
            const Vec3 x = c + p;
            inside += x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z;
        }
        const Real fraction = Real(inside) / kPoints;
        const Real standardError = V * std::sqrt(fraction * (1 - fraction) / kPoints);
        EXPECT_NEAR(v, V * fraction, 5 * standardError + V / kPoints) << trial;
    }
}

} // namespace
} // namespace veridem::dem
