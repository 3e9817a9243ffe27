#include "dem/exec/pair_schedule.h"

namespace veridem::dem
{

void adaptSchedule(PairSchedule& s, const double* seconds, int chunks)
{
    constexpr double kMix = 1.0 / 16; // weight of the newest step in the running mean
    constexpr double kMargin = 0.97;  // move only for a stage predicted this much shorter
    std::uint64_t runWeight[kMaxChunks] = {};
    for (const BlockRun& r : s.runs)
        for (std::uint32_t b = r.first; b < r.end; ++b)
            runWeight[r.chunk] += s.weight[b];
    bool measured = true;
    for (int c = 0; c < chunks; ++c)
    {
        double& speed = s.speed[static_cast<std::size_t>(c)];
        if (seconds[c] > 0 && runWeight[c] > 0)
        {
            const double rate = static_cast<double>(runWeight[c]) / seconds[c];
            speed = speed > 0 ? speed + kMix * (rate - speed) : rate;
        }
        measured = measured && speed > 0;
    }
    if (!measured)
        return;
    // The stage takes as long as its slowest thread: max over threads of weight / speed.
    const auto predicted = [&](const std::vector<BlockRun>& runs)
    {
        std::uint64_t load[kMaxChunks] = {};
        for (const BlockRun& r : runs)
            for (std::uint32_t b = r.first; b < r.end; ++b)
                load[r.chunk] += s.weight[b];
        double longest = 0;
        for (int c = 0; c < chunks; ++c)
            longest = std::max(longest, static_cast<double>(load[c]) / s.speed[static_cast<std::size_t>(c)]);
        return longest;
    };
    partitionBlocks(s.weight.data(), s.weight.size(), chunks, s.proposal, s.speed.data());
    if (predicted(s.proposal) < kMargin * predicted(s.runs))
    {
        std::swap(s.runs, s.proposal);
        s.heaviestShare = heaviestShare(s.weight.data(), s.runs, chunks);
        ++s.moves;
    }
}

} // namespace veridem::dem
