// Waiting for an atomic counter to leave a value: bounded spinning, then blocking in the kernel.
#pragma once

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

/// Returns the value of `word` once it differs from `old`. Spins (relax() between loads) for at
/// most `spinNanoseconds`, then blocks on the word (std::atomic::wait, a futex on Linux) after
/// adding 1 to `sleepers`, which the writer reads to know whether to call notify_all: the writer
/// changes `word`, then loads `sleepers`, the waiter adds to `sleepers`, then loads `word`, all
/// sequentially consistent, so at least one of the two sees the other's write and no wake-up is
/// lost.
inline std::uint32_t waitWhileEqual(const std::atomic<std::uint32_t>& word, std::uint32_t old,
                                    std::atomic<std::uint32_t>& sleepers, std::int64_t spinNanoseconds)
{
    std::uint32_t now = word.load(std::memory_order_acquire);
    if (now != old)
        return now;
    const auto start = std::chrono::steady_clock::now();
    const auto budget = std::chrono::nanoseconds(spinNanoseconds);
    for (;;)
    {
        // The clock is read once per 16 loads (a pause is tens of cycles, a clock read ~20 ns).
        for (int k = 0; k < 16; ++k)
        {
            relax();
            now = word.load(std::memory_order_acquire);
            if (now != old)
                return now;
        }
        if (std::chrono::steady_clock::now() - start >= budget)
            break;
    }
    sleepers.fetch_add(1, std::memory_order_seq_cst);
    while ((now = word.load(std::memory_order_seq_cst)) == old)
        word.wait(old, std::memory_order_seq_cst);
    sleepers.fetch_sub(1, std::memory_order_relaxed);
    return now;
}

/// Makes a change of `word` visible to waitWhileEqual: call after the change.
inline void wakeWaiters(std::atomic<std::uint32_t>& word, const std::atomic<std::uint32_t>& sleepers)
{
    if (sleepers.load(std::memory_order_seq_cst) != 0)
        word.notify_all();
}

} // namespace veridem::exec
