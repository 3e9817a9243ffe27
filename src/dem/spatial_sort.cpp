#include "dem/spatial_sort.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace veridem::dem
{

namespace
{

/// Spreads the low 21 bits of v so that there are two zero bits between consecutive bits.
std::uint64_t spreadBits(std::uint64_t v)
{
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

template <class T> void permute(std::vector<T>& values, const std::vector<std::uint32_t>& order)
{
    std::vector<T> sorted(values.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        sorted[k] = values[order[k]];
    values.swap(sorted);
}

} // namespace

std::vector<std::uint32_t> sortParticlesSpatially(World& world, Real cellSize)
{
    if (world.prepared)
        throw InputError(
            "sortParticlesSpatially: call it before the first step (contact history would be lost)");
    ParticleStore& p = world.particles;
    const std::size_t n = p.size();
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    if (n == 0)
        return order;
    Vec3 lo = p.position[0];
    Real maxRadius = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        lo = {std::fmin(lo.x, p.position[i].x), std::fmin(lo.y, p.position[i].y),
              std::fmin(lo.z, p.position[i].z)};
        maxRadius = std::fmax(maxRadius, p.radius[i]);
    }
    if (cellSize <= 0)
        cellSize = 2 * maxRadius + world.neighbors.skin;
    if (!(cellSize > 0))
        return order;
    std::vector<std::uint64_t> code(n);
    auto cellIndex = [&](Real value, Real origin)
    { return static_cast<std::uint64_t>(std::fmin((value - origin) / cellSize, 2097151.0)); };
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& x = p.position[i];
        code[i] = spreadBits(cellIndex(x.x, lo.x)) | spreadBits(cellIndex(x.y, lo.y)) << 1 |
                  spreadBits(cellIndex(x.z, lo.z)) << 2;
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return code[a] < code[b]; });
    permute(p.position, order);
    permute(p.velocity, order);
    permute(p.angularVelocity, order);
    permute(p.force, order);
    permute(p.torque, order);
    permute(p.radius, order);
    permute(p.mass, order);
    permute(p.invMass, order);
    permute(p.invInertia, order);
    permute(p.material, order);
    permute(p.id, order);
    permute(p.fixed, order);
    return order;
}

} // namespace veridem::dem
