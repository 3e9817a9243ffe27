// Waiting for an atomic counter to leave a value: bounded spinning (the bound adapted to the
// waiter's recent waits), then blocking in the kernel.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace veridem::exec
{

/// Tells the core that this thread is spinning (x86: pause, which also frees the core's shared
/// units for its other hardware thread).
inline void relax()
{
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
}

/// How long one waiting thread spins before it blocks [ns], adapted to its own recent waits.
/// A wait that ends within `most` (the awaited thread was running, a few tens of microseconds
/// behind) raises the spin to twice that wait, up to `most`, so that the next such wait ends in
/// the spin instead of paying a futex wake-up (~20 us here). A longer wait (the awaited thread
/// was most likely descheduled) drops it to `least`, so that a thread waiting for a preempted
/// peer gives its core up after a few microseconds.
struct SpinBudget
{
    std::int64_t ns = 0;

    void update(std::int64_t waited, std::int64_t least, std::int64_t most)
    {
        ns = waited > most ? least : std::clamp(std::max(ns, 2 * waited), least, most);
    }
};

/// Returns the value of `word` once it differs from `old`. Spins (relax() between loads) for at
/// most budget.ns (at least `least`), then blocks on the word (std::atomic::wait, a futex on
/// Linux) after adding 1 to `sleepers`, which the writer reads to know whether to call
/// notify_all: the writer changes `word`, then loads `sleepers`, the waiter adds to `sleepers`,
/// then loads `word`, all sequentially consistent, so at least one of the two sees the other's
/// write and no wake-up is lost. Then updates the budget with the time waited.
inline std::uint32_t waitWhileEqual(const std::atomic<std::uint32_t>& word, std::uint32_t old,
                                    std::atomic<std::uint32_t>& sleepers, SpinBudget& budget,
                                    std::int64_t least, std::int64_t most)
{
    std::uint32_t now = word.load(std::memory_order_acquire);
    if (now != old)
        return now;
    const auto start = std::chrono::steady_clock::now();
    const auto spin = std::chrono::nanoseconds(std::clamp(budget.ns, least, most));
    const auto waited = [&] { return (std::chrono::steady_clock::now() - start).count(); };
    for (;;)
    {
        // The clock is read once per 16 loads (a pause is tens of cycles, a clock read ~20 ns).
        for (int k = 0; k < 16; ++k)
        {
            relax();
            now = word.load(std::memory_order_acquire);
            if (now != old)
            {
                budget.update(waited(), least, most);
                return now;
            }
        }
        if (std::chrono::steady_clock::now() - start >= spin)
            break;
    }
    sleepers.fetch_add(1, std::memory_order_seq_cst);
    while ((now = word.load(std::memory_order_seq_cst)) == old)
        word.wait(old, std::memory_order_seq_cst);
    sleepers.fetch_sub(1, std::memory_order_relaxed);
    budget.update(waited(), least, most);
    return now;
}

/// Makes a change of `word` visible to waitWhileEqual: call after the change.
inline void wakeWaiters(std::atomic<std::uint32_t>& word, const std::atomic<std::uint32_t>& sleepers)
{
    if (sleepers.load(std::memory_order_seq_cst) != 0)
        word.notify_all();
}

} // namespace veridem::exec
