// Meshed stand-ins for the analytic plane and turntable of the DEM cases: the same surfaces as
// irregular triangle meshes (mesh walls, dem/walls/mesh_wall.h), so a case run on both must give
// the same motion. Generated in code from a fixed pseudo-random sequence (reproducible).
#pragma once

#include "core/error.h"
#include "dem/walls/wall.h"
#include "support.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace veridem::verify
{

/// A reproducible sequence of numbers in [-1, 1) (a 64-bit linear congruential generator).
class Jitter
{
  public:
    Real next()
    {
        state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
        return Real(state_ >> 11) / Real(1ull << 52) - 1;
    }

  private:
    std::uint64_t state_ = 0x9e3779b97f4a7c15ull;
};

inline dem::Wall meshWall(const std::string& name, const std::vector<Vec3>& corners, const Vec3& pivot = {})
{
    dem::MeshReport report; // (open boundary: expected for a floor, a disk or a cap)
    dem::MeshShape shape;
    shape.mesh = std::make_shared<const dem::TriangleMesh>(dem::buildTriangleMesh(corners, name, report));
    shape.pivot = pivot;
    shape.farthestVertex = shape.mesh->farthestVertex(shape.pivot);
    dem::Wall wall;
    wall.name = name;
    wall.shape = std::move(shape);
    return wall;
}

/// The rectangle [x0, x1] x [-h, h] of the plane z = 0 in nx x ny irregular cells (ny even): the
/// nodes of the row y = 0 stay on it (a ball rolling along y = 0 runs along edges and over
/// vertices), other interior nodes are moved by up to 30 % of a cell; each cell is split along a
/// random diagonal, and every third cell touching y = 0 is a fan about a point 1e-4 cells from
/// its y = 0 edge, whose triangle on that edge is a sliver of aspect ratio 1e-4.
inline dem::Wall meshedFloor(Real x0, Real x1, Real h, int nx, int ny)
{
    Jitter random;
    const Real hx = (x1 - x0) / nx, hy = 2 * h / ny;
    std::vector<Vec3> node;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
        {
            const bool interiorX = i > 0 && i<nx, interiorY = j> 0 && j < ny && 2 * j != ny;
            const Real dx = random.next(), dy = random.next();
            node.push_back(
                {x0 + hx * (i + (interiorX ? 0.3 * dx : 0)), -h + hy * (j + (interiorY ? 0.3 * dy : 0)), 0});
        }
    const auto at = [&](int i, int j) { return node[std::size_t(j) * (nx + 1) + i]; };
    std::vector<Vec3> corners;
    const auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        corners.insert(corners.end(), {a, b, c});
    };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            const bool onPath = 2 * j == ny || 2 * (j + 1) == ny;
            if (onPath && i % 3 == 0)
            {
                const Vec3 p = 2 * j == ny ? 0.5 * (a + b) + Vec3{0, 1e-4 * hy, 0}
                                           : 0.5 * (c + d) - Vec3{0, 1e-4 * hy, 0};
                add(a, b, p);
                add(b, c, p);
                add(c, d, p);
                add(d, a, p);
            }
            else if (random.next() < 0)
            {
                add(a, b, c);
                add(a, c, d);
            }
            else
            {
                add(a, b, d);
                add(b, c, d);
            }
        }
    return meshWall("meshed floor", corners);
}

/// A disk of radius R [m] centred at the origin in the plane spanned by e1, e2: `rings` rings of
/// `perRing` nodes (each ring turned by a random fraction of the angular step) about a centre fan,
/// quads between rings split along a random diagonal.
inline dem::Wall meshedDisk(Real radius, const Vec3& e1, const Vec3& e2, int rings, int perRing)
{
    Jitter random;
    std::vector<std::vector<Vec3>> ring(std::size_t(rings) + 1);
    for (int m = 1; m <= rings; ++m)
    {
        const Real turn = 0.25 * random.next();
        for (int q = 0; q < perRing; ++q)
        {
            const Real angle = 2 * kPi * (q + turn) / perRing, r = radius * m / rings;
            ring[std::size_t(m)].push_back(r * std::cos(angle) * e1 + r * std::sin(angle) * e2);
        }
    }
    std::vector<Vec3> corners;
    const auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        corners.insert(corners.end(), {a, b, c});
    };
    for (int q = 0; q < perRing; ++q)
        add(Vec3{}, ring[1][std::size_t(q)], ring[1][std::size_t((q + 1) % perRing)]);
    for (int m = 1; m < rings; ++m)
        for (int q = 0; q < perRing; ++q)
        {
            const std::size_t q1 = std::size_t((q + 1) % perRing);
            const Vec3 a = ring[std::size_t(m)][std::size_t(q)], b = ring[std::size_t(m + 1)][std::size_t(q)],
                       c = ring[std::size_t(m + 1)][q1], d = ring[std::size_t(m)][q1];
            if (random.next() < 0)
            {
                add(a, b, c);
                add(a, c, d);
            }
            else
            {
                add(a, b, d);
                add(b, c, d);
            }
        }
    return meshWall("meshed disk", corners);
}

