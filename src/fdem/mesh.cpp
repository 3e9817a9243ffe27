#include "fdem/mesh.h"

#include "core/error.h"
#include "fdem/elements/cst.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace veridem::fdem
{

Real longestEdge(const Vec2& a, const Vec2& b, const Vec2& c)
{
    return std::sqrt(std::max({lengthSquared(b - a), lengthSquared(c - b), lengthSquared(a - c)}));
}

Real minimumAltitude(const Vec2& a, const Vec2& b, const Vec2& c)
{
    // altitude onto edge e = 2A / |e|; the smallest is onto the longest edge.
    return 2 * std::abs(signedArea(a, b, c)) / longestEdge(a, b, c);
}

TriangleMesh validatedMesh(TriangleMesh mesh, const std::string& source)
{
    if (mesh.triangles.empty())
        throw InputError(source + ": the mesh has no triangles");
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
        if (!isFinite(mesh.points[i]))
            throw InputError(source + ": node " + std::to_string(i) + " has a non-finite coordinate");
    std::size_t clockwise = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    {
        const auto& tri = mesh.triangles[t];
        for (auto n : tri)
            if (n >= mesh.points.size())
            {
                std::ostringstream s;
                s << source << ": triangle " << t << " refers to node " << n << " but the mesh has "
                  << mesh.points.size() << " nodes";
                throw InputError(s.str());
            }
        const Vec2 &a = mesh.points[tri[0]], &b = mesh.points[tri[1]], &c = mesh.points[tri[2]];
        const Real area = signedArea(a, b, c);
        const Real edge = longestEdge(a, b, c);
        if (!(std::abs(area) > 1e-10 * edge * edge))
        {
            std::ostringstream s;
            s << source << ": triangle " << t << " (nodes " << tri[0] << ", " << tri[1] << ", " << tri[2]
              << ") is degenerate (area " << area << " m^2)";
            throw InputError(s.str());
        }
        if (area < 0)
            ++clockwise;
    }
    if (clockwise == mesh.triangles.size())
    {
        for (auto& tri : mesh.triangles)
            std::swap(tri[1], tri[2]);
    }
    else if (clockwise > 0)
    {
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        {
            const auto& tri = mesh.triangles[t];
            if (signedArea(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]) < 0)
            {
                std::ostringstream s;
                s << source << ": triangle " << t << " (nodes " << tri[0] << ", " << tri[1] << ", " << tri[2]
                  << ") is inverted (clockwise while " << (mesh.triangles.size() - clockwise)
                  << " others are counter-clockwise)";
                throw InputError(s.str());
            }
        }
    }
    return mesh;
}

} // namespace veridem::fdem
