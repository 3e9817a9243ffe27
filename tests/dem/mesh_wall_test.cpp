// Mesh walls: closest-point classification, contact elimination (one contact on a connected flat
// surface, two in a concave corner) and the normal force against the plane's.
#include "core/constants.h"
#include "core/error.h"
#include "dem/integrate.h"
#include "dem/walls/motion_table.h"
#include "dem/walls/wall.h"
#include "dem/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace veridem;
using namespace veridem::dem;

namespace
{

MeshShape shapeOf(const std::vector<Vec3>& corners)
{
    MeshReport report;
    MeshShape s;
    s.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(corners, "test", report));
    return s;
}

/// The unit square z = 0 as two triangles sharing the diagonal (0,0)-(1,1).
std::vector<Vec3> square()
{
    return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
}

/// A hexagon of 6 triangles about the shared vertex (0, 0, 0).
std::vector<Vec3> hexagon()
{
    std::vector<Vec3> c;
    for (int q = 0; q < 6; ++q)
    {
        const Real a0 = kPi / 3 * q, a1 = kPi / 3 * ((q + 1) % 6); // (welded: same corner values)
        c.insert(c.end(), {Vec3{}, Vec3{std::cos(a0), std::sin(a0), 0}, Vec3{std::cos(a1), std::sin(a1), 0}});
    }
    return c;
}

} // namespace

TEST(MeshWall, ClosestPointFeatures)
{
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    TrianglePoint p = closestPointOnTriangle({0.2, 0.2, 1}, a, b, c);
    EXPECT_EQ(p.feature, MeshFeature::Face);
    EXPECT_NEAR(length(p.point - Vec3{0.2, 0.2, 0}), 0, 1e-15);
    p = closestPointOnTriangle({0.5, -1, 0.3}, a, b, c);
    EXPECT_EQ(p.feature, MeshFeature::Edge);
    EXPECT_EQ(p.index, 0);
    EXPECT_NEAR(length(p.point - Vec3{0.5, 0, 0}), 0, 1e-15);
    p = closestPointOnTriangle({1, 1, 0}, a, b, c);
    EXPECT_EQ(p.feature, MeshFeature::Edge);
    EXPECT_EQ(p.index, 1);
    p = closestPointOnTriangle({-1, -1, 2}, a, b, c);
    EXPECT_EQ(p.feature, MeshFeature::Vertex);
    EXPECT_EQ(p.index, 0);
    p = closestPointOnTriangle({-0.5, 0.5, 0}, a, b, c);
    EXPECT_EQ(p.feature, MeshFeature::Edge);
    EXPECT_EQ(p.index, 2);
}

TEST(MeshWall, WeldsAndFindsAdjacency)
{
    MeshReport report;
    const TriangleMesh m = buildTriangleMesh(square(), "square", report);
    EXPECT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.edges.size(), 5u);
    ASSERT_EQ(report.warnings.size(), 1u); // open boundary, said once
    EXPECT_NE(report.warnings[0].find("open boundary of 4 edges"), std::string::npos);
}

TEST(MeshWall, WeldsAFloat32SeamAndSaysWhereTheOpenEdgesAre)
{
    // The square's second triangle repeats the shared corners as a float32 file would after a
    // transform: off by 1e-8 m (1e-8 of the 1.4 m diagonal, below kWeldTolerance = 1e-6). Exact
    // welding would leave 6 open edges (two separate triangles); within the tolerance the square
    // has 4, along its rim, which the warning locates: from (0, 0, 0) to (1, 1, 0).
    std::vector<Vec3> c = square();
    for (std::size_t k = 3; k < 6; ++k)
        if (c[k].x == c[k].y) // the shared corners (0, 0, 0) and (1, 1, 0)
            c[k] = c[k] + Vec3{1e-8, -1e-8, 1e-8};
    MeshReport report;
    const TriangleMesh m = buildTriangleMesh(c, "seam.stl", report);
    EXPECT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.edges.size(), 5u);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_NE(
        report.warnings[0].find("seam.stl: open boundary of 4 edges, e.g. the edge of triangle 0 from ("),
        std::string::npos)
        << report.warnings[0];
    EXPECT_NE(report.warnings[0].find("the open edges lie within (0, 0, 0) to (1, 1, 0) m"),
              std::string::npos)
        << report.warnings[0];
    // Corners 1e-5 apart (above the tolerance) stay apart: 6 open edges.
    c = square();
    for (std::size_t k = 3; k < 6; ++k)
        if (c[k].x == c[k].y)
            c[k] = c[k] + Vec3{1e-5, 0, 0};
    MeshReport apart;
    buildTriangleMesh(c, "apart.stl", apart);
    ASSERT_EQ(apart.warnings.size(), 1u);
    EXPECT_NE(apart.warnings[0].find("open boundary of 6 edges"), std::string::npos) << apart.warnings[0];
}

