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

// The walls' .msh reader is the 2D bodies' (io/gmsh_file.h): volumes and second-order elements
// are skipped by the format's node counts, an element type the format does not define is refused.
TEST(SurfaceMeshReader, GmshSkipsOtherElementsAndRefusesUnknownTypes)
{
    const std::string withTet =
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 "
        "0.5\n5 0 0 1\n$EndNodes\n$Elements\n4\n1 4 2 0 1 1 2 3 5\n2 2 2 0 1 1 2 3\n3 11 0 1 2 3 5 1 2 3 4 "
        "5 1\n4 2 2 0 1 1 3 4\n$EndElements\n";
    EXPECT_EQ(io::readSurfaceMesh(write("tet.msh", withTet)), kSquare);
    std::string unknown = withTet;
    unknown.replace(unknown.find("3 11 0"), 6, "3 99 0");
    EXPECT_NE(errorOf(write("u.msh", unknown)).find("u.msh:16: unknown element type 99"), std::string::npos)
        << errorOf(write("u.msh", unknown));
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

namespace
{
// The square as nine-column triangle text (the DEM8 walls' layout: a header, tabs between columns).
std::string triangleText()
{
    std::string s = "vertex1_X[m] vertex1_Y[m] vertex1_Z[m] vertex2_X[m] vertex2_Y[m] vertex2_Z[m] "
                    "vertex3_X[m] vertex3_Y[m] vertex3_Z[m]\n";
    for (std::size_t t = 0; t < 2; ++t)
    {
        for (int c = 0; c < 3; ++c)
        {
            const Vec3& v = kSquare[3 * t + c];
            s += std::to_string(v.x) + "\t" + std::to_string(v.y) + "\t" + std::to_string(v.z) +
                 (c < 2 ? "\t" : "\n");
        }
    }
    return s;
}

/// The error of reading `text` as a triangle file and building its mesh, as a [[wall]] does.
std::string textMeshError(const std::string& name, const std::string& text)
{
    try
    {
        std::vector<std::size_t> lines;
        const std::string path = write(name, text);
        const std::vector<Vec3> corners = io::readSurfaceMesh(path, 1, &lines);
        dem::MeshReport report;
        dem::buildTriangleMesh(corners, path, report, lines);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}
} // namespace

TEST(SurfaceMeshReader, TriangleTextGivesTheSameTrianglesAsStl)
{
    std::vector<std::size_t> lines;
    EXPECT_EQ(io::readSurfaceMesh(write("square.txt", triangleText()), 1, &lines),
              io::readStl(write("a.stl", asciiStl())));
    EXPECT_EQ(lines, (std::vector<std::size_t>{2, 3}));
    // Blank lines are skipped and counted; scale multiplies as for STL.
    lines.clear();
    const auto scaled = io::readTriangleText(write("s.TXT", "\n" + triangleText() + "\n"), 0.001, &lines);
    EXPECT_EQ(scaled[2], (Vec3{0.001, 0.001, 0}));
    EXPECT_EQ(lines, (std::vector<std::size_t>{3, 4}));
    // The welding of buildTriangleMesh applies: the square's 6 corners are 4 vertices.
    dem::MeshReport report;
    EXPECT_EQ(dem::buildTriangleMesh(scaled, "s", report).vertices.size(), 4u);
}

TEST(SurfaceMeshReader, BadTriangleTextNamesFileLineAndWhatWasExpected)
{
    const std::string header = "x1 y1 z1 x2 y2 z2 x3 y3 z3\n";
    const std::string good = "0 0 0 1 0 0 1 1 0\n";
    const auto error = [&](const std::string& name, const std::string& text)
    { return textMeshError(name, text); };
    EXPECT_NE(error("c.txt", header + good + "0 0 0 1 0 0 1 1\n")
                  .find("c.txt:3: expected 9 numbers per line (x y z of three corners, m), found 8"),
              std::string::npos);
    EXPECT_NE(error("w.txt", header + "0 0 0 1 0 0 1 1 0 7\n").find("w.txt:2: expected 9 numbers per line"),
              std::string::npos);
    EXPECT_NE(error("n.txt", header + "0 0 0 1 zero 0 1 1 0\n")
                  .find("n.txt:2: bad number 'zero' (expected a finite number)"),
              std::string::npos);
    EXPECT_NE(error("nan.txt", header + good + "0 0 0 1 0 nan 1 1 0\n").find("nan.txt:3: bad number 'nan'"),
              std::string::npos);
    // Collinear corners (zero area) and a repeated corner: refused by buildTriangleMesh with the line.
    EXPECT_NE(
        error("d.txt", header + good + "\n0 0 0 1 0 0 2 0 0\n").find("d.txt:4: triangle 1 is degenerate"),
        std::string::npos);
    EXPECT_NE(error("r.txt", header + "0 0 0 0 0 0 1 1 0\n").find("r.txt:2: triangle 0 is degenerate"),
              std::string::npos);
    EXPECT_NE(error("h.txt", good).find("h.txt:1: expected a header line naming the nine columns"),
              std::string::npos);
    EXPECT_NE(error("e.txt", header).find("e.txt: no triangles after the header line"), std::string::npos);
}
