// The pair stage's blocks are shared among threads in contiguous ranges that cover every block
// once, in order, with each boundary at the block edge nearest to an equal share of the weight, or
// to the threads' shares when they are given (their measured speeds).
#include "dem/exec/block_partition.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

using namespace veridem::dem;

namespace
{
/// The runs cover blocks [0, blocks) once, in order, in increasing chunks below `chunks`.
void expectCover(const std::vector<BlockRun>& runs, std::size_t blocks, int chunks)
{
    std::uint32_t next = 0;
    int lastChunk = -1;
    for (const BlockRun& r : runs)
    {
        EXPECT_EQ(r.first, next);
        EXPECT_LT(r.first, r.end);
        EXPECT_GT(r.chunk, lastChunk);
        EXPECT_LT(r.chunk, chunks);
        next = r.end;
        lastChunk = r.chunk;
    }
    EXPECT_EQ(next, blocks);
}
} // namespace

TEST(BlockPartition, OneChunkTakesEveryBlock)
{
    const std::vector<std::uint64_t> w{5, 1, 7};
    std::vector<BlockRun> runs;
    partitionBlocks(w.data(), w.size(), 1, runs);
    ASSERT_EQ(runs.size(), 1u);
    expectCover(runs, w.size(), 1);
    EXPECT_DOUBLE_EQ(heaviestShare(w.data(), runs, 1), 1.0);
}

TEST(BlockPartition, NoBlocksNoRuns)
{
    std::vector<BlockRun> runs{{0, 1, 0}};
    partitionBlocks(nullptr, 0, 2, runs);
    EXPECT_TRUE(runs.empty());
}

TEST(BlockPartition, BoundaryAtTheNearestEdge)
{
    // Total 100, half 50: edges after 40 and after 70; 40 is nearer.
    const std::vector<std::uint64_t> w{10, 30, 30, 30};
    std::vector<BlockRun> runs;
    partitionBlocks(w.data(), w.size(), 2, runs);
    expectCover(runs, w.size(), 2);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].end, 2u);
    EXPECT_DOUBLE_EQ(heaviestShare(w.data(), runs, 2), 0.6);
    // Edges after 45 and 55 from 50: a tie goes to the earlier edge.
    const std::vector<std::uint64_t> tie{45, 10, 45};
    partitionBlocks(tie.data(), tie.size(), 2, runs);
    EXPECT_EQ(runs[0].end, 1u);
}

TEST(BlockPartition, ManyBlocksBalanceWithinOneBlock)
{
    // Uneven weights: each chunk's share is within one block's weight of an equal share.
    std::vector<std::uint64_t> w(957);
    for (std::size_t b = 0; b < w.size(); ++b)
        w[b] = 2000 + (b * 7919) % 1500;
    const std::uint64_t total = std::accumulate(w.begin(), w.end(), std::uint64_t{0});
    for (int chunks : {2, 3, 8, 64})
    {
        std::vector<BlockRun> runs;
        partitionBlocks(w.data(), w.size(), chunks, runs);
        expectCover(runs, w.size(), chunks);
        EXPECT_EQ(runs.size(), static_cast<std::size_t>(chunks));
        const double oneBlock = 3500.0 / static_cast<double>(total);
        EXPECT_LE(heaviestShare(w.data(), runs, chunks), 1.0 / chunks + oneBlock) << chunks << " chunks";
    }
}

TEST(BlockPartition, MoreChunksThanBlocksLeavesSomeEmpty)
{
    const std::vector<std::uint64_t> w{3, 3};
    std::vector<BlockRun> runs;
    partitionBlocks(w.data(), w.size(), 4, runs);
    expectCover(runs, w.size(), 4);
    EXPECT_LE(runs.size(), 2u);
}

TEST(BlockPartition, SharesFollowTheThreadsSpeeds)
{
    // A thread twice as fast gets twice the weight: with 30 equal blocks and shares 1 : 2, the
    // boundary is at block 10 (a third), each boundary within one block of its share.
    const std::vector<std::uint64_t> w(30, 100);
    std::vector<BlockRun> runs;
    const double share[2] = {1.0, 2.0};
    partitionBlocks(w.data(), w.size(), 2, runs, share);
    expectCover(runs, w.size(), 2);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].end, 10u);
    // Equal shares give the equal split.
    const double equal[3] = {5.0, 5.0, 5.0};
    std::vector<BlockRun> byShare, byDefault;
    partitionBlocks(w.data(), w.size(), 3, byShare, equal);
    partitionBlocks(w.data(), w.size(), 3, byDefault);
    ASSERT_EQ(byShare.size(), byDefault.size());
    for (std::size_t r = 0; r < byShare.size(); ++r)
        EXPECT_EQ(byShare[r].end, byDefault[r].end);
}
