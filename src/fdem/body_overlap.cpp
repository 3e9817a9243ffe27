#include "fdem/body_overlap.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace veridem::fdem
{

namespace
{

struct Box
{
    Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
    void add(Vec2 p)
    {
        lo = {std::fmin(lo.x, p.x), std::fmin(lo.y, p.y)};
        hi = {std::fmax(hi.x, p.x), std::fmax(hi.y, p.y)};
    }
    bool contains(Vec2 p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
    bool overlaps(const Box& o) const
    {
        return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y;
    }
};

struct Body
{
    const TriangleMesh* mesh;
    Box box;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary; // edges of one triangle only
};

Body describe(const TriangleMesh& mesh)
{
    Body b{&mesh, {}, {}};
    for (const Vec2& p : mesh.points)
        b.box.add(p);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
        {
            const std::uint32_t a = t[k], c = t[(k + 1) % 3];
            ++edges[{std::min(a, c), std::max(a, c)}];
        }
    for (const auto& [edge, count] : edges)
        if (count == 1)
            b.boundary.push_back(edge);
    return b;
}

/// Twice the signed area of (a, b, c), with values within `eps` taken as zero.
int orientation(Vec2 a, Vec2 b, Vec2 c, Real eps)
{
    const Real o = cross(b - a, c - a);
    return o > eps ? 1 : o < -eps ? -1 : 0;
}

/// True with a point of the overlap if a triangle of `inner` has its centroid strictly inside
/// a triangle of `outer` (catches a body inside another and coincident bodies).
bool centroidInside(const Body& inner, const Body& outer, Real eps, Vec2& where)
{
    const TriangleMesh &in = *inner.mesh, &out = *outer.mesh;
    for (const auto& t : in.triangles)
    {
        const Vec2 c = (in.points[t[0]] + in.points[t[1]] + in.points[t[2]]) / 3.0;
        if (!outer.box.contains(c))
            continue;
        for (const auto& u : out.triangles)
        {
            const Vec2 &a = out.points[u[0]], &b = out.points[u[1]], &d = out.points[u[2]];
            const int o1 = orientation(a, b, c, eps), o2 = orientation(b, d, c, eps),
                      o3 = orientation(d, a, c, eps);
            if ((o1 > 0 && o2 > 0 && o3 > 0) || (o1 < 0 && o2 < 0 && o3 < 0))
            {
                where = c;
                return true;
            }
        }
    }
    return false;
}

/// True with the crossing point if boundary edges of the two bodies cross properly (not touching).
bool boundariesCross(const Body& first, const Body& second, Real eps, Vec2& where)
{
    const auto &p = first.mesh->points, &q = second.mesh->points;
    for (const auto& [i, j] : first.boundary)
    {
        if (!second.box.contains(p[i]) && !second.box.contains(p[j]))
        {
            Box edge;
            edge.add(p[i]);
            edge.add(p[j]);
            if (!edge.overlaps(second.box))
                continue;
        }
        for (const auto& [k, l] : second.boundary)
        {
            const int o1 = orientation(p[i], p[j], q[k], eps), o2 = orientation(p[i], p[j], q[l], eps);
            const int o3 = orientation(q[k], q[l], p[i], eps), o4 = orientation(q[k], q[l], p[j], eps);
            if (o1 * o2 < 0 && o3 * o4 < 0)
            {
                const Real s = cross(q[k] - p[i], q[l] - q[k]) / cross(p[j] - p[i], q[l] - q[k]);
                where = p[i] + s * (p[j] - p[i]);
                return true;
            }
        }
    }
    return false;
}

} // namespace

void checkBodiesApart(const std::vector<const TriangleMesh*>& meshes, const std::vector<std::string>& names,
                      const std::string& file)
{
    std::vector<Body> bodies;
    for (const TriangleMesh* m : meshes)
        bodies.push_back(describe(*m));
    for (std::size_t a = 0; a < bodies.size(); ++a)
        for (std::size_t b = a + 1; b < bodies.size(); ++b)
        {
            if (!bodies[a].box.overlaps(bodies[b].box))
                continue;
            const Vec2 size = Vec2{std::fmax(bodies[a].box.hi.x, bodies[b].box.hi.x),
                                   std::fmax(bodies[a].box.hi.y, bodies[b].box.hi.y)} -
                              Vec2{std::fmin(bodies[a].box.lo.x, bodies[b].box.lo.x),
                                   std::fmin(bodies[a].box.lo.y, bodies[b].box.lo.y)};
            const Real scale = std::fmax(size.x, size.y);
            const Real eps = 1e-9 * scale * scale; // rounding of coordinates given to ~1e-9 of the size
            Vec2 where{};
            if (boundariesCross(bodies[a], bodies[b], eps, where) ||
                centroidInside(bodies[a], bodies[b], eps, where) ||
                centroidInside(bodies[b], bodies[a], eps, where))
            {
                std::ostringstream s;
                s << file << ": bodies '" << names[a] << "' and '" << names[b]
                  << "' overlap at the start (near (" << where.x << ", " << where.y
                  << ") m); the contact would throw them apart: move them apart (touching is allowed)";
                throw InputError(s.str());
            }
        }
}

} // namespace veridem::fdem