TEST(MeshWall, DegenerateTriangleIsRefusedWithItsIndex)
{
    std::vector<Vec3> c = square();
    c.insert(c.end(), {Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0}, Vec3{1, 1, 0}}); // collinear
    MeshReport report;
    try
    {
        buildTriangleMesh(c, "bad.stl", report);
        FAIL();
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("bad.stl: triangle 2 is degenerate"), std::string::npos)
            << e.what();
    }
}

TEST(MeshWall, NonManifoldEdgeIsNamed)
{
    std::vector<Vec3> c = square();
    c.insert(c.end(), {Vec3{0, 0, 0}, Vec3{1, 1, 0}, Vec3{0.5, 0.5, 1}}); // a fin on the diagonal
    MeshReport report;
    buildTriangleMesh(c, "fin", report);
    bool named = false;
    for (const auto& w : report.warnings)
        named = named || w.find("1 non-manifold edges") != std::string::npos;
    EXPECT_TRUE(named);
}

TEST(MeshWall, SphereOnSharedEdgeOfCoplanarTrianglesHasOneContact)
{
    const MeshShape s = shapeOf(square());
    const Real r = 0.01, z = 0.009;
    MeshContact c[kMeshSlots];
    // Exactly on the shared diagonal, then just off it either side.
    for (const Real off : {0.0, 1e-12, -1e-12, 1e-6})
    {
        const Vec3 x{0.5 + off, 0.5 - off, z};
        ASSERT_EQ(meshContacts(s, {}, x, r, c), 1) << off;
        // The plane's contact: overlap r - z and normal +z (to round-off).
        const WallGap plane = wallGap(PlaneShape{}, {}, x, r);
        EXPECT_NEAR(c[0].overlap, plane.overlap, 1e-15);
        EXPECT_NEAR(length(c[0].normal - Vec3{0, 0, 1}), 0, 1e-15);
    }
}

TEST(MeshWall, SphereOnSharedVertexOfSixTrianglesHasOneContact)
{
    const MeshShape s = shapeOf(hexagon());
    MeshContact c[kMeshSlots];
    for (const Vec3 x :
         {Vec3{0, 0, 0.009}, Vec3{1e-9, 0, 0.009}, Vec3{1e-3, 1e-3, 0.009}, Vec3{0, 0, -0.009}})
    {
        ASSERT_EQ(meshContacts(s, {}, x, 0.01, c), 1);
        EXPECT_NEAR(c[0].overlap, 0.001, 1e-15);
        EXPECT_NEAR(std::fabs(c[0].normal.z), 1, 1e-15);
    }
}

TEST(MeshWall, EdgeAndVertexNormalsAreClosestPointNormals)
{
    const MeshShape s = shapeOf(square());
    MeshContact c[kMeshSlots];
    // Beyond the open edge y = 0, below-and-outside: the edge normal points from the edge to the centre.
    ASSERT_EQ(meshContacts(s, {}, {0.5, -0.006, 0.008}, 0.011, c), 1);
    EXPECT_NEAR(length(c[0].normal - Vec3{0, -0.6, 0.8}), 0, 1e-14);
    EXPECT_NEAR(c[0].overlap, 0.001, 1e-15);
    // Beyond the corner (1, 1).
    ASSERT_EQ(meshContacts(s, {}, {1.006, 1.0, 0.008}, 0.011, c), 1);
    EXPECT_NEAR(length(c[0].normal - Vec3{0.6, 0, 0.8}), 0, 1e-14);
}

TEST(MeshWall, ConcaveCornerHasTwoContacts)
{
    // Floor z = 0 and wall x = 0 (x >= 0 side) meeting along the y axis.
    std::vector<Vec3> c = square();
    const std::vector<Vec3> wall{{0, 0, 0}, {0, 1, 1}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}};
    c.insert(c.end(), wall.begin(), wall.end());
    const MeshShape s = shapeOf(c);
    MeshContact found[kMeshSlots];
    ASSERT_EQ(meshContacts(s, {}, {0.009, 0.5, 0.008}, 0.01, found), 2);
    EXPECT_NEAR(found[0].overlap, 0.002, 1e-15); // the floor (deeper)
    EXPECT_NEAR(length(found[0].normal - Vec3{0, 0, 1}), 0, 1e-15);
    EXPECT_NEAR(found[1].overlap, 0.001, 1e-15);
    EXPECT_NEAR(length(found[1].normal - Vec3{1, 0, 0}), 0, 1e-15);
}

