// A 12 ms probe of how much of a CPU core this process gets, printed by veridem_bench before and
// after its timed loop (docs/performance.md, "Reading the numbers on a shared machine").
//
// Two integer-add loops, timed with the steady clock:
//   - a chain of dependent adds runs at one add per cycle whatever else shares the core, so its
//     rate is the clock frequency [GHz];
//   - eight independent chains run as many adds per cycle as the core's integer units give this
//     thread: about 3.7 a cycle on an uncontended Zen 3 core with this loop (seen here at
//     3.2 GHz), 2.2-2.8 when another hardware thread (another tenant's, on a shared machine) uses
//     the same core; 4.8-5.1 on a Zen 5 core (one hardware thread per core).
// Their ratio, adds per cycle, tells a run on a whole core from one on a shared core, which the
// clock alone does not (the clock stayed at ~3.1 GHz while the one-ball step took 1.45x longer).
#pragma once

#include <algorithm>
#include <chrono>

namespace veridem::bench
{

/// What a whole core reads, printed after each probe (the hosts this project has run on).
inline constexpr const char* kWholeCoreAdds = "~3.7: a whole Zen 3 core, ~5: a Zen 5 core";

struct CoreProbe
{
    double clockGHz = 0;     // dependent adds per second / 1e9
    double addsPerCycle = 0; // independent adds per cycle; 0: no probe on this CPU
};

/// Nine rounds of both loops (~12 ms in all); the median of each measure, so that a round in
/// which the thread was preempted does not count.
inline CoreProbe probeCore()
{
#if defined(__x86_64__) && defined(__GNUC__)
    using Clock = std::chrono::steady_clock;
    constexpr long kIterations = 250'000;
    constexpr int kRounds = 9;
    double clock[kRounds], perCycle[kRounds];
    for (int r = 0; r < kRounds; ++r)
    {
        unsigned long x = 0;
        auto start = Clock::now();
        for (long i = 0; i < kIterations; ++i) // 8 dependent adds an iteration
            __asm__ volatile("add $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\t"
                             "add $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0"
                             : "+r"(x));
        const double chain = std::chrono::duration<double>(Clock::now() - start).count();
        unsigned long a = 1, b = 2, c = 3, d = 4, e = 5, f = 6, g = 7, h = 8;
        start = Clock::now();
        for (long i = 0; i < kIterations; ++i) // 16 adds in 8 independent chains an iteration
            __asm__ volatile("add $1, %0\n\tadd $1, %1\n\tadd $1, %2\n\tadd $1, %3\n\t"
                             "add $1, %4\n\tadd $1, %5\n\tadd $1, %6\n\tadd $1, %7\n\t"
                             "add $1, %0\n\tadd $1, %1\n\tadd $1, %2\n\tadd $1, %3\n\t"
                             "add $1, %4\n\tadd $1, %5\n\tadd $1, %6\n\tadd $1, %7"
                             : "+r"(a), "+r"(b), "+r"(c), "+r"(d), "+r"(e), "+r"(f), "+r"(g), "+r"(h));
        const double parallel = std::chrono::duration<double>(Clock::now() - start).count();
        const double clockHz = 8.0 * kIterations / chain;
        clock[r] = clockHz / 1e9;
        perCycle[r] = 16.0 * kIterations / parallel / clockHz;
    }
    std::sort(clock, clock + kRounds);
    std::sort(perCycle, perCycle + kRounds);
    return {clock[kRounds / 2], perCycle[kRounds / 2]};
#else
    return {};
#endif
}

} // namespace veridem::bench
