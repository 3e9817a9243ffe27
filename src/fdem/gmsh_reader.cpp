#include "fdem/gmsh_reader.h"

#include "core/error.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace veridem::fdem
{

namespace
{

/// Whitespace-separated tokens with the line number of the last one read, for error messages.
class Tokens
{
  public:
    Tokens(std::istream& in, std::string source) : in_(in), source_(std::move(source))
    {
        // The stream's size bounds every declared count (each entry takes at least two bytes), so a
        // short file declaring 1e8 nodes is refused before anything is allocated for them.
        const auto here = in_.tellg();
        if (here < 0)
        {
            in_.clear();
            return;
        }
        if (in_.seekg(0, std::ios::end))
        {
            const auto end = in_.tellg();
            if (end >= here)
                bytes_ = static_cast<long long>(end - here);
        }
        in_.clear();
        in_.seekg(here);
    }

    [[noreturn]] void fail(const std::string& what) const
    {
        throw InputError(source_ + ":" + std::to_string(line_) + ": " + what);
    }

    bool next(std::string& token)
    {
        while (!(words_ >> token))
        {
            std::string text;
            if (!std::getline(in_, text))
                return false;
            ++line_;
            words_.clear();
            words_.str(text);
        }
        return true;
    }

    std::string word(const char* what)
    {
        std::string t;
        if (!next(t))
            fail(std::string("unexpected end of file, expected ") + what);
        return t;
    }

    long long integer(const char* what)
    {
        const std::string t = word(what);
        std::size_t used = 0;
        long long v = 0;
        try
        {
            v = std::stoll(t, &used);
        }
        catch (const std::exception&)
        {
            used = 0;
        }
        if (used != t.size())
            fail(std::string("expected ") + what + " (an integer), got '" + t + "'");
        return v;
    }

    std::size_t count(const char* what)
    {
        const long long v = integer(what);
        if (v < 0 || v > 100000000)
            fail(std::string(what) + " out of range: " + std::to_string(v));
        if (bytes_ >= 0 && v > bytes_ / 2)
            fail(std::string(what) + " " + std::to_string(v) + " cannot fit in a file of " +
                 std::to_string(bytes_) + " bytes (each entry takes at least 2)");
        return static_cast<std::size_t>(v);
    }

    Real real(const char* what)
    {
        const std::string t = word(what);
        std::size_t used = 0;
        double v = 0;
        try
        {
            v = std::stod(t, &used);
        }
        catch (const std::exception&)
        {
            used = 0;
        }
        if (used != t.size() || !std::isfinite(v))
            fail(std::string("expected ") + what + " (a finite number), got '" + t + "'");
        return v;
    }

    void expect(const std::string& keyword)
    {
        const std::string t = word(keyword.c_str());
        if (t != keyword)
            fail("expected " + keyword + ", got '" + t + "'");
    }

    /// Restarts the token stream at the next line (skips the rest of the current line).
    void skipLine() { words_.str(""), words_.clear(); }

  private:
    std::istream& in_;
    std::string source_;
    std::istringstream words_;
    std::size_t line_ = 0;
    long long bytes_ = -1; // size of the stream from where reading started; -1 if unknown
};

struct Reader
{
    Tokens& tokens;
    std::unordered_map<long long, std::uint32_t> nodeIndex;
    TriangleMesh mesh;

    void addNode(long long tag, Real x, Real y, Real z)
    {
        if (std::abs(z) > 1e-12 * (1 + std::abs(x) + std::abs(y)))
            tokens.fail("node " + std::to_string(tag) + " has z = " + std::to_string(z) +
                        "; a 2D mesh must lie in the x-y plane");
        if (!nodeIndex.emplace(tag, static_cast<std::uint32_t>(mesh.points.size())).second)
            tokens.fail("node tag " + std::to_string(tag) + " appears twice");
        mesh.points.push_back({x, y});
    }

    std::uint32_t node(long long tag)
    {
        const auto it = nodeIndex.find(tag);
        if (it == nodeIndex.end())
            tokens.fail("element refers to node " + std::to_string(tag) + ", which is not in $Nodes");
        return it->second;
    }

    /// Number of nodes of the Gmsh element types we may meet (skipped unless triangles).
    std::size_t nodesOfType(long long type)
    {
        switch (type)
        {
        case 15:
            return 1; // point
        case 1:
            return 2; // line
        case 2:
            return 3; // triangle
        case 3:
            return 4; // quadrangle
        case 4:
            return 4; // tetrahedron
        case 8:
            return 3; // 3-node line
        case 9:
            return 6; // 6-node triangle
        default:
            tokens.fail("unsupported element type " + std::to_string(type) +
                        " (2D meshes of 3-node triangles expected)");
        }
    }

    void nodes22()
    {
        const std::size_t n = tokens.count("number of nodes");
        for (std::size_t i = 0; i < n; ++i)
        {
            const long long tag = tokens.integer("node tag");
            const Real x = tokens.real("x"), y = tokens.real("y"), z = tokens.real("z");
            addNode(tag, x, y, z);
        }
        tokens.expect("$EndNodes");
    }

    void elements22()
    {
        const std::size_t n = tokens.count("number of elements");
        for (std::size_t i = 0; i < n; ++i)
        {
            tokens.integer("element tag");
            const long long type = tokens.integer("element type");
            const std::size_t tags = tokens.count("number of tags");
            for (std::size_t k = 0; k < tags; ++k)
                tokens.integer("element tag value");
            const std::size_t count = nodesOfType(type);
            std::array<long long, 6> ids{};
            for (std::size_t k = 0; k < count; ++k)
                ids[k] = tokens.integer("element node");
            if (type == 2)
                mesh.triangles.push_back({node(ids[0]), node(ids[1]), node(ids[2])});
        }
        tokens.expect("$EndElements");
    }

    void nodes41()
    {
        const std::size_t blocks = tokens.count("number of entity blocks");
        tokens.count("number of nodes");
        tokens.integer("minimum node tag");
        tokens.integer("maximum node tag");
        for (std::size_t b = 0; b < blocks; ++b)
        {
            const long long dim = tokens.integer("entity dimension");
            tokens.integer("entity tag");
            const long long parametric = tokens.integer("parametric flag");
            const std::size_t n = tokens.count("number of nodes in block");
            std::vector<long long> tags(n);
            for (auto& t : tags)
                t = tokens.integer("node tag");
            for (std::size_t i = 0; i < n; ++i)
            {
                const Real x = tokens.real("x"), y = tokens.real("y"), z = tokens.real("z");
                if (parametric)
                    for (long long k = 0; k < std::min<long long>(dim, 2); ++k)
                        tokens.real("parametric coordinate");
                addNode(tags[i], x, y, z);
            }
        }
        tokens.expect("$EndNodes");
    }

    void elements41()
    {
        const std::size_t blocks = tokens.count("number of entity blocks");
        tokens.count("number of elements");
        tokens.integer("minimum element tag");
        tokens.integer("maximum element tag");
        for (std::size_t b = 0; b < blocks; ++b)
        {
            tokens.integer("entity dimension");
            tokens.integer("entity tag");
            const long long type = tokens.integer("element type");
            const std::size_t n = tokens.count("number of elements in block");
            const std::size_t count = nodesOfType(type);
            for (std::size_t i = 0; i < n; ++i)
            {
                tokens.integer("element tag");
                std::array<long long, 6> ids{};
                for (std::size_t k = 0; k < count; ++k)
                    ids[k] = tokens.integer("element node");
                if (type == 2)
                    mesh.triangles.push_back({node(ids[0]), node(ids[1]), node(ids[2])});
            }
        }
        tokens.expect("$EndElements");
    }

    void skipSection(const std::string& name)
    {
        const std::string end = "$End" + name.substr(1);
        std::string t;
        while (tokens.next(t))
            if (t == end)
                return;
        tokens.fail("section " + name + " has no " + end);
    }
};

} // namespace

TriangleMesh readGmsh(std::istream& in, const std::string& source)
{
    Tokens tokens(in, source);
    Reader reader{tokens, {}, {}};
    std::string t;
    int version = 0; // 22 or 41
    bool sawNodes = false, sawElements = false;
    while (tokens.next(t))
    {
        if (t == "$MeshFormat")
        {
            const std::string v = tokens.word("format version");
            const long long fileType = tokens.integer("file type");
            tokens.integer("data size");
            if (v == "2.2")
                version = 22;
            else if (v == "4.1")
                version = 41;
            else
                tokens.fail("unsupported .msh version " + v + " (2.2 and 4.1 are read)");
            if (fileType != 0)
                tokens.fail("binary .msh files are not read; save as ASCII (Mesh.Binary = 0)");
            tokens.expect("$EndMeshFormat");
        }
        else if (t == "$Nodes" || t == "$Elements")
        {
            if (version == 0)
                tokens.fail(t + " before $MeshFormat");
            if (t == "$Nodes")
            {
                if (sawNodes)
                    tokens.fail("a second $Nodes section");
                version == 22 ? reader.nodes22() : reader.nodes41();
                sawNodes = true;
            }
            else
            {
                if (!sawNodes)
                    tokens.fail("$Elements before $Nodes");
                version == 22 ? reader.elements22() : reader.elements41();
                sawElements = true;
            }
        }
        else if (t.size() > 1 && t[0] == '$' && t.rfind("$End", 0) != 0)
            reader.skipSection(t);
        else
            tokens.fail("unexpected '" + t + "' outside a section");
    }
    if (!sawNodes || !sawElements)
        throw InputError(source + ": not a .msh mesh (missing " + (sawNodes ? "$Elements" : "$Nodes") +
                         " section)");
    if (reader.mesh.triangles.empty())
        throw InputError(source + ": the mesh has no 3-node triangles (element type 2)");
    // Drop nodes that no triangle uses (geometry points, lines): keep the mesh compact.
    std::vector<std::uint32_t> renumber(reader.mesh.points.size(), UINT32_MAX);
    TriangleMesh out;
    for (auto tri : reader.mesh.triangles)
    {
        for (auto& n : tri)
        {
            if (renumber[n] == UINT32_MAX)
            {
                renumber[n] = static_cast<std::uint32_t>(out.points.size());
                out.points.push_back(reader.mesh.points[n]);
            }
            n = renumber[n];
        }
        out.triangles.push_back(tri);
    }
    return validatedMesh(std::move(out), source);
}

TriangleMesh readGmsh(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw InputError(path + ": cannot open the mesh file");
    return readGmsh(in, path);
}

} // namespace veridem::fdem
