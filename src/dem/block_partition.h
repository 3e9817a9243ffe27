// Which thread evaluates which block of the pair stage.
//
// The pair stage works on fixed blocks of particles (NeighborList::kBlockParticles). A block's
// contacts write only its own particles' force sums, its candidates' history and the deferred
// entries of its cross-block slots, so the blocks may be shared among threads in any grouping
// without changing a single bit of the result; only the health record (the largest overlap, the
// first slot that has it) must be folded in block order. Each thread takes a contiguous range of
// blocks (its partners stay together in cache: a finer mix of blocks, balanced to 50.1 % of the
// candidates on the 20k bed, made the two threads' total work ~10 % larger), with the boundary at
// the block edge nearest to an equal share of the weight.
//
// That split is fixed for many steps, but on a shared machine each core's speed is not: another
// tenant's hardware thread slows one core, then the other (docs/performance.md, session 13: ~7 %
// of the two-thread pair stage lost waiting for the slower thread). So each thread takes its
// range's blocks from the front, one at a time, and a thread that has finished its own range
// takes the remaining blocks of the others from their back ends (BlockRange): the ranges stay
// contiguous except where two threads meet, and every block is still evaluated exactly once.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
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
/// block order, covering every block exactly once.
void partitionBlocks(const std::uint64_t* weight, std::size_t blocks, int chunks,
                     std::vector<BlockRun>& runs);

/// The largest chunk's share of the total weight (0.5 is perfect balance on two threads), for
/// the benchmark's report and the tests.
double heaviestShare(const std::uint64_t* weight, const std::vector<BlockRun>& runs, int chunks);

/// The blocks [front, back) of one thread's run not yet taken, shared between threads: its owner
/// takes them from the front, the others from the back, each block exactly once (one atomic
/// word holds both ends, so a front and a back claim cannot take the same block). On its own
/// cache line, so that claims on one range do not slow the threads claiming on another.
class alignas(64) BlockRange
{
  public:
    /// Blocks [first, end) to be taken (not safe while another thread claims).
    void reset(std::uint32_t first, std::uint32_t end)
    {
        ends_.store(pack(first, end), std::memory_order_relaxed);
    }
    /// The first block not yet taken, now taken; none if the range is empty.
    std::optional<std::uint32_t> takeFront() { return take(true); }
    /// The last block not yet taken, now taken; none if the range is empty.
    std::optional<std::uint32_t> takeBack() { return take(false); }

  private:
    static std::uint64_t pack(std::uint32_t front, std::uint32_t back)
    {
        return (std::uint64_t(front) << 32) | back;
    }
    std::optional<std::uint32_t> take(bool fromFront)
    {
        // Relaxed: a block's inputs were written before the parallel region started, and its
        // results are read after the region's closing barrier; only the claim must be atomic.
        std::uint64_t ends = ends_.load(std::memory_order_relaxed);
        for (;;)
        {
            const auto front = static_cast<std::uint32_t>(ends >> 32),
                       back = static_cast<std::uint32_t>(ends);
            if (front >= back)
                return std::nullopt;
            const std::uint64_t taken = fromFront ? pack(front + 1, back) : pack(front, back - 1);
            if (ends_.compare_exchange_weak(ends, taken, std::memory_order_relaxed))
                return fromFront ? front : back - 1;
        }
    }
    std::atomic<std::uint64_t> ends_{0};
};

} // namespace veridem::dem