TEST(MeshWall, RotatedMeshMapsParticleIntoItsFrame)
{
    MeshShape s = shapeOf(square());
    rotateMesh(s, {kPi / 2, 0, 0}); // the square turns into the plane y = 0 (x-z), normal -y
    MeshContact c[kMeshSlots];
    ASSERT_EQ(meshContacts(s, {}, {0.5, -0.008, 0.5}, 0.01, c), 1);
    EXPECT_NEAR(length(c[0].normal - Vec3{0, -1, 0}), 0, 1e-15);
    EXPECT_NEAR(c[0].overlap, 0.002, 1e-15);
    EXPECT_NEAR(s.turned, kPi / 2, 1e-15);
}

TEST(MeshWall, NormalForceOnSharedEdgeEqualsThePlanes)
{
    // A resting ball centred on the shared diagonal: the force stage gives the plane's force.
    const auto force = [](Wall wall)
    {
        World world;
        Material m;
        m.density = 7800;
        m.normalStiffness = 1e5;
        world.addMaterial(m);
        world.gravity = {0, 0, -kStandardGravity};
        world.walls.push_back(std::move(wall));
        world.particles.add({0.5, 0.5, 0.0099}, {}, {}, 0.01, m.density, 0);
        prepare(world);
        step(world, 1e-6);
        return world.particles.force[0];
    };
    Wall plane;
    plane.shape = PlaneShape{};
    Wall mesh;
    mesh.shape = shapeOf(square());
    const Vec3 fp = force(plane), fm = force(mesh);
    EXPECT_NEAR(fm.z, fp.z, 1e-12 * fp.z);
    EXPECT_NEAR(fm.x, 0, 1e-12 * fp.z);
}

TEST(MeshWall, BallInConcaveCornerFeelsBothFacesInTheForceStage)
{
    // Floor z = 0 and wall x = 0 of one mesh; a ball pressed into both: two touching contacts
    // and a force with both normals' components (the plane's linear law on each: kn * overlap).
    std::vector<Vec3> c = square();
    const std::vector<Vec3> side{{0, 0, 0}, {0, 1, 1}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}};
    c.insert(c.end(), side.begin(), side.end());
    World world;
    Material m;
    m.density = 7800;
    m.normalStiffness = 1e5;
    world.addMaterial(m);
    Wall mesh;
    mesh.shape = shapeOf(c);
    world.walls.push_back(std::move(mesh));
    world.particles.add({0.009, 0.5, 0.008}, {}, {}, 0.01, m.density, 0);
    prepare(world);
    step(world, 1e-7);
    EXPECT_EQ(world.health.touchingWalls, 2u);
    const Vec3 f = world.particles.force[0];
    // Overlaps 0.002 m (floor) and 0.001 m (side): kn * overlap, to 1e-4 relative (the normal
    // damping of the half-step velocity that the contact force itself gives adds ~3e-5 of it).
    EXPECT_NEAR(f.z, 1e5 * 0.002, 1e-4 * 200);
    EXPECT_NEAR(f.x, 1e5 * 0.001, 1e-4 * 100);
}

TEST(MeshWall, OmegaTableTurnsTheMeshByItsIntegral)
{
    // omega_z(t) rising linearly from 0 to 2 rad/s over [0, 1] s: the turned angle is t^2, and the
    // midpoint rule of moveWalls integrates a linear piece exactly (round-off only).
    Wall wall;
    wall.shape = shapeOf(square());
    wall.motion.angularVelocityTable = MotionTable({0, 1}, {{0, 0, 0}, {0, 0, 2}});
    std::vector<Wall> walls{wall};
    for (int k = 0; k < 1000; ++k)
        moveWalls(walls, 1e-3);
    const MeshShape& s = std::get<MeshShape>(walls[0].shape);
    EXPECT_NEAR(s.turned, 1.0, 1e-12);
    EXPECT_NEAR(s.rotation[0].x, std::cos(1.0), 1e-12);
    EXPECT_NEAR(std::fabs(s.rotation[0].y), std::sin(1.0), 1e-12);
    EXPECT_NEAR(length(walls[0].motion.angularVelocity - Vec3{0, 0, 2 * (1 - 0.5e-3)}), 0, 1e-12);
}
