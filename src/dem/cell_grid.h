// The binning the three particle grids share: the neighbour list's search (pair_search.cpp, a
// grid per size class), the pairs through periodic faces (periodic.cpp) and the insertion look-up
// (particle_index.cpp). Each sizes its own grid (cell edge and counts: its own cut-off, periodic
// axes, a cover box); a point's cell along an axis and the sort of particles by cell are written
// here once.
#pragma once

#include "core/constants.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// The cell along one axis of a grid starting at `origin` [m] with cells `cell` [m] wide,
/// `count` of them, of the coordinate `value` [m]. Beyond the grid (or not finite): its nearest
/// cell on that axis (NaN: cell 0). Clamping moves two points closer along the axis, so two
/// points within one cell of each other stay in neighbouring cells.
inline std::size_t cellCoordinate(Real value, Real origin, Real cell, std::size_t count)
{
    const Real c = (value - origin) / cell;
    return c >= 0 && c < Real(count) ? static_cast<std::size_t>(c) : c >= Real(count) ? count - 1 : 0;
}

/// Counting sort of particles by cell, on one grid or several (each particle on one of them):
/// particle i of `cellOf.size()` is in cell cellOf[i] of grid gridOf(i); on entry startOf(g)[c + 1]
/// holds the number of grid g's particles in its cell c (startOf(g)[0] = 0); on return
/// startOf(g)[c] is where that cell's particles begin in sortedOf(g) and startOf(g)[c + 1] where
/// they end, each cell's in ascending index. sortedOf(g) must hold grid g's particles.
template <class GridOf, class StartOf, class SortedOf>
void sortByCell(const std::vector<std::uint32_t>& cellOf, int grids, GridOf gridOf, StartOf startOf,
                SortedOf sortedOf)
{
    std::vector<std::vector<std::uint32_t>> fill(grids);
    for (int g = 0; g < grids; ++g)
    {
        std::vector<std::uint32_t>& start = startOf(g);
        for (std::size_t c = 0; c + 1 < start.size(); ++c)
            start[c + 1] += start[c];
        if (!start.empty())
            fill[g].assign(start.begin(), start.end() - 1);
    }
    for (std::size_t i = 0; i < cellOf.size(); ++i)
    {
        const int g = gridOf(i);
        sortedOf(g)[fill[g][cellOf[i]]++] = static_cast<std::uint32_t>(i);
    }
}

} // namespace veridem::dem
