#include "dem/walls/triangle_mesh.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>

namespace veridem::dem
{

namespace
{

/// x with 3 significant digits.
std::string number(Real x)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

/// "(x, y, z)" [m].
std::string point(const Vec3& x)
{
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", x.x, x.y, x.z);
    return text;
}

/// "the edge of triangle T from (..) to (..)" for edge g.
std::string describeEdge(const TriangleMesh& m, std::size_t g)
{
    return "the edge of triangle " + std::to_string(m.edgeUsers[m.edgeStart[g]] / 3) + " from " +
           point(m.vertices[m.edges[g][0]]) + " to " + point(m.vertices[m.edges[g][1]]);
}

/// Edges of the mesh and their users (triangle * 3 + local edge), and each triangle's edge ids.
void buildEdges(TriangleMesh& m)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> ids;
    std::vector<std::vector<std::uint32_t>> users;
    m.triangleEdges.resize(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (int e = 0; e < 3; ++e)
        {
            std::uint32_t a = m.triangles[t][e], b = m.triangles[t][(e + 1) % 3];
            if (a > b)
                std::swap(a, b);
            const auto [it, added] = ids.try_emplace({a, b}, static_cast<std::uint32_t>(m.edges.size()));
            if (added)
            {
                m.edges.push_back({a, b});
                users.emplace_back();
            }
            users[it->second].push_back(static_cast<std::uint32_t>(t * 3 + e));
            m.triangleEdges[t][e] = it->second;
        }
    m.edgeStart.assign(1, 0);
    for (const auto& u : users)
    {
        m.edgeUsers.insert(m.edgeUsers.end(), u.begin(), u.end());
        m.edgeStart.push_back(static_cast<std::uint32_t>(m.edgeUsers.size()));
    }
    std::vector<std::vector<std::uint32_t>> neighbours(m.vertices.size());
    for (const auto& e : m.edges)
    {
        neighbours[e[0]].push_back(e[1]);
        neighbours[e[1]].push_back(e[0]);
    }
    m.vertexStart.assign(1, 0);
    for (const auto& n : neighbours)
    {
        m.vertexNeighbours.insert(m.vertexNeighbours.end(), n.begin(), n.end());
        m.vertexStart.push_back(static_cast<std::uint32_t>(m.vertexNeighbours.size()));
    }
}

/// True unless an axis separates the triangle (a, b, c) from the cube of half-size h about
/// `centre` [m]: the triangle's normal or an edge crossed with a cube axis (the separating-axis
/// test of Akenine-Moller 2001; the cube's own axes are the caller's box test). h is taken
/// larger by a relative 1e-6, so round-off never drops a triangle that meets the cube.
bool triangleMeetsCube(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& centre, Real h)
{
    const Vec3 v[3] = {a - centre, b - centre, c - centre};
    const Real slack = h * (1 + 1e-6);
    const auto separates = [&](const Vec3& axis)
    {
        const Real p0 = dot(axis, v[0]), p1 = dot(axis, v[1]), p2 = dot(axis, v[2]);
        const Real reach = slack * (std::fabs(axis.x) + std::fabs(axis.y) + std::fabs(axis.z));
        return std::fmin(p0, std::fmin(p1, p2)) > reach || std::fmax(p0, std::fmax(p1, p2)) < -reach;
    };
    const Vec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    if (separates(cross(edges[0], edges[1])))
        return false;
    for (const Vec3& e : edges)
        if (separates(Vec3{0, -e.z, e.y}) || separates(Vec3{e.z, 0, -e.x}) || separates(Vec3{-e.y, e.x, 0}))
            return false;
    return true;
}

/// The uniform grid: cell edge about the median triangle extent (at least 1/256 of the diagonal,
/// at most 8 cells per triangle overall), each triangle listed in every cell of its box that it
/// meets (triangleMeetsCube: a long sliver, as in a fan of an end disk, is not listed in the many
/// cells of its box that it misses). A triangle within r of a point meets a cell of the point's
/// box of half-size r, so trianglesNear still gives every triangle that can touch a sphere.
void buildGrid(TriangleMesh& m)
{
    std::vector<Real> extents;
    extents.reserve(m.triangles.size());
    for (const auto& t : m.triangles)
    {
        Vec3 lo = m.vertices[t[0]], hi = lo;
        for (int c = 1; c < 3; ++c)
        {
            const Vec3& v = m.vertices[t[c]];
            lo = {std::fmin(lo.x, v.x), std::fmin(lo.y, v.y), std::fmin(lo.z, v.z)};
            hi = {std::fmax(hi.x, v.x), std::fmax(hi.y, v.y), std::fmax(hi.z, v.z)};
        }
        extents.push_back(std::fmax(hi.x - lo.x, std::fmax(hi.y - lo.y, hi.z - lo.z)));
    }
    std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
    const Real medianExtent = extents[extents.size() / 2];
    const Vec3 extent = m.upper - m.lower;
    Real cell = std::fmax(medianExtent, m.size / 256);
    const auto count = [&](Real c)
    {
        return std::array<int, 3>{1 + static_cast<int>(extent.x / c), 1 + static_cast<int>(extent.y / c),
                                  1 + static_cast<int>(extent.z / c)};
    };
    std::array<int, 3> n = count(cell);
    const double budget = 8.0 * Real(m.triangles.size()) + 64;
    while (double(n[0]) * n[1] * n[2] > budget)
    {
        cell *= 1.25;
        n = count(cell);
    }
    m.cell = cell;
    m.cells = n;
    m.gridOrigin = m.lower;
    const std::size_t total = std::size_t(n[0]) * n[1] * n[2];
    std::vector<std::vector<std::uint32_t>> lists(total);
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
    {
        Vec3 lo = m.vertices[m.triangles[t][0]], hi = lo;
        for (int c = 1; c < 3; ++c)
        {
            const Vec3& v = m.vertices[m.triangles[t][c]];
            lo = {std::fmin(lo.x, v.x), std::fmin(lo.y, v.y), std::fmin(lo.z, v.z)};
            hi = {std::fmax(hi.x, v.x), std::fmax(hi.y, v.y), std::fmax(hi.z, v.z)};
        }
        const auto index = [&](Real value, Real origin, int cells)
        { return std::clamp(static_cast<int>((value - origin) / cell), 0, cells - 1); };
        const Vec3 &a = m.vertices[m.triangles[t][0]], &b = m.vertices[m.triangles[t][1]],
                   &c = m.vertices[m.triangles[t][2]];
        for (int i = index(lo.x, m.lower.x, n[0]); i <= index(hi.x, m.lower.x, n[0]); ++i)
            for (int j = index(lo.y, m.lower.y, n[1]); j <= index(hi.y, m.lower.y, n[1]); ++j)
                for (int k = index(lo.z, m.lower.z, n[2]); k <= index(hi.z, m.lower.z, n[2]); ++k)
                {
                    const Vec3 centre = m.lower + cell * Vec3{i + 0.5, j + 0.5, k + 0.5};
                    if (triangleMeetsCube(a, b, c, centre, 0.5 * cell))
                        lists[(std::size_t(k) * n[1] + j) * n[0] + i].push_back(
                            static_cast<std::uint32_t>(t));
                }
    }
    m.cellStart.assign(1, 0);
    for (const auto& l : lists)
    {
        m.cellTriangles.insert(m.cellTriangles.end(), l.begin(), l.end());
        m.cellStart.push_back(static_cast<std::uint32_t>(m.cellTriangles.size()));
    }
}

} // namespace

TriangleMesh buildTriangleMesh(const std::vector<Vec3>& corners, const std::string& source,
                               MeshReport& report, const std::vector<std::size_t>& lines)
{
    if (corners.empty() || corners.size() % 3 != 0)
        throw InputError(source + ": the mesh has no triangles");
    TriangleMesh m;
    m.lower = m.upper = corners[0];
    Real farthest = 0; // the largest coordinate's magnitude [m]
    for (const Vec3& c : corners)
    {
        if (!isFinite(c))
            throw InputError(source + ": a vertex coordinate is not finite");
        m.lower = {std::fmin(m.lower.x, c.x), std::fmin(m.lower.y, c.y), std::fmin(m.lower.z, c.z)};
        m.upper = {std::fmax(m.upper.x, c.x), std::fmax(m.upper.y, c.y), std::fmax(m.upper.z, c.z)};
        farthest = std::fmax(farthest, std::fmax(std::fabs(c.x), std::fmax(std::fabs(c.y), std::fabs(c.z))));
    }
    m.size = length(m.upper - m.lower);
    const Real minTwiceArea = 1e-12 * m.size * m.size;
    // Welding: a corner joins the first vertex (in file order) within `tolerance` in every
    // coordinate, found on a grid of that cell size (the 27 cells around it).
    const Real tolerance = kWeldTolerance * std::fmax(m.size, farthest);
    std::map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>> weld;
    const auto cellOf = [&](const Vec3& x)
    {
        return std::array<std::int64_t, 3>{std::llround(x.x / tolerance), std::llround(x.y / tolerance),
                                           std::llround(x.z / tolerance)};
    };
    const auto weldedIndex = [&](const Vec3& x)
    {
        const std::array<std::int64_t, 3> cell = cellOf(x);
        std::uint32_t found = TriangleMesh::kNone;
        for (std::int64_t i = -1; i <= 1; ++i)
            for (std::int64_t j = -1; j <= 1; ++j)
                for (std::int64_t k = -1; k <= 1; ++k)
                {
                    const auto near = weld.find({cell[0] + i, cell[1] + j, cell[2] + k});
                    if (near == weld.end())
                        continue;
                    for (const std::uint32_t v : near->second)
                    {
                        const Vec3 d = m.vertices[v] - x;
                        if (std::fabs(d.x) <= tolerance && std::fabs(d.y) <= tolerance &&
                            std::fabs(d.z) <= tolerance)
                            found = std::min(found, v);
                    }
                }
        if (found == TriangleMesh::kNone)
        {
            found = static_cast<std::uint32_t>(m.vertices.size());
            m.vertices.push_back(x);
            weld[cell].push_back(found);
        }
        return found;
    };
    for (std::size_t t = 0; t < corners.size() / 3; ++t)
    {
        std::array<std::uint32_t, 3> tri{};
        for (int c = 0; c < 3; ++c)
            tri[c] = weldedIndex(corners[3 * t + c]);
        const Vec3 n =
            cross(m.vertices[tri[1]] - m.vertices[tri[0]], m.vertices[tri[2]] - m.vertices[tri[0]]);
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] || !(length(n) > minTwiceArea))
            throw InputError(source + (t < lines.size() ? ":" + std::to_string(lines[t]) : std::string()) +
                             ": triangle " + std::to_string(t) +
                             " is degenerate (zero area relative to the mesh size; expected three distinct, "
                             "non-collinear corners)");
        m.triangles.push_back(tri);
        m.normals.push_back(n / length(n));
    }
    m.inward.resize(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (int e = 0; e < 3; ++e)
        {
            const Vec3& a = m.vertices[m.triangles[t][e]];
            const Vec3& b = m.vertices[m.triangles[t][(e + 1) % 3]];
            const Vec3& w = m.vertices[m.triangles[t][(e + 2) % 3]];
            const Vec3 u = (b - a) / length(b - a);
            m.inward[t][e] = normalizedOrZero((w - a) - dot(w - a, u) * u);
        }
    m.bounds.resize(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
    {
        const Vec3& a = m.vertices[m.triangles[t][0]];
        m.bounds[t] = {a, m.normals[t], m.inward[t], dot(a - m.vertices[m.triangles[t][1]], m.inward[t][1])};
    }
    buildEdges(m);
    std::size_t open = 0, nonManifold = 0, example = 0, firstOpen = 0;
    for (std::size_t g = 0; g < m.edges.size(); ++g)
    {
        const std::uint32_t users = m.edgeStart[g + 1] - m.edgeStart[g];
        if (users == 1 && open++ == 0)
            firstOpen = g;
        else if (users > 2 && nonManifold++ == 0)
            example = g;
    }
    if (open > 0)
    {
        // Where they are: one of them and the box around them all.
        Vec3 lo = m.vertices[m.edges[firstOpen][0]], hi = lo;
        for (std::size_t g = 0; g < m.edges.size(); ++g)
            if (m.edgeStart[g + 1] - m.edgeStart[g] == 1)
                for (const std::uint32_t v : m.edges[g])
                {
                    const Vec3& x = m.vertices[v];
                    lo = {std::fmin(lo.x, x.x), std::fmin(lo.y, x.y), std::fmin(lo.z, x.z)};
                    hi = {std::fmax(hi.x, x.x), std::fmax(hi.y, x.y), std::fmax(hi.z, x.z)};
                }
        report.warnings.push_back(source + ": open boundary of " + std::to_string(open) + " edges, e.g. " +
                                  describeEdge(m, firstOpen) + "; the open edges lie within " + point(lo) +
                                  " to " + point(hi) + " m (corners within " + number(tolerance) +
                                  " m of each other are welded)");
    }
    if (nonManifold > 0)
    {
        report.warnings.push_back(source + ": " + std::to_string(nonManifold) +
                                  " non-manifold edges (used by 3 or more triangles), e.g. " +
                                  describeEdge(m, example));
    }
    buildGrid(m);
    return m;
}

Real TriangleMesh::farthestVertex(const Vec3& point) const
{
    Real far = 0;
    for (const Vec3& v : vertices)
        far = std::fmax(far, length(v - point));
    return far;
}

void TriangleMesh::trianglesNear(const Vec3& low, const Vec3& high, std::vector<std::uint32_t>& out) const
{
    out.clear();
    if (high.x < lower.x || high.y < lower.y || high.z < lower.z || low.x > upper.x || low.y > upper.y ||
        low.z > upper.z || !isFinite(low) || !isFinite(high))
        return;
    const auto index = [&](Real value, Real origin, int n)
    { return std::clamp(static_cast<int>((value - origin) / cell), 0, n - 1); };
    const int i0 = index(low.x, gridOrigin.x, cells[0]), i1 = index(high.x, gridOrigin.x, cells[0]);
    const int j0 = index(low.y, gridOrigin.y, cells[1]), j1 = index(high.y, gridOrigin.y, cells[1]);
    const int k0 = index(low.z, gridOrigin.z, cells[2]), k1 = index(high.z, gridOrigin.z, cells[2]);
    for (int k = k0; k <= k1; ++k)
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i)
            {
                const std::size_t c = (std::size_t(k) * cells[1] + j) * cells[0] + i;
                out.insert(out.end(), cellTriangles.begin() + cellStart[c],
                           cellTriangles.begin() + cellStart[c + 1]);
            }
    if (i0 != i1 || j0 != j1 || k0 != k1)
    {
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }
}

std::size_t TriangleMesh::memoryBytes() const
{
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(vertices) + bytes(triangles) + bytes(normals) + bytes(triangleEdges) + bytes(inward) +
           bytes(bounds) + bytes(edges) + bytes(edgeStart) + bytes(edgeUsers) + bytes(vertexStart) +
           bytes(vertexNeighbours) + bytes(cellStart) + bytes(cellTriangles);
}

TrianglePoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const Real d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return {a, MeshFeature::Vertex, 0};
    const Vec3 bp = p - b;
    const Real d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return {b, MeshFeature::Vertex, 1};
    const Real vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return {a + (d1 / (d1 - d3)) * ab, MeshFeature::Edge, 0};
    const Vec3 cp = p - c;
    const Real d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return {c, MeshFeature::Vertex, 2};
    const Real vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return {a + (d2 / (d2 - d6)) * ac, MeshFeature::Edge, 2};
    const Real va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return {b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), MeshFeature::Edge, 1};
    const Real denominator = 1 / (va + vb + vc);
    return {a + (vb * denominator) * ab + (vc * denominator) * ac, MeshFeature::Face, 0};
}

} // namespace veridem::dem
