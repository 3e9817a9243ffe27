#include "io/surface_mesh_reader.h"

#include "core/error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
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
        std::size_t used = 0;
        Real v = 0;
        try
        {
            v = std::stod(word, &used);
        }
        catch (const std::exception&)
        {
            used = 0;
        }
        if (used != word.size() || !std::isfinite(v))
            fail("bad number '" + word + "' (expected a finite number)");
        return v;
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

/// Gmsh 2.2: "$Nodes n / id x y z" and "$Elements n / id type ntags tags... nodes".
/// Gmsh 4.1: entity blocks of node tags then coordinates, and of elements.
std::vector<Vec3> gmsh(const std::string& text, const std::string& path, Real scale)
{
    Lines lines(text, path);
    std::vector<std::string> w;
    std::map<std::int64_t, Vec3> nodes;
    std::vector<std::array<std::int64_t, 3>> triangles;
    int major = 0;
    const auto count = [&](const std::string& word)
    {
        const std::int64_t n = lines.integer(word);
        if (n < 0 || n > (std::int64_t(1) << 32))
            lines.fail("bad count '" + word + "'");
        return n;
    };
    while (lines.next(w))
    {
        if (w[0] == "$MeshFormat")
        {
            lines.require(w, "the format line");
            if (w.size() < 2 || (w[0] != "2.2" && w[0] != "4.1"))
                lines.fail("Gmsh format '" + w[0] + "' is not supported (expected 2.2 or 4.1)");
            if (w[1] != "0")
                lines.fail("binary .msh files are not supported (save as ASCII)");
            major = w[0] == "2.2" ? 2 : 4;
        }
        else if (w[0] == "$Nodes")
        {
            if (major == 0)
                lines.fail("$Nodes before $MeshFormat");
            lines.require(w, "the node count");
            if (major == 2)
            {
                const std::int64_t n = count(w[0]);
                for (std::int64_t k = 0; k < n; ++k)
                {
                    lines.require(w, "a node 'id x y z'");
                    if (w.size() < 4)
                        lines.fail("expected a node 'id x y z'");
                    nodes[lines.integer(w[0])] =
                        scale * Vec3{lines.number(w[1]), lines.number(w[2]), lines.number(w[3])};
                }
            }
            else
            {
                if (w.size() < 4)
                    lines.fail("expected 'numEntityBlocks numNodes minTag maxTag'");
                const std::int64_t blocks = count(w[0]);
                for (std::int64_t b = 0; b < blocks; ++b)
                {
                    lines.require(w, "a node block header");
                    if (w.size() < 4)
                        lines.fail("expected 'entityDim entityTag parametric numNodes'");
                    const std::int64_t n = count(w[3]);
                    std::vector<std::int64_t> tags;
                    for (std::int64_t k = 0; k < n; ++k)
                    {
                        lines.require(w, "a node tag");
                        tags.push_back(lines.integer(w[0]));
                    }
                    for (std::int64_t k = 0; k < n; ++k)
                    {
                        lines.require(w, "node coordinates 'x y z'");
                        if (w.size() < 3)
                            lines.fail("expected node coordinates 'x y z'");
                        nodes[tags[std::size_t(k)]] =
                            scale * Vec3{lines.number(w[0]), lines.number(w[1]), lines.number(w[2])};
                    }
                }
            }
        }
        else if (w[0] == "$Elements")
        {
            if (major == 0)
                lines.fail("$Elements before $MeshFormat");
            lines.require(w, "the element count");
            const auto node = [&](const std::string& word)
            {
                const std::int64_t id = lines.integer(word);
                if (!nodes.count(id))
                    lines.fail("element names node " + word + ", which is not defined");
                return id;
            };
            if (major == 2)
            {
                const std::int64_t n = count(w[0]);
                for (std::int64_t k = 0; k < n; ++k)
                {
                    lines.require(w, "an element");
                    if (w.size() < 3)
                        lines.fail("expected an element 'id type ntags ...'");
                    const std::int64_t type = lines.integer(w[1]), tags = count(w[2]);
                    if (type != 2)
                        continue;
                    if (std::int64_t(w.size()) != 3 + tags + 3)
                        lines.fail("a triangle needs 3 nodes after its " + std::to_string(tags) + " tags");
                    const std::size_t at = std::size_t(3 + tags);
                    triangles.push_back({node(w[at]), node(w[at + 1]), node(w[at + 2])});
                }
            }
            else
            {
                if (w.size() < 4)
                    lines.fail("expected 'numEntityBlocks numElements minTag maxTag'");
                const std::int64_t blocks = count(w[0]);
                for (std::int64_t b = 0; b < blocks; ++b)
                {
                    lines.require(w, "an element block header");
                    if (w.size() < 4)
                        lines.fail("expected 'entityDim entityTag elementType numElements'");
                    const std::int64_t type = lines.integer(w[2]), n = count(w[3]);
                    for (std::int64_t k = 0; k < n; ++k)
                    {
                        lines.require(w, "an element");
                        if (type != 2)
                            continue;
                        if (w.size() != 4)
                            lines.fail("expected a triangle 'tag n1 n2 n3'");
                        triangles.push_back({node(w[1]), node(w[2]), node(w[3])});
                    }
                }
            }
        }
    }
    if (major == 0)
        throw InputError(path + ": no $MeshFormat section (not a Gmsh .msh file?)");
    std::vector<Vec3> corners;
    for (const auto& t : triangles)
        for (const std::int64_t id : t)
            corners.push_back(nodes[id]);
    if (corners.empty())
        throw InputError(path + ": no 3-node triangles (element type 2) in the mesh");
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
    {
        std::size_t used = 0;
        try
        {
            std::stod(word, &used);
        }
        catch (const std::exception&)
        {
            used = 0;
        }
        numeric = numeric && used == word.size();
    }
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
    return gmsh(readAll(path), path, scale);
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
