// The mesh contact query's parts against their formulas: the per-triangle Bound record, the
// distance lower bound that skips triangles (triangleFartherThan) against closestPointOnTriangle
// and a brute-force sampling of the triangle, and the query on a curved surface against the
// nearest point of every triangle.
#include "core/constants.h"
#include "dem/walls/mesh_wall.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

using namespace veridem;
using namespace veridem::dem;

namespace
{

/// Random triangles: well shaped and slivers (one corner near the opposite edge), of size ~1 m
/// about a point far from the origin (so the bound's rounding is tested at 100x its size).
std::vector<Vec3> randomTriangles(std::mt19937_64& random, int count)
{
    std::uniform_real_distribution<Real> unit(-1, 1);
    std::vector<Vec3> corners;
    const Vec3 centre{100, -50, 30};
    for (int t = 0; t < count; ++t)
    {
        const Vec3 a = centre + Vec3{unit(random), unit(random), unit(random)} + Vec3{3.0 * t, 0, 0};
        const Vec3 b = a + Vec3{unit(random), unit(random), unit(random)};
        Vec3 c = a + Vec3{unit(random), unit(random), unit(random)};
        if (t % 3 == 0) // a sliver: c 1e-3 of |ab| off the line ab
            c = a + 0.4 * (b - a) + 1e-3 * length(b - a) * normalizedOrZero(cross(b - a, c - a));
        corners.insert(corners.end(), {a, b, c});
    }
    return corners;
}

/// The distance from p to triangle (a, b, c) by sampling it on a barycentric grid of n steps per
/// side [m]: at least the true distance, and above it by at most the grid spacing.
Real sampledDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int n)
{
    Real best = INFINITY;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j)
        {
            const Real u = Real(i) / n, v = Real(j) / n;
            best = std::fmin(best, length(p - (a + u * (b - a) + v * (c - a))));
        }
    return best;
}

} // namespace

