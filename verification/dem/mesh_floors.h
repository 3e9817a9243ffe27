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

inline dem::Wall meshWall(const std::string& name, const std::vector<Vec3>& corners)
{
    dem::MeshReport report; // (open boundary: expected for a floor or a disk)
    dem::MeshShape shape;
    shape.mesh = std::make_shared<const dem::TriangleMesh>(dem::buildTriangleMesh(corners, name, report));
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

} // namespace veridem::verify
