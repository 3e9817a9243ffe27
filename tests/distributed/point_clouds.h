// Reproducible point clouds for the decomposition tests: the same points and weights on every
// machine (std::mt19937_64 is fully specified; the doubles are made from its integers by hand,
// not by a library distribution).
#pragma once

#include "core/vec3.h"

#include <cstdint>
#include <random>
#include <vector>

namespace veridem::distributed::clouds
{

struct Cloud
{
    std::vector<Vec3> position;        // [m]
    std::vector<std::uint32_t> weight; // 1..8
};

/// A uniform number in [0, 1) from the generator's 53 high bits.
inline double unit(std::mt19937_64& g)
{
    return static_cast<double>(g() >> 11) * 0x1.0p-53;
}

/// n points: a dense pile (60 %) in one corner of a 0.2 x 0.1 x 0.05 m box and a thin gas over
/// the rest, with weights 1-8 (a particle's cost: 1 plus its contacts).
inline Cloud makeCloud(std::size_t n, std::uint64_t seed)
{
    std::mt19937_64 g(seed);
    Cloud c;
    for (std::size_t i = 0; i < n; ++i)
    {
        const bool pile = unit(g) < 0.6;
        const double s = pile ? 0.3 : 1.0;
        c.position.push_back({0.2 * s * unit(g), 0.1 * s * unit(g), 0.05 * unit(g)});
        c.weight.push_back(static_cast<std::uint32_t>(1 + (g() >> 61)));
    }
    return c;
}

} // namespace veridem::distributed::clouds