TEST(MeshQuery, BoundRecordCopiesTheTriangleAndItsApexHeight)
{
    std::mt19937_64 random(11);
    MeshReport report;
    const TriangleMesh m = buildTriangleMesh(randomTriangles(random, 30), "random", report);
    ASSERT_EQ(m.bounds.size(), m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
    {
        const Vec3 &a = m.vertices[m.triangles[t][0]], &b = m.vertices[m.triangles[t][1]],
                   &c = m.vertices[m.triangles[t][2]];
        const TriangleMesh::Bound& bound = m.bounds[t];
        EXPECT_EQ(length(bound.corner - a), 0);
        EXPECT_EQ(length(bound.normal - m.normals[t]), 0);
        for (int e = 0; e < 3; ++e)
            EXPECT_EQ(length(bound.inward[e] - m.inward[t][e]), 0);
        // The distance of a from the line bc: |(c - b) x (a - b)| / |c - b| (round-off: 1e-12 of
        // the triangle's size, as the inward direction is normalised from differences of ~1 m).
        const Real height = length(cross(c - b, a - b)) / length(c - b);
        EXPECT_NEAR(bound.apexHeight, height, 1e-12 * length(b - a));
    }
}

TEST(MeshQuery, FartherThanIsALowerBoundOfTheDistanceAndExactOverTheFaceAndEdges)
{
    std::mt19937_64 random(5);
    MeshReport report;
    const TriangleMesh m = buildTriangleMesh(randomTriangles(random, 30), "random", report);
    std::uniform_real_distribution<Real> unit(-1, 1), share(0, 1);
    int skipped = 0, tight = 0;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
    {
        const Vec3 &a = m.vertices[m.triangles[t][0]], &b = m.vertices[m.triangles[t][1]],
                   &c = m.vertices[m.triangles[t][2]];
        for (int trial = 0; trial < 400; ++trial)
        {
            const Vec3 p = a + 2 * share(random) * (b - a) + share(random) * (c - a) +
                           0.5 * Vec3{unit(random), unit(random), unit(random)};
            const TrianglePoint closest = closestPointOnTriangle(p, a, b, c);
            const Real distance = length(p - closest.point);
            // A lower bound: never farther than r when the distance is below r (radii about the
            // distance, some within 1e-9 of it, where the bound's margin decides).
            for (const Real factor : {0.5, 0.999, 1 - 1e-9, 1 + 1e-9, 1.001, 2.0})
            {
                const Real r = factor * distance;
                Real s;
                if (triangleFartherThan(m, static_cast<std::uint32_t>(t), p, r, s))
                {
                    ++skipped;
                    EXPECT_GT(distance, r) << "triangle " << t << " trial " << trial;
                }
                EXPECT_EQ(s, dot(p - a, m.normals[t])); // (the signed plane distance, the same bits)
            }
            // Over the face or an edge the bound is the distance itself (the plane distance, and
            // across an edge the distance from its line), so it decides 1e-8 m (above its margin,
            // 1e-10 of lengths of ~1 m, and the round-off of coordinates of 100 m) below it.
            if (closest.feature != MeshFeature::Vertex && distance > 1e-6)
            {
                Real s;
                EXPECT_TRUE(triangleFartherThan(m, static_cast<std::uint32_t>(t), p, distance - 1e-8, s))
                    << "triangle " << t << " trial " << trial;
                ++tight;
            }
        }
    }
    EXPECT_GT(skipped, 1000);
    EXPECT_GT(tight, 1000);
}

TEST(MeshQuery, ClosestPointAgreesWithSampling)
{
    std::mt19937_64 random(9);
    MeshReport report;
    const TriangleMesh m = buildTriangleMesh(randomTriangles(random, 12), "random", report);
    std::uniform_real_distribution<Real> unit(-1, 1), share(0, 1);
    constexpr int kSteps = 400;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
    {
        const Vec3 &a = m.vertices[m.triangles[t][0]], &b = m.vertices[m.triangles[t][1]],
                   &c = m.vertices[m.triangles[t][2]];
        const Real spacing = std::fmax(length(b - a), std::fmax(length(c - a), length(c - b))) / kSteps;
        for (int trial = 0; trial < 20; ++trial)
        {
            const Vec3 p = a + share(random) * (b - a) + share(random) * (c - a) +
                           0.3 * Vec3{unit(random), unit(random), unit(random)};
            const Real distance = length(p - closestPointOnTriangle(p, a, b, c).point);
            const Real sampled = sampledDistance(p, a, b, c, kSteps);
            // The sampled distance is no less than the true one, and more by at most a spacing.
            EXPECT_LE(distance, sampled * (1 + 1e-12));
            EXPECT_LE(sampled - distance, spacing);
        }
    }
}

TEST(MeshQuery, DeepestContactOnACurvedSurfaceIsTheNearestPointOfAnyTriangle)
{
    // The inside of a cylinder of radius 45 mm about +y as 96 segments and 8 rings of 2.9 mm, two
    // triangles per quad (the micro-benchmark's drum): a sphere of radius 1 mm near the wall.
    const Real pi = kPi, radius = 0.045, ring = 2.9e-3, r = 1e-3;
    const int segments = 96, rings = 8;
    const auto at = [&](int q, int k)
    {
        const Real a = 2 * pi * q / segments;
        return Vec3{radius * std::cos(a), k * ring, radius * std::sin(a)};
    };
    std::vector<Vec3> corners;
    for (int k = 0; k < rings; ++k)
        for (int q = 0; q < segments; ++q)
        {
            const Vec3 a = at(q, k), b = at((q + 1) % segments, k), c = at((q + 1) % segments, k + 1),
                       d = at(q, k + 1);
            corners.insert(corners.end(), {a, b, c, a, c, d});
        }
    MeshReport report;
    MeshShape shape;
    shape.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(corners, "drum", report));
    const TriangleMesh& m = *shape.mesh;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<Real> angle(0, 2 * pi), along(3e-3, 20e-3), depth(0.1e-3, 1.2e-3);
    int touching = 0;
    for (int trial = 0; trial < 2000; ++trial)
    {
        const Real a = angle(random), h = radius - depth(random);
        const Vec3 x{h * std::cos(a), along(random), h * std::sin(a)};
        Real nearest = INFINITY;
        for (const auto& tri : m.triangles)
            nearest =
                std::fmin(nearest, length(x - closestPointOnTriangle(x, m.vertices[tri[0]],
                                                                     m.vertices[tri[1]], m.vertices[tri[2]])
                                                  .point));
        std::vector<std::uint32_t> near;
        const std::size_t count = meshTrianglesNear(shape, {}, x, r, 0.5e-3, near);
        MeshContact c[kMeshSlots];
        const int found = meshContacts(shape, {}, x, r, near.data(), count, c);
        if (!(nearest < r))
        {
            EXPECT_EQ(found, 0) << trial;
            continue;
        }
        ++touching;
        ASSERT_GE(found, 1) << trial;
        // The deepest contact is the nearest point of the surface (round-off: 1e-15 m, a few ulps
        // of the coordinates of 0.045 m).
        EXPECT_NEAR(c[0].overlap, r - nearest, 1e-15) << trial;
    }
    EXPECT_GT(touching, 500);
}
