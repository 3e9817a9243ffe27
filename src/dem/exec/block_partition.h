// Which thread evaluates which block of the pair stage.
//
// The pair stage works on fixed blocks of particles (NeighborList::kBlockParticles). A block's
// contacts write only its own particles' force sums, its candidates' history and the deferred
// entries of its cross-block slots, so the blocks may be shared among threads in any grouping
// without changing a single bit of the result; only the health record (the largest overlap, the
// first slot that has it) must be folded in block order. Each thread takes a contiguous range of
// blocks (its partners stay together in cache: a finer mix of blocks, balanced to 50.1 % of the
// candidates on the 20k bed, makes the two threads' total work ~10 % larger), with the boundary at
// the block edge nearest to the thread's share of the weight.
//
// The threads need not be equally fast: on a shared machine another tenant can slow one core
// for seconds at a time. So the shares follow each thread's measured speed (exec/pair_schedule.h,
// scheduleBlocks): the pair stage times each thread on its own run, and the boundary moves by
// whole blocks when the speeds predict a shorter stage. No thread takes another's blocks within a
// step: on a host whose two vCPUs are ~480 ns apart, a block taken every step moves its rows to
// the other core and back every step (20k bed, two threads: 2.49e7 particle-steps/s with that
// against 3.14e7 without, docs/performance.md). A moved boundary moves the rows of one block once. Stage 4
// (world.cpp, PassSchedule) is balanced the same way on its own measured rates, at a finer grain (64
// particles).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// Blocks [first, end) evaluated by thread (chunk) `chunk`.
struct BlockRun
{
    std::uint32_t first = 0, end = 0;
    int chunk = 0;
};

/// Shares `blocks` blocks of work `weight[b]` (any unit) among `chunks` threads (chunks >= 1; blocks
/// may be 0) in contiguous ranges. Writes the runs (one per chunk that has blocks) to `runs`, in
/// block order, covering every block exactly once. `share` (chunks values, positive): the part of
/// the weight each thread should get, in proportion (null: equal parts); each boundary is the
/// block edge nearest to its thread's cumulative part.
void partitionBlocks(const std::uint64_t* weight, std::size_t blocks, int chunks, std::vector<BlockRun>& runs,
                     const double* share = nullptr);

/// The largest chunk's share of the total weight (0.5 is perfect balance on two threads), for
/// the benchmark's report and the tests.
double heaviestShare(const std::uint64_t* weight, const std::vector<BlockRun>& runs, int chunks);

} // namespace veridem::dem
