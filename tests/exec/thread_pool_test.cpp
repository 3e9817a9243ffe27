// The thread pool of the parallel loops (exec/thread_pool.h): every chunk runs exactly once,
// whatever the thread count; the workers take part; nested calls and per-thread overrides run on
// the calling thread; no wake-up is lost when the workers have gone to sleep.
#include "exec/thread_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

namespace veridem::exec
{
namespace
{

TEST(ThreadPool, EveryChunkRunsExactlyOnce)
{
    for (const int threads : {1, 2, 3, 4})
    {
        const ThreadCountOverride loops(threads);
        for (const int chunks : {0, 1, 2, 3, 5, 8, 33, 70}) // (above 32: several chunks a slot)
            for (int repeat = 0; repeat < 20; ++repeat)
            {
                std::vector<std::atomic<int>> runs(static_cast<std::size_t>(chunks));
                std::vector<std::thread::id> ran(static_cast<std::size_t>(chunks));
                run(chunks,
                    [&](int c)
                    {
                        ++runs[static_cast<std::size_t>(c)];
                        ran[static_cast<std::size_t>(c)] = std::this_thread::get_id();
                    });
                std::vector<std::thread::id> distinct;
                for (int c = 0; c < chunks; ++c)
                {
                    const auto k = static_cast<std::size_t>(c);
                    EXPECT_EQ(runs[k].load(), 1) << threads << " threads, chunk " << c << " of " << chunks;
                    if (std::find(distinct.begin(), distinct.end(), ran[k]) == distinct.end())
                        distinct.push_back(ran[k]);
                }
                EXPECT_LE(distinct.size(), static_cast<std::size_t>(threads));
            }
    }
}

/// The caller's chunk waits until another chunk has run on another thread (up to 10 s, far
/// beyond any wake-up): the workers take part.
TEST(ThreadPool, WorkersTakePart)
{
    const ThreadCountOverride loops(2);
    const auto caller = std::this_thread::get_id();
    std::atomic<bool> elsewhere{false};
    run(2,
        [&](int)
        {
            if (std::this_thread::get_id() != caller)
            {
                elsewhere = true;
                return;
            }
            const auto start = std::chrono::steady_clock::now();
            while (!elsewhere && std::chrono::steady_clock::now() - start < std::chrono::seconds(10))
                std::this_thread::yield();
        });
    EXPECT_TRUE(elsewhere.load());
}

TEST(ThreadPool, ANestedCallRunsOnTheCallingThread)
{
    const ThreadCountOverride loops(2);
    std::vector<int> inner(4, 0);
    std::atomic<int> innerOnOtherThreads{0};
    run(2,
        [&](int outer)
        {
            const auto self = std::this_thread::get_id();
            run(2,
                [&](int c)
                {
                    ++inner[static_cast<std::size_t>(2 * outer + c)];
                    if (std::this_thread::get_id() != self)
                        ++innerOnOtherThreads;
                });
        });
    EXPECT_EQ(inner, std::vector<int>(4, 1));
    EXPECT_EQ(innerOnOtherThreads.load(), 0);
}

TEST(ThreadPool, AnOverrideOfOneRunsEveryChunkOnTheCallingThread)
{
    const ThreadCountOverride outer(2);
    {
        const ThreadCountOverride loops(1);
        EXPECT_EQ(threads(), 1);
        int onOtherThreads = 0; // (written by the calling thread only, if the override holds)
        const auto self = std::this_thread::get_id();
        run(4, [&](int) { onOtherThreads += std::this_thread::get_id() != self; });
        EXPECT_EQ(onOtherThreads, 0);
    }
    EXPECT_EQ(threads(), 2); // restored
    EXPECT_THROW(ThreadCountOverride(0), std::invalid_argument);
    EXPECT_THROW(setThreads(0), std::invalid_argument);
}

/// Many joins in a row, some right after the last (the workers still spinning), some after a
/// pause longer than the spin (the workers asleep), and with no spin at all (every wait blocks):
/// a lost wake-up would hang here (CTest's timeout), a lost or repeated chunk would miscount.
TEST(ThreadPool, ManyJoinsWithSpinningAndSleepingWorkers)
{
    const ThreadCountOverride loops(3);
    const std::int64_t defaultSpin = spinNanoseconds();
    for (const std::int64_t spin : {defaultSpin, std::int64_t{0}})
    {
        setSpinNanoseconds(spin);
        std::atomic<long> sum{0};
        long expected = 0;
        for (int round = 0; round < 20000; ++round)
        {
            if (round % 1000 == 0)
                std::this_thread::sleep_for(std::chrono::microseconds(3 * defaultSpin / 1000 + 1));
            run(3, [&](int c) { sum += c + 1; });
            expected += 6;
        }
        EXPECT_EQ(sum.load(), expected) << "spin " << spin << " ns";
    }
    setSpinNanoseconds(defaultSpin);
    EXPECT_THROW(setSpinNanoseconds(-1), std::invalid_argument);
}

} // namespace
} // namespace veridem::exec
