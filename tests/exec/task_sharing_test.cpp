#include "exec/task_sharing.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace veridem::exec
{
namespace
{

/// Workers as the verification runner has them: they run pending tasks until close().
struct Helpers
{
    TaskSharing& sharing;
    std::vector<std::thread> threads;
    Helpers(TaskSharing& s, int n) : sharing(s)
    {
        for (int i = 0; i < n; ++i)
            threads.emplace_back(
                [this]
                {
                    while (sharing.runPending() || sharing.waitForTask())
                    {
                    }
                });
    }
    ~Helpers()
    {
        sharing.close();
        for (auto& t : threads)
            t.join();
    }
};

TEST(TaskSharing, CallerAloneRunsEveryTaskOnce)
{
    TaskSharing sharing;
    std::vector<int> runs(50, 0);
    sharing.forEach(runs.size(), [&](std::size_t i) { ++runs[i]; });
    for (int r : runs)
        EXPECT_EQ(r, 1);
    sharing.forEach(0, [](std::size_t) { FAIL() << "no task to run"; });
}

TEST(TaskSharing, HelpersShareTheTasksAndEachRunsOnce)
{
    TaskSharing sharing;
    Helpers helpers(sharing, 3);
    std::vector<std::atomic<int>> runs(400);
    std::vector<double> results(runs.size(), 0);
    std::atomic<int> otherThreads{0};
    const auto caller = std::this_thread::get_id();
    sharing.forEach(runs.size(),
                    [&](std::size_t i)
                    {
                        ++runs[i];
                        if (std::this_thread::get_id() != caller)
                            ++otherThreads;
                        double x = 0; // a little work, so that the helpers get some
                        for (int k = 0; k < 20000; ++k)
                            x += 1.0 / static_cast<double>(std::size_t(k) + i + 1);
                        results[i] = x;
                    });
    for (std::size_t i = 0; i < runs.size(); ++i)
    {
        EXPECT_EQ(runs[i].load(), 1) << "task " << i;
        EXPECT_GT(results[i], 0) << "task " << i;
    }
    EXPECT_GT(otherThreads.load(), 0) << "the helpers took none of 400 tasks";
}

TEST(TaskSharing, NestedForEachAndTwoCallersFinish)
{
    TaskSharing sharing;
    Helpers helpers(sharing, 1);
    std::atomic<int> total{0};
    const auto outer = [&]
    { sharing.forEach(6, [&](std::size_t) { sharing.forEach(5, [&](std::size_t) { ++total; }); }); };
    std::thread second(outer);
    outer();
    second.join();
    EXPECT_EQ(total.load(), 2 * 6 * 5);
}

TEST(TaskSharing, FirstExceptionByIndexAfterAllTasksRan)
{
    TaskSharing sharing;
    Helpers helpers(sharing, 2);
    std::atomic<int> ran{0};
    try
    {
        sharing.forEach(20,
                        [&](std::size_t i)
                        {
                            ++ran;
                            if (i == 7 || i == 13)
                                throw std::runtime_error("task " + std::to_string(i));
                        });
        FAIL() << "no exception";
    }
    catch (const std::runtime_error& e)
    {
        EXPECT_STREQ(e.what(), "task 7");
    }
    EXPECT_EQ(ran.load(), 20);
}

TEST(TaskSharing, AWaitingCallerDoesTheIdleWork)
{
    TaskSharing sharing;
    std::atomic<bool> idleRan{false}, secondStarted{false}, timedOut{false};
    sharing.setIdleWork(
        [&]
        {
            const bool first = !idleRan.exchange(true);
            return first; // one piece of idle work, then nothing left
        });
    Helpers helpers(sharing, 1);
    const auto waitFor = [&](const std::atomic<bool>& flag)
    {
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (!flag && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        if (!flag)
            timedOut = true;
    };
    // The caller takes task 0 (its own first, under the lock that offered them), and holds it until
    // the helper has taken task 1; task 1 ends only once the caller, with nothing pending, has done
    // the idle work.
    sharing.forEach(2,
                    [&](std::size_t i)
                    {
                        if (i == 0)
                            waitFor(secondStarted);
                        else
                        {
                            secondStarted = true;
                            waitFor(idleRan);
                        }
                    });
    EXPECT_TRUE(idleRan.load());
    EXPECT_FALSE(timedOut.load());
}

TEST(TaskSharing, WaitForTaskReturnsFalseAfterClose)
{
    TaskSharing sharing;
    sharing.close();
    EXPECT_FALSE(sharing.waitForTask());
    EXPECT_FALSE(sharing.runPending());
}

} // namespace
} // namespace veridem::exec
