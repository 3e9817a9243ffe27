#include "fdem/mesher.h"

#include "core/error.h"
#include "fdem/elements/cst.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace veridem::fdem
{

TriangleMesh meshRectangle(Vec2 origin, Vec2 size, int nx, int ny, DiagonalPattern pattern)
{
    if (!(size.x > 0) || !(size.y > 0) || !isFinite(size) || !isFinite(origin))
        throw InputError("rectangle mesher: the size must be positive and finite (got " +
                         std::to_string(size.x) + " x " + std::to_string(size.y) + " m)");
    if (nx < 1 || ny < 1)
        throw InputError("rectangle mesher: the cell counts must be >= 1 (got " + std::to_string(nx) + " x " +
                         std::to_string(ny) + ")");
    TriangleMesh m;
    const auto column = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            m.points.push_back({origin.x + size.x * i / nx, origin.y + size.y * j / ny});
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const std::uint32_t a = column(i, j), b = column(i + 1, j), c = column(i + 1, j + 1),
                                d = column(i, j + 1);
            if (pattern == DiagonalPattern::Right || (i + j) % 2 == 0)
            {
                m.triangles.push_back({a, b, c});
                m.triangles.push_back({a, c, d});
            }
            else
            {
                m.triangles.push_back({a, b, d});
                m.triangles.push_back({b, c, d});
            }
        }
    return m;
}

namespace
{

bool segmentsCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d)
{
    const Real d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const Real d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

bool insideOrOn(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c)
{
    return cross(b - a, p - a) >= 0 && cross(c - b, p - b) >= 0 && cross(a - c, p - c) >= 0;
}

} // namespace

std::vector<Vec2> counterClockwiseOutline(const std::vector<Vec2>& vertices)
{
    const std::size_t n = vertices.size();
    if (n < 3)
        throw InputError("polygon mesher: a polygon needs at least 3 vertices (got " + std::to_string(n) +
                         ")");
    Real area2 = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!isFinite(vertices[i]))
            throw InputError("polygon mesher: vertex " + std::to_string(i) + " is not finite");
        area2 += cross(vertices[i], vertices[(i + 1) % n]);
    }
    if (!(std::abs(area2) > 0))
        throw InputError("polygon mesher: the polygon has zero area");
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j)
        {
            if (i == 0 && j == n - 1)
                continue;
            if (segmentsCross(vertices[i], vertices[(i + 1) % n], vertices[j], vertices[(j + 1) % n]))
                throw InputError("polygon mesher: edges " + std::to_string(i) + " and " + std::to_string(j) +
                                 " cross (the polygon must be simple)");
        }
    std::vector<Vec2> ring(vertices);
    if (area2 < 0)
        std::reverse(ring.begin(), ring.end());
    return ring;
}

TriangleMesh meshPolygon(const std::vector<Vec2>& vertices)
{
    counterClockwiseOutline(vertices); // the checks
    const std::size_t n = vertices.size();
    Real area2 = 0;
    for (std::size_t i = 0; i < n; ++i)
        area2 += cross(vertices[i], vertices[(i + 1) % n]);
    TriangleMesh m;
    m.points = vertices;
    std::vector<std::uint32_t> ring(n);
    for (std::size_t i = 0; i < n; ++i)
        ring[i] = static_cast<std::uint32_t>(area2 > 0 ? i : n - 1 - i); // counter-clockwise order
    while (ring.size() > 3)
    {
        bool clipped = false;
        for (std::size_t i = 0; i < ring.size() && !clipped; ++i)
        {
            const std::size_t ip = (i + ring.size() - 1) % ring.size(), in = (i + 1) % ring.size();
            const Vec2 &a = m.points[ring[ip]], &b = m.points[ring[i]], &c = m.points[ring[in]];
            if (!(signedArea(a, b, c) > 0))
                continue; // reflex or collinear vertex: not an ear
            bool empty = true;
            for (std::size_t k = 0; k < ring.size() && empty; ++k)
                if (k != ip && k != i && k != in && insideOrOn(m.points[ring[k]], a, b, c))
                    empty = false;
            if (!empty)
                continue;
            m.triangles.push_back({ring[ip], ring[i], ring[in]});
            ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
            clipped = true;
        }
        if (!clipped)
            throw InputError(
                "polygon mesher: no ear found (is the outline simple and without repeated vertices?)");
    }
    m.triangles.push_back({ring[0], ring[1], ring[2]});
    return m;
}

} // namespace veridem::fdem
