#include "dem/neighbor_list.h"

#include <algorithm>
#include <cmath>

namespace veridem::dem
{

bool NeighborList::needsRebuild(const ParticleStore& particles) const
{
    if (positionAtBuild_.size() != particles.size())
        return true;
    const Real limit2 = 0.25 * skin * skin;
    const std::size_t n = particles.size();
    for (std::size_t i = 0; i < n; ++i)
        if (lengthSquared(particles.position[i] - positionAtBuild_[i]) > limit2)
            return true;
    return false;
}

void NeighborList::rebuild(const ParticleStore& particles)
{
    ++rebuilds_;
    const std::size_t n = particles.size();
    positionAtBuild_ = particles.position;
    newFirst_.clear();
    newSecond_.clear();
    if (n == 0)
    {
        first.clear();
        second.clear();
        history.clear();
        return;
    }

    // Grid over the bounding box; cell edge covers the largest possible pair distance.
    Vec3 lo = particles.position[0], hi = lo;
    Real maxRadius = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& x = particles.position[i];
        lo = {std::fmin(lo.x, x.x), std::fmin(lo.y, x.y), std::fmin(lo.z, x.z)};
        hi = {std::fmax(hi.x, x.x), std::fmax(hi.y, x.y), std::fmax(hi.z, x.z)};
        maxRadius = std::fmax(maxRadius, particles.radius[i]);
    }
    Real cell = std::fmax(2 * maxRadius + skin, 1e-12);
    auto cellsAlong = [&](Real extent) { return static_cast<std::size_t>(extent / cell) + 1; };
    // Keep the grid O(N): a lone particle far away must not create billions of empty cells.
    const std::size_t maxCells = 4 * n + 64;
    while (cellsAlong(hi.x - lo.x) * cellsAlong(hi.y - lo.y) * cellsAlong(hi.z - lo.z) > maxCells)
        cell *= 1.5;
    const std::size_t nx = cellsAlong(hi.x - lo.x), ny = cellsAlong(hi.y - lo.y),
                      nz = cellsAlong(hi.z - lo.z);
    const std::size_t cellCount = nx * ny * nz;
    auto coordinate = [&](Real value, Real origin, std::size_t count)
    { return std::min(static_cast<std::size_t>((value - origin) / cell), count - 1); };

    // Counting sort of particles by cell.
    cellStart_.assign(cellCount + 1, 0);
    cellOf_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& x = particles.position[i];
        const std::size_t c =
            (coordinate(x.z, lo.z, nz) * ny + coordinate(x.y, lo.y, ny)) * nx + coordinate(x.x, lo.x, nx);
        cellOf_[i] = static_cast<std::uint32_t>(c);
        ++cellStart_[c + 1];
    }
    for (std::size_t c = 0; c < cellCount; ++c)
        cellStart_[c + 1] += cellStart_[c];
    cellParticles_.resize(n);
    {
        std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
            cellParticles_[fill[cellOf_[i]]++] = static_cast<std::uint32_t>(i);
    }

    // For each i, all j > i within r_i + r_j + skin, in ascending j.
    for (std::size_t i = 0; i < n; ++i)
    {
        const std::size_t c = cellOf_[i];
        const std::size_t cx = c % nx, cy = (c / nx) % ny, cz = c / (nx * ny);
        const Vec3 xi = particles.position[i];
        const Real ri = particles.radius[i];
        scratch_.clear();
        for (std::size_t z = (cz ? cz - 1 : 0); z <= std::min(cz + 1, nz - 1); ++z)
            for (std::size_t y = (cy ? cy - 1 : 0); y <= std::min(cy + 1, ny - 1); ++y)
                for (std::size_t x = (cx ? cx - 1 : 0); x <= std::min(cx + 1, nx - 1); ++x)
                {
                    const std::size_t neighbour = (z * ny + y) * nx + x;
                    for (std::uint32_t k = cellStart_[neighbour]; k < cellStart_[neighbour + 1]; ++k)
                    {
                        const std::uint32_t j = cellParticles_[k];
                        if (j <= i)
                            continue;
                        const Real reach = ri + particles.radius[j] + skin;
                        if (lengthSquared(xi - particles.position[j]) < reach * reach)
                            scratch_.push_back(j);
                    }
                }
        std::sort(scratch_.begin(), scratch_.end());
        for (std::uint32_t j : scratch_)
        {
            newFirst_.push_back(static_cast<std::uint32_t>(i));
            newSecond_.push_back(j);
        }
    }

    // Merge history by key: both lists are sorted by (i, j).
    newHistory_.assign(newFirst_.size(), ContactHistory{});
    std::size_t old = 0;
    for (std::size_t k = 0; k < newFirst_.size(); ++k)
    {
        const auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
        const std::uint64_t wanted = key(newFirst_[k], newSecond_[k]);
        while (old < first.size() && key(first[old], second[old]) < wanted)
            ++old;
        if (old < first.size() && key(first[old], second[old]) == wanted)
            newHistory_[k] = history[old];
    }
    first.swap(newFirst_);
    second.swap(newSecond_);
    history.swap(newHistory_);
}

} // namespace veridem::dem
