// Polygons meshed with interior nodes to a target edge length h (mesher.h: meshPolygonRefined), and
// the outline of a disc.
//
// 1. The outline's edges are split into round(L / h) equal pieces (at least one).
// 2. Inside, a triangular lattice of spacing h (rows h sqrt(3)/2 apart, every other row shifted by
//    h / 2: equilateral triangles), keeping the points inside the polygon and at least h / 2 from the
//    outline (a closer point would make a sliver against the outline's pieces).
// 3. The Delaunay triangulation of all points (delaunay.h; Bowyer 1981, Watson 1981). A piece of the
//    outline missing from it is split at its midpoint and the midpoint inserted, until every piece
//    is an edge (the segment recovery of Ruppert's refinement, J. Algorithms 18:548, 1995); then
//    the triangles whose centroid lies outside the polygon are dropped: every triangle is wholly
//    inside or outside because the outline is made of edges.
// 4. "Smart" Laplacian smoothing of the interior nodes (Freitag & Plassmann, IJNME 49:109, 2000, the
//    simple variant: a node moves to the mean of its neighbours only if the smallest angle of its
//    triangles does not decrease), a few sweeps in node order (deterministic).
// The result is checked: every triangle counter-clockwise, the areas summing to the polygon's.
#include "core/constants.h"
#include "core/error.h"
#include "fdem/delaunay.h"
#include "fdem/elements/cst.h"
#include "fdem/mesher.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace veridem::fdem
{

namespace
{

/// Even-odd rule: p strictly inside the closed polygon (points on the outline may go either way).
bool inside(const std::vector<Vec2>& ring, Vec2 p)
{
    bool in = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    {
        const Vec2 &a = ring[i], &b = ring[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
            in = !in;
    }
    return in;
}

Real distanceToSegment(Vec2 p, Vec2 a, Vec2 b)
{
    const Vec2 ab = b - a;
    const Real t = std::clamp(dot(p - a, ab) / lengthSquared(ab), Real(0), Real(1));
    return length(p - (a + t * ab));
}

/// Smallest interior angle of a triangle [rad]; 0 if it is not counter-clockwise.
Real smallestAngle(Vec2 a, Vec2 b, Vec2 c)
{
    if (!(signedArea(a, b, c) > 0))
        return 0;
    const auto angle = [](Vec2 p, Vec2 q, Vec2 r)
    { return std::atan2(std::abs(cross(q - p, r - p)), dot(q - p, r - p)); };
    return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

} // namespace

std::vector<Vec2> discOutline(Vec2 centre, Real radius, Real edgeLength)
{
    if (!(radius > 0) || !std::isfinite(radius) || !isFinite(centre))
        throw InputError("disc mesher: the radius must be positive and finite (got " +
                         std::to_string(radius) + " m)");
    if (!(edgeLength > 0) || !std::isfinite(edgeLength))
        throw InputError("disc mesher: the edge length must be positive and finite (got " +
                         std::to_string(edgeLength) + " m)");
    const Real sides = std::max(12.0, std::ceil(2 * kPi * radius / edgeLength));
    if (sides > 1e7)
        throw InputError("disc mesher: edge length " + std::to_string(edgeLength) +
                         " m is too small for radius " + std::to_string(radius) +
                         " m (more than 1e7 outline points)");
    const auto n = static_cast<std::size_t>(sides);
    std::vector<Vec2> out(n);
    for (std::size_t k = 0; k < n; ++k)
    {
        const Real angle = 2 * kPi * static_cast<Real>(k) / static_cast<Real>(n);
        out[k] = centre + radius * Vec2{std::cos(angle), std::sin(angle)};
    }
    return out;
}

TriangleMesh meshPolygonRefined(const std::vector<Vec2>& vertices, Real h)
{
    if (!(h > 0) || !std::isfinite(h))
        throw InputError("polygon mesher: the edge length must be positive and finite (got " +
                         std::to_string(h) + " m)");
    const std::vector<Vec2> ring = counterClockwiseOutline(vertices);
    const std::size_t n = ring.size();
    Vec2 lo = ring[0], hi = ring[0];
    Real area = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        lo = {std::min(lo.x, ring[i].x), std::min(lo.y, ring[i].y)};
        hi = {std::max(hi.x, ring[i].x), std::max(hi.y, ring[i].y)};
        area += 0.5 * cross(ring[i], ring[(i + 1) % n]);
    }
    const Real rowPitch = h * std::sqrt(3.0) / 2;
    if ((hi.x - lo.x) / h * (hi.y - lo.y) / rowPitch > 5e6)
        throw InputError("polygon mesher: edge length " + std::to_string(h) +
                         " m would make more than 1e7 triangles for this polygon");

    DelaunayTriangulation dt(lo, hi);
    // 1. The outline's pieces; segments hold triangulation point ids.
    std::vector<std::array<std::uint32_t, 2>> segments;
    std::vector<std::uint32_t> outlineIds;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec2 a = ring[i], b = ring[(i + 1) % n];
        const Real pieces = std::max(Real(1), std::round(length(b - a) / h));
        for (int k = 0; k < pieces; ++k)
            outlineIds.push_back(dt.insert(k == 0 ? a : a + (k / pieces) * (b - a)));
    }
    for (std::size_t i = 0; i < outlineIds.size(); ++i)
        segments.push_back({outlineIds[i], outlineIds[(i + 1) % outlineIds.size()]});
    // 2. The lattice, row by row in alternating directions (short walks in the point location).
    const int rows = static_cast<int>(std::floor((hi.y - lo.y) / rowPitch));
    const int columns = static_cast<int>(std::floor((hi.x - lo.x) / h)) + 1;
    const Real y0 = 0.5 * (lo.y + hi.y) - 0.5 * Real(rows) * rowPitch; // rows centred in the box
    for (int j = 0; j <= rows; ++j)
    {
        const Real x0 = 0.5 * (lo.x + hi.x) - 0.5 * Real(columns - 1) * h + (j % 2 ? 0.5 * h : 0.0);
        for (int c = 0; c <= columns; ++c)
        {
            const int i = j % 2 ? columns - c : c;
            const Vec2 p{x0 + Real(i) * h, y0 + Real(j) * rowPitch};
            if (!inside(ring, p))
                continue;
            Real clearance = h;
            for (std::size_t e = 0; e < n && clearance >= 0.5 * h; ++e)
                clearance = std::min(clearance, distanceToSegment(p, ring[e], ring[(e + 1) % n]));
            if (clearance >= 0.5 * h)
                dt.insert(p);
        }
    }
    // 3. Segment recovery.
    for (int round = 0;; ++round)
    {
        std::vector<std::array<std::uint32_t, 2>> next;
        bool split = false;
        for (const auto& s : segments)
        {
            if (dt.hasEdge(s[0], s[1]))
            {
                next.push_back(s);
                continue;
            }
            const auto m = dt.insert(0.5 * (dt.points()[s[0]] + dt.points()[s[1]]));
            next.push_back({s[0], m});
            next.push_back({m, s[1]});
            split = true;
        }
        segments.swap(next);
        if (!split)
            break;
        if (round == 40)
            throw InputError("polygon mesher: the outline could not be recovered in the triangulation "
                             "(an angle of the polygon too sharp for edge length " +
                             std::to_string(h) + " m?)");
    }
    // Triangles inside, with the points renumbered (the 3 helper points and any unused point dropped).
    TriangleMesh mesh;
    const auto& points = dt.points();
    std::vector<std::uint32_t> renumber(points.size(), ~0u);
    for (auto t : dt.triangles())
    {
        if (!inside(ring, (points[t[0]] + points[t[1]] + points[t[2]]) / 3))
            continue;
        for (auto& id : t)
        {
            if (renumber[id] == ~0u)
            {
                renumber[id] = static_cast<std::uint32_t>(mesh.points.size());
                mesh.points.push_back(points[id]);
            }
            id = renumber[id];
        }
        mesh.triangles.push_back(t);
    }
    // 4. Smoothing of the nodes that are not on the outline.
    std::vector<std::uint8_t> onOutline(mesh.points.size(), 0);
    for (const auto& s : segments)
        for (auto id : s)
            onOutline[renumber[id]] = 1;
    std::vector<std::vector<std::uint32_t>> around(mesh.points.size()); // triangles of each node
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (auto id : mesh.triangles[t])
            around[id].push_back(t);
    const auto worstAngle = [&](std::uint32_t node)
    {
        Real worst = kPi;
        for (auto t : around[node])
        {
            const auto& c = mesh.triangles[t];
            worst = std::min(worst, smallestAngle(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]]));
        }
        return worst;
    };
    for (int sweep = 0; sweep < 5; ++sweep)
        for (std::uint32_t node = 0; node < mesh.points.size(); ++node)
        {
            if (onOutline[node])
                continue;
            Vec2 sum{};
            Real count = 0;
            for (auto t : around[node])
                for (auto id : mesh.triangles[t])
                    if (id != node)
                    {
                        sum += mesh.points[id];
                        count += 1; // each neighbour counted twice (two triangles): same mean
                    }
            const Vec2 old = mesh.points[node];
            const Real before = worstAngle(node);
            mesh.points[node] = sum / count;
            if (!(worstAngle(node) >= before))
                mesh.points[node] = old;
        }
    // Check: counter-clockwise triangles whose areas sum to the polygon's.
    Real total = 0;
    for (const auto& c : mesh.triangles)
    {
        const Real a = signedArea(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]]);
        if (!(a > 0))
            throw InputError("polygon mesher: an inverted triangle was made (degenerate outline?)");
        total += a;
    }
    if (!(std::abs(total - area) <= 1e-9 * area))
    {
        std::ostringstream s;
        s << "polygon mesher: the triangles cover " << total << " m^2 of the polygon's " << area << " m^2";
        throw InputError(s.str());
    }
    return mesh;
}

} // namespace veridem::fdem
