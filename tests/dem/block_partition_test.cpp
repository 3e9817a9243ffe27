// The pair stage's blocks are shared among threads in contiguous ranges that cover every block
// once, in order, with each boundary at the block edge nearest to an equal share of the weight.
#include "dem/block_partition.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <thread>
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

TEST(BlockRange, FrontAndBackTakeEachBlockOnce)
{
    BlockRange range;
    range.reset(3, 9);
    std::vector<std::uint32_t> taken;
    for (int k = 0; k < 10; ++k) // alternating ends: 3, 8, 4, 7, 5, 6, then nothing
        if (const auto b = (k % 2 == 0) ? range.takeFront() : range.takeBack())
            taken.push_back(*b);
    EXPECT_EQ(taken, (std::vector<std::uint32_t>{3, 8, 4, 7, 5, 6}));
    EXPECT_FALSE(range.takeFront());
    EXPECT_FALSE(range.takeBack());
    range.reset(5, 5); // an empty run
    EXPECT_FALSE(range.takeFront());
}

TEST(BlockRange, TwoThreadsTakeEachBlockExactlyOnce)
{
    // One thread from the front, one from the back, racing on the same range: every block is
    // taken by exactly one of them, the front's blocks ascending and the back's descending.
    constexpr std::uint32_t kBlocks = 20000;
    for (int round = 0; round < 20; ++round)
    {
        BlockRange range;
        range.reset(0, kBlocks);
        std::vector<std::uint32_t> front, back;
        std::thread owner(
            [&]
            {
                while (const auto b = range.takeFront())
                    front.push_back(*b);
            });
        std::thread helper(
            [&]
            {
                while (const auto b = range.takeBack())
                    back.push_back(*b);
            });
        owner.join();
        helper.join();
        ASSERT_EQ(front.size() + back.size(), kBlocks);
        for (std::size_t k = 0; k < front.size(); ++k)
            ASSERT_EQ(front[k], k);
        for (std::size_t k = 0; k < back.size(); ++k)
            ASSERT_EQ(back[k], kBlocks - 1 - k);
    }
}
