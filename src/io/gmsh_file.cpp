#include "io/gmsh_file.h"

#include "core/error.h"
#include "io/number_text.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace veridem::io
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
        const std::optional<double> v = parseFiniteNumber(t);
        if (!v)
            fail(std::string("expected ") + what + " (a finite number), got '" + t + "'");
        return *v;
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

/// Nodes per element of Gmsh's fixed-size element types (the format's table, types 1-31, 92, 93);
/// 0 for a type the format does not define.
std::size_t nodesOfType(long long type)
{
    static constexpr std::array<std::uint8_t, 32> kNodes{0,  2,  3,  4,  4, 8, 6,  5,  3,  6, 9,
                                                         10, 27, 18, 14, 1, 8, 20, 15, 13, 9, 10,
                                                         12, 15, 15, 21, 4, 5, 6,  20, 35, 56};
    if (type >= 1 && type < static_cast<long long>(kNodes.size()))
        return kNodes[static_cast<std::size_t>(type)];
    if (type == 92)
        return 64;
    if (type == 93)
        return 125;
    return 0;
}

struct Reader
{
    Tokens& tokens;
    std::unordered_map<long long, std::size_t> nodeIndex; // tag -> index into all
    std::vector<Vec3> all;
    std::vector<std::array<long long, 3>> triangles; // node tags

    void addNode(long long tag, Real x, Real y, Real z)
    {
        if (!nodeIndex.emplace(tag, all.size()).second)
            tokens.fail("node tag " + std::to_string(tag) + " appears twice");
        all.push_back({x, y, z});
    }

    long long node(long long tag)
    {
        if (!nodeIndex.count(tag))
            tokens.fail("element refers to node " + std::to_string(tag) + ", which is not in $Nodes");
        return tag;
    }

    std::size_t nodeCount(long long type)
    {
        const std::size_t n = nodesOfType(type);
        if (n == 0)
            tokens.fail("unknown element type " + std::to_string(type));
        return n;
    }

    /// One element's node tags; a triangle is kept.
    void element(long long type)
    {
        const std::size_t count = nodeCount(type);
        std::array<long long, 3> ids{};
        for (std::size_t k = 0; k < count; ++k)
        {
            const long long id = tokens.integer("element node");
            if (k < 3)
                ids[k] = id;
        }
        if (type == 2)
            triangles.push_back({node(ids[0]), node(ids[1]), node(ids[2])});
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
            element(type);
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
            nodeCount(type); // an unknown type is refused at its block header
            for (std::size_t i = 0; i < n; ++i)
            {
                tokens.integer("element tag");
                element(type);
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

GmshTriangles readGmshTriangles(std::istream& in, const std::string& source)
{
    Tokens tokens(in, source);
    Reader reader{tokens, {}, {}, {}};
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
                if (sawElements)
                    tokens.fail("a second $Elements section");
                version == 22 ? reader.elements22() : reader.elements41();
                sawElements = true;
            }
        }
        else if (t.size() > 1 && t[0] == '$' && t.rfind("$End", 0) != 0)
            reader.skipSection(t);
        else
            tokens.fail("unexpected '" + t + "' outside a section");
    }
    if (version == 0)
        throw InputError(source + ": no $MeshFormat section (not a Gmsh .msh file?)");
    if (!sawNodes || !sawElements)
        throw InputError(source + ": not a .msh mesh (missing " + (sawNodes ? "$Elements" : "$Nodes") +
                         " section)");
    if (reader.triangles.empty())
        throw InputError(source + ": the mesh has no 3-node triangles (element type 2)");
    // Keep the nodes the triangles use (not geometry points or the nodes of other elements), in
    // the order of first use.
    GmshTriangles out;
    std::unordered_map<long long, std::uint32_t> renumber;
    for (const auto& tri : reader.triangles)
    {
        std::array<std::uint32_t, 3> corners{};
        for (int c = 0; c < 3; ++c)
        {
            const auto [it, added] = renumber.emplace(tri[c], static_cast<std::uint32_t>(out.nodes.size()));
            if (added)
            {
                out.nodes.push_back(reader.all[reader.nodeIndex.at(tri[c])]);
                out.nodeTags.push_back(tri[c]);
            }
            corners[c] = it->second;
        }
        out.triangles.push_back(corners);
    }
    return out;
}

GmshTriangles readGmshTriangles(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw InputError(path + ": cannot open the mesh file");
    return readGmshTriangles(in, path);
}

} // namespace veridem::io
