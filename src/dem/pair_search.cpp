#include "dem/pair_search.h"

#include "dem/cell_grid.h"
#include "dem/parallel.h"

#include <algorithm>
#include <cmath>

namespace veridem::dem
{

namespace
{

/// One size class's particles binned on a uniform grid over the particles' bounding box: cell c's
/// particles are cellParticles[cellStart[c], cellStart[c+1]) in ascending index.
struct ClassGrid
{
    Real cell = 0;    // edge [m]
    Real largest = 0; // the class's largest radius R_k [m]
    std::size_t count = 0;
    std::size_t n[3] = {1, 1, 1};
    std::vector<std::uint32_t> cellStart, cellParticles;
};

/// The class of radius r [m]: k with r in [largest / 2^(k+1), largest / 2^k), the last class
/// taking everything smaller.
int classOf(Real r, Real largest, int classes)
{
    int k = 0;
    Real bound = 0.5 * largest;
    while (k + 1 < classes && r < bound)
    {
        ++k;
        bound *= 0.5;
    }
    return k;
}

} // namespace

int sizeClassCount(Real smallest, Real largest)
{
    int count = 1;
    Real bound = 0.5 * largest;
    while (count < kMaxSizeClasses && smallest < bound)
    {
        ++count;
        bound *= 0.5;
    }
    return count;
}

void findPairsWithin(const ParticleStore& particles, Real search, std::vector<std::uint32_t>& count,
                     std::vector<std::uint32_t>& partners, std::size_t expected)
{
    const std::size_t n = particles.size();
    partners.clear();
    if (n == 0)
        return;
    Vec3 lo = particles.position[0], hi = lo;
    Real largest = 0, smallest = particles.radius[0];
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& x = particles.position[i];
        lo = {std::fmin(lo.x, x.x), std::fmin(lo.y, x.y), std::fmin(lo.z, x.z)};
        hi = {std::fmax(hi.x, x.x), std::fmax(hi.y, x.y), std::fmax(hi.z, x.z)};
        largest = std::fmax(largest, particles.radius[i]);
        smallest = std::fmin(smallest, particles.radius[i]);
    }
    const int classes = sizeClassCount(smallest, largest);
    std::vector<std::uint8_t> classOfParticle(classes > 1 ? n : 0);
    ClassGrid grids[kMaxSizeClasses];
    for (std::size_t i = 0; i < n; ++i)
    {
        const int k = classes > 1 ? classOf(particles.radius[i], largest, classes) : 0;
        if (classes > 1)
            classOfParticle[i] = static_cast<std::uint8_t>(k);
        ++grids[k].count;
        grids[k].largest = std::fmax(grids[k].largest, particles.radius[i]);
    }

