// The thread split of the pair stage: which thread evaluates which run of particle blocks
// (World::pairSchedule, dem/exec/block_partition.h), weighted by each block's touching candidates and
// moved as the threads' measured speeds change. Any split gives the same bits: the order of the
// sums does not depend on it (dem/forces.cpp). No physics here.
#pragma once

#include "dem/exec/block_partition.h"
#include "dem/world.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace veridem::dem
{

inline constexpr int kMaxChunks = 64; // threads of a force stage, at most

/// The runs of blocks the threads evaluate (world.exec.pairSchedule), remade when the candidate
/// sub-list, the slots or the thread count changed. Weight of a block: its touching candidates
/// (the selection and the kernel follow their count), a cross-block one counted three times,
/// because its partner lies in another block and it stores a deferred entry. On the 20k bed,
/// blocks 0-9 hold 9.6 % more candidates but 55 % more cross-block ones, and two threads split
/// by plain count take 11-25 % longer on them; the weight 3 fits that (the longer thread's pair
/// time is 2.12-2.40 s against 2.44-2.97 s per 3000 steps). The imbalance is not false sharing:
/// a block's deferred entries are one range in slot order. The order of the sums does not depend on
/// the schedule: any split gives the same bits. `activeFrom`: particle -> its first candidate.
template <class ActiveFrom>
inline const std::vector<BlockRun>& scheduleBlocks(World& world, std::size_t blocks, int chunks,
                                                   const ActiveFrom& activeFrom)
{
    PairSchedule& s = world.exec.pairSchedule;
    const NeighborList& list = world.neighbors;
    const std::size_t n = world.particles.size();
    if (s.chunks != chunks || s.subListRebuilds != list.activeRebuildCount() ||
        s.slotRebuilds != list.rebuildCount() || s.particles != n)
    {
        constexpr std::size_t B = NeighborList::kBlockParticles;
        constexpr std::uint64_t kCrossBlockWeight = 3;
        std::vector<std::uint64_t> weight(blocks);
        for (std::size_t b = 0; b < blocks; ++b)
        {
            const std::size_t begin = activeFrom(b * B), end = activeFrom(std::min((b + 1) * B, n));
            std::uint64_t w = end - begin;
            for (std::size_t a = begin; a < end; ++a)
                w += (kCrossBlockWeight - 1) * (list.activeDeferred[a] != NeighborList::kInBlock);
            weight[b] = w;
        }
        if (s.speed.size() != static_cast<std::size_t>(chunks))
            s.speed.assign(static_cast<std::size_t>(chunks), 0.0); // other threads: measure anew
        const bool measured = std::all_of(s.speed.begin(), s.speed.end(), [](double v) { return v > 0; });
        partitionBlocks(weight.data(), blocks, chunks, s.runs, measured ? s.speed.data() : nullptr);
        s.heaviestShare = heaviestShare(weight.data(), s.runs, chunks);
        s.weight = std::move(weight);
        s.runHealth.assign(blocks, ContactHealth{});
        s.chunks = chunks;
        s.subListRebuilds = list.activeRebuildCount();
        s.slotRebuilds = list.rebuildCount();
        s.particles = n;
    }
    return s.runs;
}

/// After a parallel pair stage: folds each thread's rate on its own run (its runs' weight over
/// `seconds[c]`, the time it took) into the running mean of its speed, and moves the split if
/// the speeds predict the stage at least 3 % shorter (partitionBlocks with the speeds as shares).
/// The margin keeps the boundary from moving back and forth between two block edges as the
/// measured speeds jitter: each move carries a block's rows (~200 KB) to the other core once.
void adaptSchedule(PairSchedule& s, const double* seconds, int chunks);

} // namespace veridem::dem
