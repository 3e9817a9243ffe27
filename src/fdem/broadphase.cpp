#include "fdem/broadphase.h"

#include "exec/thread_pool.h"

#include <algorithm>
#include <cmath>

namespace veridem::fdem
{

std::vector<std::pair<std::uint32_t, std::uint32_t>> findCandidatePairs(const std::vector<BoundingBox>& boxes,
                                                                        Real buffer)
{
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    const std::size_t n = boxes.size();
    if (n < 2)
        return pairs;
    // Binned by centre: two boxes within the buffer have centres at most (the larger side + buffer)
    // apart along each axis, so in the same or a neighbouring cell.
    std::vector<Vec2> centre(n);
    Real side = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        centre[i] = (boxes[i].lo + boxes[i].hi) / 2;
        side = std::max({side, boxes[i].hi.x - boxes[i].lo.x, boxes[i].hi.y - boxes[i].lo.y});
    }
    Vec2 lo = centre[0], hi = lo;
    for (const Vec2& c : centre)
    {
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
        hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
    }
    Real cell = side + buffer;
    const Real maxCells = 4.0 * static_cast<Real>(n) + 1024;
    auto cellsAlong = [&](Real extent) { return static_cast<std::size_t>(std::floor(extent / cell)) + 1; };
    while (static_cast<Real>(cellsAlong(hi.x - lo.x)) * static_cast<Real>(cellsAlong(hi.y - lo.y)) > maxCells)
        cell *= 1.5;
    const std::size_t nx = cellsAlong(hi.x - lo.x), ny = cellsAlong(hi.y - lo.y);
    std::vector<std::size_t> cellOf(n);
    std::vector<std::uint32_t> start(nx * ny + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
    {
        const auto ix = std::min(nx - 1, static_cast<std::size_t>((centre[i].x - lo.x) / cell));
        const auto iy = std::min(ny - 1, static_cast<std::size_t>((centre[i].y - lo.y) / cell));
        cellOf[i] = iy * nx + ix;
        ++start[cellOf[i] + 1];
    }
    for (std::size_t c = 0; c < nx * ny; ++c)
        start[c + 1] += start[c];
    std::vector<std::uint32_t> sorted(n);
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
            sorted[fill[cellOf[i]]++] = static_cast<std::uint32_t>(i);
    }
    // Rows of cells in chunks on the thread pool, each chunk into its own list; the lists are joined
    // and sorted, so the result does not depend on the thread count.
    constexpr std::size_t kRows = 8;
    const std::size_t chunks = (ny + kRows - 1) / kRows;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(chunks);
    exec::run(static_cast<int>(chunks),
              [&](int chunk)
              {
                  auto& out = found[static_cast<std::size_t>(chunk)];
                  const auto test = [&](std::uint32_t i, std::uint32_t j)
                  {
                      const BoundingBox &a = boxes[i], &b = boxes[j];
                      if (a.group != b.group && (a.active || b.active) && withinBuffer(a, b, buffer))
                          out.emplace_back(std::min(i, j), std::max(i, j));
                  };
                  const std::size_t rowEnd = std::min(ny, (static_cast<std::size_t>(chunk) + 1) * kRows);
                  for (std::size_t iy = static_cast<std::size_t>(chunk) * kRows; iy < rowEnd; ++iy)
                      for (std::size_t ix = 0; ix < nx; ++ix)
                      {
                          const std::size_t c = iy * nx + ix;
                          for (std::uint32_t p = start[c]; p < start[c + 1]; ++p)
                          {
                              for (std::uint32_t q = p + 1; q < start[c + 1]; ++q)
                                  test(sorted[p], sorted[q]);
                              // half neighbourhood: E, NW, N, NE
                              const long offsets[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
                              for (const auto& o : offsets)
                              {
                                  const long jx = static_cast<long>(ix) + o[0],
                                             jy = static_cast<long>(iy) + o[1];
                                  if (jx < 0 || jy < 0 || jx >= static_cast<long>(nx) ||
                                      jy >= static_cast<long>(ny))
                                      continue;
                                  const std::size_t d =
                                      static_cast<std::size_t>(jy) * nx + static_cast<std::size_t>(jx);
                                  for (std::uint32_t q = start[d]; q < start[d + 1]; ++q)
                                      test(sorted[p], sorted[q]);
                              }
                          }
                      }
                  std::sort(out.begin(), out.end());
              });
    std::size_t total = 0;
    for (const auto& f : found)
        total += f.size();
    pairs.reserve(total);
    for (const auto& f : found)
        pairs.insert(pairs.end(), f.begin(), f.end());
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

} // namespace veridem::fdem
