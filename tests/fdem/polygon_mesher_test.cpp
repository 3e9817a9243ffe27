// Polygons meshed with interior nodes to a target edge length (fdem/polygon_mesher.cpp) and the
// Delaunay triangulation under it.
#include "core/constants.h"
#include "core/error.h"
#include "fdem/delaunay.h"
#include "fdem/elements/cst.h"
#include "fdem/mesh.h"
#include "fdem/mesher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

namespace veridem::fdem
{
namespace
{

struct Quality
{
    Real area = 0;                     // [m^2]
    Real minAngleDegrees = 180;        // smallest angle of any triangle
    Real meanEdge = 0;                 // mean length of the distinct edges [m]
    Real minEdge = 1e300, maxEdge = 0; // [m]
    std::size_t interiorNodes = 0;     // nodes not on a boundary edge
};

Quality quality(const TriangleMesh& m)
{
    Quality q;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : m.triangles)
    {
        const Real a = signedArea(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
        EXPECT_GT(a, 0) << "triangles must be counter-clockwise";
        q.area += a;
        for (int k = 0; k < 3; ++k)
        {
            const Vec2 p = m.points[t[k]], u = m.points[t[(k + 1) % 3]] - p, v = m.points[t[(k + 2) % 3]] - p;
            q.minAngleDegrees =
                std::min(q.minAngleDegrees, std::atan2(std::abs(cross(u, v)), dot(u, v)) * 180 / kPi);
            ++edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
        }
    }
    std::vector<std::uint8_t> boundary(m.points.size(), 0);
    for (const auto& [e, count] : edges)
    {
        const Real l = length(m.points[e.second] - m.points[e.first]);
        q.meanEdge += l / static_cast<Real>(edges.size());
        q.minEdge = std::min(q.minEdge, l);
        q.maxEdge = std::max(q.maxEdge, l);
        if (count == 1)
            boundary[e.first] = boundary[e.second] = 1;
    }
    q.interiorNodes = static_cast<std::size_t>(std::count(boundary.begin(), boundary.end(), 0));
    return q;
}

TEST(Delaunay, FourPointsOfASquareGiveTwoTrianglesAndTheirEdges)
{
    DelaunayTriangulation dt({0, 0}, {1, 1});
    const auto a = dt.insert({0, 0}), b = dt.insert({1, 0}), c = dt.insert({1, 1.1}), d = dt.insert({0, 1});
    EXPECT_EQ(dt.triangles().size(), 2u);
    EXPECT_TRUE(dt.hasEdge(a, b) && dt.hasEdge(b, c) && dt.hasEdge(c, d) && dt.hasEdge(d, a));
    // (1, 1.1) lies outside the circle through the other three: the Delaunay diagonal is b-d.
    EXPECT_TRUE(dt.hasEdge(b, d));
    EXPECT_FALSE(dt.hasEdge(a, c));
}

TEST(PolygonMesher, DiscKeepsItsAreaAndHasUniformWellShapedTriangles)
{
    // A disc of radius 0.05 m at h = R/10, R/20, R/40. The mesh covers the inscribed polygon of
    // discOutline exactly (its vertices are nodes): area (n/2) R^2 sin(2 pi/n) to round-off (1e-12).
    // The lattice is equilateral (60 degrees); the band next to the outline spans gaps of h/2 to
    // h/2 + h sqrt(3)/2 against outline pieces of ~h, whose worst triangles, smoothed, stay above
    // 25 degrees (a Delaunay triangle of points >= h/2 apart with circumradius <~ h cannot be
    // thinner than asin(1/4) = 14.5 degrees; 25 is what the smoothing must reach). Edge lengths: the
    // mean within 15 % of h, every edge within [0.3 h, 1.8 h] (the band's extremes).
    const Real radius = 0.05;
    for (Real divisions : {10.0, 20.0, 40.0})
    {
        const Real h = radius / divisions;
        const auto outline = discOutline({0.1, -0.2}, radius, h);
        const TriangleMesh m = meshPolygonRefined(outline, h);
        EXPECT_NO_THROW(validatedMesh(m, "disc"));
        const Quality q = quality(m);
        const Real n = static_cast<Real>(outline.size());
        EXPECT_NEAR(q.area, 0.5 * n * radius * radius * std::sin(2 * kPi / n), 1e-12 * radius * radius) << h;
        EXPECT_GE(q.minAngleDegrees, 25.0) << h;
        EXPECT_NEAR(q.meanEdge / h, 1.0, 0.15) << h;
        EXPECT_GE(q.minEdge / h, 0.3) << h;
        EXPECT_LE(q.maxEdge / h, 1.8) << h;
        // Triangle count near the equilateral estimate area / (sqrt(3)/4 h^2) (within 20 %).
        EXPECT_NEAR(static_cast<Real>(m.triangles.size()) / (q.area / (std::sqrt(3.0) / 4 * h * h)), 1.0,
                    0.2);
        EXPECT_GT(q.interiorNodes, 0u);
        std::cout << "[ measured ] disc h = R/" << divisions << ": " << m.triangles.size()
                  << " triangles, min angle " << q.minAngleDegrees << " deg, mean edge / h " << q.meanEdge / h
                  << ", edges in [" << q.minEdge / h << ", " << q.maxEdge / h << "] h\n";
    }
}

TEST(PolygonMesher, NonConvexAndClockwisePolygonsKeepTheirArea)
{
    // An L-shape (area 0.75 m^2, a reflex corner) given clockwise, and a thin rectangle with a long
    // side much longer than h: area exact, angles as above.
    const std::vector<Vec2> lShape{{0, 0}, {0, 1}, {0.5, 1}, {0.5, 0.5}, {1, 0.5}, {1, 0}};
    for (Real h : {0.2, 0.1, 0.037})
    {
        const Quality q = quality(meshPolygonRefined(lShape, h));
        EXPECT_NEAR(q.area, 0.75, 1e-12) << h;
        EXPECT_GE(q.minAngleDegrees, 25.0) << h;
        EXPECT_NEAR(q.meanEdge / h, 1.0, 0.15) << h;
        std::cout << "[ measured ] L-shape h = " << h << ": min angle " << q.minAngleDegrees
                  << " deg, mean edge / h " << q.meanEdge / h << "\n";
    }
    const Quality bar = quality(meshPolygonRefined({{0, 0}, {0.2, 0}, {0.2, 0.02}, {0, 0.02}}, 0.005));
    EXPECT_NEAR(bar.area, 0.004, 1e-15);
    EXPECT_GE(bar.minAngleDegrees, 25.0);
}

TEST(PolygonMesher, BadInputIsRefused)
{
    const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_THROW(meshPolygonRefined(square, 0), InputError);
    EXPECT_THROW(meshPolygonRefined(square, -1), InputError);
    EXPECT_THROW(meshPolygonRefined(square, 1e-5), InputError);                          // 1e10 triangles
    EXPECT_THROW(meshPolygonRefined({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 0.1), InputError); // bow tie
    EXPECT_THROW(discOutline({0, 0}, 0, 0.1), InputError);
    EXPECT_THROW(discOutline({0, 0}, 1, 0), InputError);
    // An edge length larger than the polygon still meshes it (outline pieces of one edge each).
    EXPECT_NEAR(quality(meshPolygonRefined(square, 5)).area, 1.0, 1e-15);
}

} // namespace
} // namespace veridem::fdem