    // Each class's grid: cells as wide as its largest pair distance, enlarged while they would
    // number more than 4 per particle of the class (a lone particle far away must not create
    // billions of empty cells). Cell counts in floating point, converted only once bounded: a
    // blown-up state (huge or non-finite positions, stopped by the caller's health check) must
    // neither hang this loop nor overflow a conversion. A box that is not finite gets one cell.
    const bool finiteBox = isFinite(hi - lo);
    const Real extent[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
    for (int k = 0; k < classes; ++k)
    {
        ClassGrid& g = grids[k];
        if (g.count == 0)
            continue;
        g.cell = std::fmax(2 * g.largest + search, 1e-12);
        const auto along = [&](Real e) { return finiteBox ? std::floor(e / g.cell) + 1 : Real(1); };
        const Real maxCells = Real(4 * g.count + 64);
        while (along(extent[0]) * along(extent[1]) * along(extent[2]) > maxCells)
            g.cell *= 1.5;
        for (int a = 0; a < 3; ++a)
            g.n[a] = static_cast<std::size_t>(along(extent[a]));
        const std::size_t cells = g.n[0] * g.n[1] * g.n[2];
        // Counting sort of the class's particles by cell (stable: ascending index within a cell).
        g.cellStart.assign(cells + 1, 0);
        g.cellParticles.resize(g.count);
    }
    std::vector<std::uint32_t> cellOf(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        ClassGrid& g = grids[classes > 1 ? classOfParticle[i] : 0];
        const Vec3& x = particles.position[i];
        const std::size_t c =
            (cellCoordinate(x.z, lo.z, g.cell, g.n[2]) * g.n[1] + cellCoordinate(x.y, lo.y, g.cell, g.n[1])) *
                g.n[0] +
            cellCoordinate(x.x, lo.x, g.cell, g.n[0]);
        cellOf[i] = static_cast<std::uint32_t>(c);
        ++g.cellStart[c + 1];
    }
    sortByCell(
        cellOf, classes, [&](std::size_t i) { return classes > 1 ? int(classOfParticle[i]) : 0; },
        [&](int k) -> std::vector<std::uint32_t>& { return grids[k].cellStart; },
        [&](int k) { return grids[k].cellParticles.data(); });

    // For each i, all j > i within r_i + r_j + search, in ascending j. Each chunk of particles
    // (one per thread) collects its own pairs; the chunks are concatenated in order.
    const int chunks = std::min(loopThreads(n), 64);
    std::vector<std::vector<std::uint32_t>> chunkPartners(static_cast<std::size_t>(chunks));
    if (expected > 0 && chunks > 1)
        for (auto& part : chunkPartners)
            part.reserve((expected + expected / 8) / static_cast<std::size_t>(chunks) + 64);
    parallelChunks(
        n, chunks,
        [&](int chunk, std::size_t begin, std::size_t end)
        {
            std::vector<std::uint32_t>& out = chunkPartners[static_cast<std::size_t>(chunk)];
            std::vector<std::uint32_t> scratch;
            for (std::size_t i = begin; i < end; ++i)
            {
                const Vec3 xi = particles.position[i];
                const Real ri = particles.radius[i];
                scratch.clear();
                for (int k = 0; k < classes; ++k)
                {
                    const ClassGrid& g = grids[k];
                    if (g.count == 0)
                        continue;
                    // Cells within reach: one on each side while r_i <= R_k (the cell is then
                    // at least r_i + R_k + search wide); more for a sphere larger than the class.
                    const Real cellsAway = (ri + g.largest + search) / g.cell;
                    const std::size_t widest = std::max({g.n[0], g.n[1], g.n[2]});
                    const std::size_t m = cellsAway <= 1 ? 1
                                          : cellsAway < Real(widest)
                                              ? static_cast<std::size_t>(std::ceil(cellsAway))
                                              : widest; // (also NaN: the whole grid)
                    const std::size_t cx = cellCoordinate(xi.x, lo.x, g.cell, g.n[0]),
                                      cy = cellCoordinate(xi.y, lo.y, g.cell, g.n[1]),
                                      cz = cellCoordinate(xi.z, lo.z, g.cell, g.n[2]);
                    const std::size_t xBegin = cx > m ? cx - m : 0, xEnd = std::min(cx + m, g.n[0] - 1);
                    for (std::size_t z = cz > m ? cz - m : 0; z <= std::min(cz + m, g.n[2] - 1); ++z)
                        for (std::size_t y = cy > m ? cy - m : 0; y <= std::min(cy + m, g.n[1] - 1); ++y)
                        {
                            const std::size_t row = (z * g.n[1] + y) * g.n[0];
                            // Cells of one row are contiguous in cellParticles.
                            for (std::uint32_t s = g.cellStart[row + xBegin]; s < g.cellStart[row + xEnd + 1];
                                 ++s)
                            {
                                const std::uint32_t j = g.cellParticles[s];
                                if (j <= i)
                                    continue;
                                const Real within = ri + particles.radius[j] + search;
                                if (lengthSquared(xi - particles.position[j]) < within * within)
                                    scratch.push_back(j);
                            }
                        }
                }
                std::sort(scratch.begin(), scratch.end());
                out.insert(out.end(), scratch.begin(), scratch.end());
                count[i + 1] = static_cast<std::uint32_t>(scratch.size());
            }
        });
    // The grids are no longer needed: freed before the chunks are joined (the rebuild's peak).
    for (ClassGrid& g : grids)
    {
        std::vector<std::uint32_t>().swap(g.cellStart);
        std::vector<std::uint32_t>().swap(g.cellParticles);
    }
    std::vector<std::uint32_t>().swap(cellOf);
    std::vector<std::uint8_t>().swap(classOfParticle);
    std::size_t total = 0;
    for (const auto& part : chunkPartners)
        total += part.size();
    partners.reserve(total);
    for (const auto& part : chunkPartners)
        partners.insert(partners.end(), part.begin(), part.end());
}

} // namespace veridem::dem
