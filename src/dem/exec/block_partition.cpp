#include "dem/exec/block_partition.h"

#include <algorithm>
#include <cmath>

namespace veridem::dem
{

void partitionBlocks(const std::uint64_t* weight, std::size_t blocks, int chunks, std::vector<BlockRun>& runs,
                     const double* share)
{
    runs.clear();
    chunks = std::max(chunks, 1);
    std::uint64_t total = 0;
    for (std::size_t b = 0; b < blocks; ++b)
        total += weight[b];
    double shareTotal = 0, shareBefore = 0; // all shares; those of chunks [0, c]
    if (share)
        for (int c = 0; c < chunks; ++c)
            shareTotal += share[c];
    std::size_t edge = 0;     // the chunk's first block
    std::uint64_t prefix = 0; // weight of blocks [0, edge)
    for (int c = 0; c < chunks; ++c)
    {
        std::size_t end = edge;
        std::uint64_t atEnd = prefix;
        if (c + 1 == chunks)
            end = blocks;
        else
        {
            // The boundary after chunk c: the edge nearest to (c + 1) / chunks of the total, or
            // to the shares of chunks [0, c] (integer arithmetic for equal parts; ties go to the
            // earlier edge).
            std::uint64_t target =
                total * static_cast<std::uint64_t>(c + 1) / static_cast<std::uint64_t>(chunks);
            if (share && shareTotal > 0)
            {
                shareBefore += share[c];
                target = static_cast<std::uint64_t>(
                    std::llround(static_cast<double>(total) * std::min(1.0, shareBefore / shareTotal)));
            }
            while (end < blocks && atEnd + weight[end] <= target)
                atEnd += weight[end++];
            if (end < blocks && atEnd + weight[end] - target < target - atEnd)
                atEnd += weight[end++];
        }
        if (end > edge)
            runs.push_back({static_cast<std::uint32_t>(edge), static_cast<std::uint32_t>(end), c});
        edge = end;
        prefix = atEnd;
    }
}

double heaviestShare(const std::uint64_t* weight, const std::vector<BlockRun>& runs, int chunks)
{
    std::vector<std::uint64_t> load(static_cast<std::size_t>(std::max(chunks, 1)), 0);
    std::uint64_t total = 0;
    for (const BlockRun& r : runs)
        for (std::uint32_t b = r.first; b < r.end; ++b)
        {
            load[static_cast<std::size_t>(r.chunk)] += weight[b];
            total += weight[b];
        }
    return total == 0 ? 0.0
                      : static_cast<double>(*std::max_element(load.begin(), load.end())) /
                            static_cast<double>(total);
}

} // namespace veridem::dem
