#include "core/error.h"
#include "fdem/elements/cst.h"
#include "fdem/gmsh_reader.h"
#include "fdem/mesher.h"

#include <gtest/gtest.h>

#include <sstream>

namespace veridem::fdem
{
namespace
{

Real totalArea(const TriangleMesh& m)
{
    Real a = 0;
    for (const auto& t : m.triangles)
    {
        const Real s = signedArea(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
        EXPECT_GT(s, 0) << "triangles must be counter-clockwise";
        a += s;
    }
    return a;
}

TEST(Mesher, RectangleHasTwoTrianglesPerCellAndTheRightArea)
{
    for (auto pattern : {DiagonalPattern::Right, DiagonalPattern::Alternate})
    {
        const TriangleMesh m = meshRectangle({1, 2}, {0.3, 0.2}, 3, 2, pattern);
        EXPECT_EQ(m.points.size(), 12u);
        EXPECT_EQ(m.triangles.size(), 12u);
        EXPECT_NEAR(totalArea(m), 0.06, 1e-15);
    }
}

TEST(Mesher, PolygonIsTriangulatedByEarClipping)
{
    // an L shape given clockwise
    const std::vector<Vec2> outline{{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
    const TriangleMesh m = meshPolygon(outline);
    EXPECT_EQ(m.triangles.size(), 4u);
    EXPECT_NEAR(totalArea(m), 3, 1e-14);
}

TEST(Mesher, BadInputIsRejected)
{
    EXPECT_THROW(meshRectangle({0, 0}, {0, 1}, 2, 2), InputError);
    EXPECT_THROW(meshRectangle({0, 0}, {1, 1}, 0, 2), InputError);
    EXPECT_THROW(meshPolygon({{0, 0}, {1, 0}}), InputError);
    EXPECT_THROW(meshPolygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), InputError); // bow tie
}

TEST(Mesh, ValidationRejectsDegenerateAndInvertedTriangles)
{
    TriangleMesh m;
    m.points = {{0, 0}, {1, 0}, {2, 0}, {0, 1}};
    m.triangles = {{0, 1, 2}};
    EXPECT_THROW(validatedMesh(m, "test"), InputError);
    m.triangles = {{0, 1, 3}, {1, 2, 3}, {0, 3, 1}};
    try
    {
        validatedMesh(m, "test");
        FAIL() << "expected InputError";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("inverted"), std::string::npos) << e.what();
    }
    m.triangles = {{0, 3, 1}}; // all clockwise: flipped, not an error
    EXPECT_NO_THROW(validatedMesh(m, "test"));
    m.triangles = {{0, 1, 7}};
    EXPECT_THROW(validatedMesh(m, "test"), InputError);
}

TEST(GmshReader, ReadsFormat22And41Alike)
{
    const TriangleMesh a = readGmsh(std::string(VERIDEM_FDEM_TEST_DATA) + "/square_v22.msh");
    const TriangleMesh b = readGmsh(std::string(VERIDEM_FDEM_TEST_DATA) + "/square_v41.msh");
    for (const TriangleMesh* m : {&a, &b})
    {
        EXPECT_EQ(m->points.size(), 5u);
        EXPECT_EQ(m->triangles.size(), 4u);
        EXPECT_NEAR(totalArea(*m), 0.0025, 1e-16);
    }
}

TEST(GmshReader, MalformedFilesGiveOneLineErrors)
{
    const std::string dir = VERIDEM_FDEM_TEST_DATA;
    for (const char* name : {"/truncated.msh", "/inverted.msh", "/does_not_exist.msh"})
    {
        try
        {
            readGmsh(dir + name);
            FAIL() << "expected InputError for " << name;
        }
        catch (const InputError& e)
        {
            const std::string message = e.what();
            EXPECT_EQ(message.find('\n'), std::string::npos);
            EXPECT_NE(message.find(name + 1), std::string::npos) << message;
        }
    }
    try
    {
        readGmsh(dir + "/truncated.msh");
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("truncated.msh:8:"), std::string::npos) << e.what();
    }
    std::istringstream binary("$MeshFormat\n4.1 1 8\n$EndMeshFormat\n");
    EXPECT_THROW(readGmsh(binary, "binary.msh"), InputError);
    std::istringstream version("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n");
    EXPECT_THROW(readGmsh(version, "v3.msh"), InputError);
    std::istringstream out3d("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 1\n$EndNodes\n");
    EXPECT_THROW(readGmsh(out3d, "3d.msh"), InputError);
}

} // namespace
} // namespace veridem::fdem
