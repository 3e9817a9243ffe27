// Surface-mesh readers: ASCII and binary STL give the same triangles, Gmsh 2.2 and 4.1 the same
// mesh, scale multiplies, and bad files are refused naming file and line or triangle.
#include "core/error.h"
#include "dem/walls/triangle_mesh.h"
#include "io/surface_mesh_reader.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace veridem;

namespace
{

std::string tempPath(const std::string& name)
{
    return (std::filesystem::temp_directory_path() / ("veridem_mesh_reader_" + name)).string();
}

std::string write(const std::string& name, const std::string& content)
{
    const std::string path = tempPath(name);
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

// Two triangles of the unit square (float-exact coordinates).
const std::vector<Vec3> kSquare{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0.5}};

std::string asciiStl()
{
    std::string s = "solid square\n";
    for (std::size_t t = 0; t < 2; ++t)
    {
        s += "  facet normal 0 0 1\n    outer loop\n";
        for (int c = 0; c < 3; ++c)
        {
            const Vec3& v = kSquare[3 * t + c];
            s += "      vertex " + std::to_string(v.x) + " " + std::to_string(v.y) + " " +
                 std::to_string(v.z) + "\n";
        }
        s += "    endloop\n  endfacet\n";
    }
    return s + "endsolid square\n";
}

std::string binaryStl(std::uint32_t count, std::size_t triangles)
{
    std::string s(80, ' ');
    s.replace(0, 5, "solid"); // a binary header may start with "solid" too
    s.append(reinterpret_cast<const char*>(&count), 4);
    for (std::size_t t = 0; t < triangles; ++t)
    {
        float f[12] = {0, 0, 1};
        for (int c = 0; c < 3; ++c)
        {
            const Vec3& v = kSquare[3 * t + c];
            f[3 + 3 * c] = float(v.x);
            f[4 + 3 * c] = float(v.y);
            f[5 + 3 * c] = float(v.z);
        }
        s.append(reinterpret_cast<const char*>(f), 48);
        s.append(2, '\0');
    }
    return s;
}

std::string errorOf(const std::string& path)
{
    try
    {
        io::readSurfaceMesh(path);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST(SurfaceMeshReader, AsciiAndBinaryStlAgree)
{
    const auto ascii = io::readStl(write("a.stl", asciiStl()));
    const auto binary = io::readStl(write("b.stl", binaryStl(2, 2)));
    EXPECT_EQ(ascii, kSquare);
    EXPECT_EQ(binary, kSquare);
    const auto scaled = io::readSurfaceMesh(write("s.STL", binaryStl(2, 2)), 0.001);
    EXPECT_EQ(scaled[2], (Vec3{0.001, 0.001, 0}));
    dem::MeshReport report;
    EXPECT_EQ(dem::buildTriangleMesh(ascii, "a", report).vertices.size(), 4u);
}

TEST(SurfaceMeshReader, GmshFormats)
{
    const std::string v22 =
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 "
        "0.5\n$EndNodes\n$Elements\n3\n1 1 2 0 1 1 2\n2 2 2 0 1 1 2 3\n3 2 2 0 1 1 3 "
        "4\n$EndElements\n";
    const std::string v41 =
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 "
        "0\n1 1 0\n0 1 0.5\n$EndNodes\n$Elements\n2 3 1 3\n1 1 1 1\n1 1 2\n2 1 2 2\n2 1 2 3\n3 1 "
        "3 4\n$EndElements\n";
    EXPECT_EQ(io::readSurfaceMesh(write("v22.msh", v22)), kSquare);
    EXPECT_EQ(io::readSurfaceMesh(write("v41.msh", v41)), kSquare);
}

TEST(SurfaceMeshReader, BadFilesAreNamed)
{
    EXPECT_NE(errorOf(tempPath("missing.stl")).find("missing.stl: mesh file not found"), std::string::npos);
    // 84 + 50 n does not match: read as binary, triangle 1 is incomplete.
    EXPECT_NE(errorOf(write("t.stl", binaryStl(2, 2).substr(0, 84 + 70))).find("triangle 1 is incomplete"),
              std::string::npos);
    std::string bad = asciiStl();
    bad.replace(bad.find("vertex 1.000000"), 15, "vertex 1.0x0000");
    EXPECT_NE(errorOf(write("n.stl", bad)).find("n.stl:5: bad number '1.0x0000'"), std::string::npos)
        << errorOf(write("n.stl", bad));
    EXPECT_NE(errorOf(write("u.obj", "x")).find("unknown mesh file type"), std::string::npos);
    EXPECT_NE(errorOf(write("b.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n")).find("b.msh:2: binary"),
              std::string::npos);
}
