#include "fdem/delaunay.h"

#include "core/error.h"

#include <algorithm>
#include <string>

namespace veridem::fdem
{

namespace
{

Real orient(const Vec2& a, const Vec2& b, const Vec2& c)
{
    return cross(b - a, c - a);
}

} // namespace

DelaunayTriangulation::DelaunayTriangulation(Vec2 lo, Vec2 hi)
{
    const Vec2 centre = 0.5 * (lo + hi);
    const Real size = std::max({hi.x - lo.x, hi.y - lo.y, Real(1e-300)});
    const Real r = 50 * size; // the helper triangle's inscribed circle holds the box with a wide margin
    points_ = {centre + Vec2{-1.7320508075688772 * r, -r}, centre + Vec2{1.7320508075688772 * r, -r},
               centre + Vec2{0, 2 * r}};
    corners_.push_back({0, 1, 2});
    neighbour_.push_back({kNone, kNone, kNone});
    alive_.push_back(1);
    pointTriangle_ = {0, 0, 0};
}

bool DelaunayTriangulation::inCircumcircle(std::uint32_t t, Vec2 p) const
{
    const Vec2 a = points_[corners_[t][0]] - p, b = points_[corners_[t][1]] - p,
               c = points_[corners_[t][2]] - p;
    const Real det =
        lengthSquared(a) * cross(b, c) + lengthSquared(b) * cross(c, a) + lengthSquared(c) * cross(a, b);
    return det > 0;
}

std::uint32_t DelaunayTriangulation::locate(Vec2 p) const
{
    std::uint32_t t = last_;
    // Visibility walk: cross an edge that has p on its outer side; it terminates on a Delaunay
    // triangulation (Edelsbrunner 1990). The cap only guards against round-off cycles.
    for (std::size_t stepCount = 0; stepCount < 4 * corners_.size() + 16; ++stepCount)
    {
        bool moved = false;
        for (int k = 0; k < 3 && !moved; ++k)
        {
            const Vec2 &a = points_[corners_[t][(k + 1) % 3]], &b = points_[corners_[t][(k + 2) % 3]];
            if (orient(a, b, p) < 0 && neighbour_[t][k] != kNone)
            {
                t = neighbour_[t][k];
                moved = true;
            }
        }
        if (!moved)
            return t;
    }
    for (std::uint32_t s = 0; s < corners_.size(); ++s) // fallback: scan every live triangle
        if (alive_[s])
        {
            const auto& c = corners_[s];
            if (orient(points_[c[0]], points_[c[1]], p) >= 0 &&
                orient(points_[c[1]], points_[c[2]], p) >= 0 && orient(points_[c[2]], points_[c[0]], p) >= 0)
                return s;
        }
    throw InputError("Delaunay triangulation: a point lies outside the enclosing triangle");
}

std::uint32_t DelaunayTriangulation::insert(Vec2 p)
{
    const auto id = static_cast<std::uint32_t>(points_.size());
    points_.push_back(p);
    pointTriangle_.push_back(kNone);
    // The cavity: the containing triangle and the connected triangles whose circumcircle holds p.
    std::vector<std::uint32_t> cavity{locate(p)};
    std::vector<std::uint8_t>& inCavity = mark_; // all zero between insertions
    inCavity.resize(corners_.size() + 1, 0);
    inCavity[cavity[0]] = 1;
    for (std::size_t i = 0; i < cavity.size(); ++i)
        for (auto n : neighbour_[cavity[i]])
            if (n != kNone && !inCavity[n] && inCircumcircle(n, p))
            {
                inCavity[n] = 1;
                cavity.push_back(n);
            }
    struct Edge
    {
        std::uint32_t a, b, outside;
    };
    std::vector<Edge> boundary;
    for (auto t : cavity)
        for (int k = 0; k < 3; ++k)
        {
            const auto n = neighbour_[t][k];
            if (n == kNone || !inCavity[n])
            {
                const Edge e{corners_[t][(k + 1) % 3], corners_[t][(k + 2) % 3], n};
                if (!(orient(points_[e.a], points_[e.b], p) > 0))
                    throw InputError("Delaunay triangulation: a point (" + std::to_string(p.x) + ", " +
                                     std::to_string(p.y) + ") m is too close to an edge (degenerate input)");
                boundary.push_back(e);
            }
        }
    for (auto t : cavity)
    {
        alive_[t] = 0;
        inCavity[t] = 0;
    }
    // The new triangles (a, b, p), one per boundary edge, linked to the outside and to each other.
    const auto first = static_cast<std::uint32_t>(corners_.size());
    for (std::size_t i = 0; i < boundary.size(); ++i)
    {
        const Edge& e = boundary[i];
        const auto t = first + static_cast<std::uint32_t>(i);
        corners_.push_back({e.a, e.b, id});
        neighbour_.push_back({kNone, kNone, e.outside});
        alive_.push_back(1);
        if (e.outside != kNone) // the outside triangle's slot across (b, a) now points here
            for (int k = 0; k < 3; ++k)
                if (corners_[e.outside][(k + 1) % 3] == e.b && corners_[e.outside][(k + 2) % 3] == e.a)
                    neighbour_[e.outside][k] = t;
        pointTriangle_[e.a] = pointTriangle_[e.b] = pointTriangle_[id] = t;
    }
    for (std::size_t i = 0; i < boundary.size(); ++i)
        for (std::size_t j = 0; j < boundary.size(); ++j)
        {
            if (boundary[j].a == boundary[i].b) // edge (b_i, p) is opposite a_i: corner 0
                neighbour_[first + i][0] = first + static_cast<std::uint32_t>(j);
            if (boundary[j].b == boundary[i].a) // edge (p, a_i) is opposite b_i: corner 1
                neighbour_[first + i][1] = first + static_cast<std::uint32_t>(j);
        }
    last_ = first;
    return id;
}

bool DelaunayTriangulation::hasEdge(std::uint32_t a, std::uint32_t b) const
{
    // Turn around point a through the edges that use it until b is seen or the turn is complete.
    const std::uint32_t start = pointTriangle_[a];
    std::uint32_t t = start;
    for (std::size_t guard = 0; guard < 4096; ++guard)
    {
        const auto& c = corners_[t];
        int k = 0;
        while (c[k] != a)
            ++k;
        if (c[(k + 1) % 3] == b || c[(k + 2) % 3] == b)
            return true;
        t = neighbour_[t][(k + 1) % 3]; // across the edge (a, c[k+2])
        if (t == kNone || t == start)
            return false;
    }
    return false;
}

std::vector<std::array<std::uint32_t, 3>> DelaunayTriangulation::triangles() const
{
    std::vector<std::array<std::uint32_t, 3>> out;
    for (std::size_t t = 0; t < corners_.size(); ++t)
        if (alive_[t] && corners_[t][0] > 2 && corners_[t][1] > 2 && corners_[t][2] > 2)
            out.push_back(corners_[t]);
    return out;
}

} // namespace veridem::fdem