/// Triangles joining two rings of points (each a closed loop of increasing angle, the first points
/// at angles `startA` <= `startB` < startA + 2 pi / a.size() [rad]): a zipper that always advances
/// the ring whose next point comes first in angle, so rings of different counts are joined by
/// near-equilateral triangles when the counts follow the rings' lengths.
inline void zipRings(const std::vector<Vec3>& a, Real startA, const std::vector<Vec3>& b, Real startB,
                     std::vector<Vec3>& corners)
{
    const std::size_t na = a.size(), nb = b.size();
    std::size_t i = 0, j = 0;
    const auto angleA = [&](std::size_t k) { return startA + 2 * kPi * Real(k) / Real(na); };
    const auto angleB = [&](std::size_t k) { return startB + 2 * kPi * Real(k) / Real(nb); };
    while (i < na || j < nb)
        if (j == nb || (i < na && angleA(i + 1) < angleB(j + 1)))
        {
            corners.insert(corners.end(), {a[i % na], a[(i + 1) % na], b[j % nb]});
            ++i;
        }
        else
        {
            corners.insert(corners.end(), {a[i % na], b[(j + 1) % nb], b[j % nb]});
            ++j;
        }
}

/// The inside of the sphere of radius R [m] centred at `centre`, from its lowest point up to the
/// polar angle `maxPolar` [rad] from the bottom, in rings of near-equilateral triangles of edge
/// about `edge` [m]: ring k at polar angle k edge / R holds round(2 pi R sin / edge) nodes (at
/// least 6), each ring turned by a random fraction of its step, rings joined by zipRings. The
/// wall's pivot is the sphere's centre. A facet's normal departs from the sphere's normal at its
/// points by at most about its circumradius / R (largestFacetTilt measures it).
inline dem::Wall meshedSphericalCap(const Vec3& centre, Real radius, Real maxPolar, Real edge)
{
    Jitter random;
    const int rings = int(std::ceil(maxPolar * radius / edge));
    const Real step = maxPolar / rings;
    const auto point = [&](Real polar, Real azimuth)
    {
        return centre + radius * Vec3{std::sin(polar) * std::cos(azimuth),
                                      std::sin(polar) * std::sin(azimuth), -std::cos(polar)};
    };
    std::vector<Vec3> corners, previous{point(0, 0)};
    Real previousStart = 0;
    for (int k = 1; k <= rings; ++k)
    {
        const Real polar = k * step;
        const int count = std::max(6, int(std::lround(2 * kPi * radius * std::sin(polar) / edge)));
        const Real angularStep = 2 * kPi / count;
        // The first node lies in [previousStart, previousStart + angularStep), as zipRings needs.
        const Real start = previousStart + angularStep * 0.5 * (1 + random.next());
        std::vector<Vec3> ring;
        for (int q = 0; q < count; ++q)
            ring.push_back(point(polar, start + q * angularStep));
        if (previous.size() == 1)
            for (int q = 0; q < count; ++q)
                corners.insert(corners.end(),
                               {previous[0], ring[std::size_t(q)], ring[std::size_t((q + 1) % count)]});
        else
            zipRings(previous, previousStart, ring, start, corners);
        previous = std::move(ring);
        previousStart = start;
    }
    return meshWall("meshed spherical cap", corners, centre);
}

/// The largest angle [rad] between a triangle's normal and the sphere's normal (from `centre`) at
/// the triangle's corners: the facet error of a meshed sphere (the sphere normal turns most across
/// a facet between its corners).
inline Real largestFacetTilt(const dem::Wall& wall, const Vec3& centre)
{
    const auto& mesh = *std::get<dem::MeshShape>(wall.shape).mesh;
    Real largest = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (const std::uint32_t v : mesh.triangles[t])
        {
            const Vec3 radial = mesh.vertices[v] - centre;
            const Real c = std::fabs(dot(mesh.normals[t], radial)) / length(radial);
            largest = std::fmax(largest, std::acos(std::fmin(Real(1), c)));
        }
    return largest;
}

} // namespace veridem::verify
