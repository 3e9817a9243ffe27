#include "io/surface_mesh_reader.h"

#include "core/error.h"
#include "io/gmsh_file.h"
#include "io/number_text.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace veridem::io
{

namespace
{

std::string readAll(const std::string& path)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw InputError(path + ": mesh file not found (or not a regular file)");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot open the mesh file");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Line-by-line tokens with the line number, for the ASCII formats.
class Lines
{
  public:
    Lines(const std::string& text, std::string path) : in_(text), path_(std::move(path)) {}

    /// The next non-blank line split into words; false at the end of the file.
    bool next(std::vector<std::string>& words)
    {
        std::string line;
        while (std::getline(in_, line))
        {
            ++line_;
            std::istringstream s(line);
            words.assign(std::istream_iterator<std::string>(s), std::istream_iterator<std::string>());
            if (!words.empty())
                return true;
        }
        return false;
    }
    void require(std::vector<std::string>& words, const std::string& what)
    {
        if (!next(words))
            fail("unexpected end of file, expected " + what);
    }
    std::size_t line() const { return line_; }
    [[noreturn]] void fail(const std::string& message) const
    {
        throw InputError(path_ + ":" + std::to_string(line_) + ": " + message);
    }
    Real number(const std::string& word) const
    {
        const std::optional<double> v = parseFiniteNumber(word);
        if (!v)
            fail("bad number '" + word + "' (expected a finite number)");
        return *v;
    }
    std::int64_t integer(const std::string& word) const
    {
        std::size_t used = 0;
        long long v = 0;
        try
        {
            v = std::stoll(word, &used);
        }
        catch (const std::exception&)
        {
            used = 0;
        }
        if (used != word.size())
            fail("bad integer '" + word + "'");
        return v;
    }

  private:
    std::istringstream in_;
    std::string path_;
    std::size_t line_ = 0;
};

std::vector<Vec3> asciiStl(const std::string& text, const std::string& path, Real scale)
{
    Lines lines(text, path);
    std::vector<std::string> w;
    std::vector<Vec3> corners;
    std::size_t inFacet = 0;
    bool open = false;
    while (lines.next(w))
    {
        if (w[0] == "vertex")
        {
            if (!open)
                lines.fail("'vertex' outside a facet");
            if (w.size() != 4)
                lines.fail("expected 'vertex x y z'");
            corners.push_back(scale * Vec3{lines.number(w[1]), lines.number(w[2]), lines.number(w[3])});
            ++inFacet;
        }
        else if (w[0] == "facet")
        {
            open = true;
            inFacet = 0;
        }
        else if (w[0] == "endfacet")
        {
            if (inFacet != 3)
                lines.fail("facet " + std::to_string(corners.size() / 3) + " has " + std::to_string(inFacet) +
                           " vertices, expected 3");
            open = false;
        }
        else if (w[0] != "solid" && w[0] != "outer" && w[0] != "endloop" && w[0] != "endsolid")
            lines.fail("unexpected '" + w[0] + "' in an ASCII STL file");
    }
    if (open)
        lines.fail("unexpected end of file inside a facet");
    return corners;
}

std::vector<Vec3> binaryStl(const std::string& bytes, const std::string& path, Real scale)
{
    if (bytes.size() < 84)
        throw InputError(path + ": truncated binary STL (" + std::to_string(bytes.size()) +
                         " bytes, the header alone is 84)");
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    std::vector<Vec3> corners;
    for (std::uint32_t t = 0; t < count; ++t)
    {
        const std::size_t at = 84 + std::size_t(t) * 50;
        if (at + 50 > bytes.size())
            throw InputError(path + ": truncated binary STL: the header counts " + std::to_string(count) +
                             " triangles, triangle " + std::to_string(t) + " is incomplete");
        for (int c = 0; c < 3; ++c)
        {
            float v[3];
            std::memcpy(v, bytes.data() + at + 12 + 12 * c, 12);
            const Vec3 corner{v[0], v[1], v[2]};
            if (!isFinite(corner))
                throw InputError(path + ": triangle " + std::to_string(t) + " has a non-finite coordinate");
            corners.push_back(scale * corner);
        }
    }
    return corners;
}

/// Nine-column triangle text: a header line, then per line the x y z of three corners.
std::vector<Vec3> triangleText(const std::string& text, const std::string& path, Real scale,
                               std::vector<std::size_t>* lines)
{
    Lines in(text, path);
    std::vector<std::string> w;
    const std::string expected = "expected 9 numbers per line (x y z of three corners, m)";
    if (!in.next(w))
        throw InputError(path + ": empty triangle file (" + expected + " after a header line)");
    bool numeric = true;
    for (const std::string& word : w)
        numeric = numeric && parseNumber(word).has_value();
    if (numeric)
        in.fail("expected a header line naming the nine columns before the triangles");
    std::vector<Vec3> corners;
    while (in.next(w))
    {
        if (w.size() != 9)
            in.fail(expected + ", found " + std::to_string(w.size()));
        for (int c = 0; c < 3; ++c)
            corners.push_back(scale *
                              Vec3{in.number(w[3 * c]), in.number(w[3 * c + 1]), in.number(w[3 * c + 2])});
        if (lines)
            lines->push_back(in.line());
    }
    if (corners.empty())
        throw InputError(path + ": no triangles after the header line (" + expected + ")");
    return corners;
}

} // namespace

std::vector<Vec3> readTriangleText(const std::string& path, Real scale, std::vector<std::size_t>* lines)
{
    return triangleText(readAll(path), path, scale, lines);
}

std::vector<Vec3> readStl(const std::string& path, Real scale)
{
    const std::string bytes = readAll(path);
    if (bytes.size() >= 84)
    {
        std::uint32_t count = 0;
        std::memcpy(&count, bytes.data() + 80, 4);
        if (bytes.size() == 84 + 50 * std::uint64_t(count))
            return binaryStl(bytes, path, scale);
    }
    std::size_t first = 0;
    while (first < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[first])))
        ++first;
    // (A binary header may start with "solid" too; its data holds zero bytes, ASCII text none.)
    if (bytes.compare(first, 5, "solid") == 0 && bytes.find('\0') == std::string::npos)
    {
        std::vector<Vec3> corners = asciiStl(bytes, path, scale);
        if (corners.empty())
            throw InputError(path + ": the ASCII STL file has no facets");
        return corners;
    }
    return binaryStl(bytes, path, scale);
}

std::vector<Vec3> readGmshSurface(const std::string& path, Real scale)
{
    std::istringstream text(readAll(path));
    const GmshTriangles mesh = readGmshTriangles(text, path);
    std::vector<Vec3> corners;
    corners.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        for (const std::uint32_t n : t)
            corners.push_back(scale * mesh.nodes[n]);
    return corners;
}

std::vector<Vec3> readSurfaceMesh(const std::string& path, Real scale, std::vector<std::size_t>* lines)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".stl")
        return readStl(path, scale);
    if (ext == ".msh")
        return readGmshSurface(path, scale);
    if (ext == ".txt")
        return readTriangleText(path, scale, lines);
    throw InputError(path + ": unknown mesh file type '" + ext + "' (expected .stl, .msh or .txt)");
}

} // namespace veridem::io
