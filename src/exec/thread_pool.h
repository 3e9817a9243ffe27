// The threads of the parallel loops: a process-wide thread count and a persistent pool of worker
// threads with one fork-join operation, run(chunks, body). No physics here.
//
// Chunk c runs on participant c % P of a pool of P threads (participant 0 is the calling thread,
// participants 1..P-1 the pool's workers) whenever that participant is running, so a caller that
// gives each thread a share of the work by its chunk index (the measured-speed splits of the force
// stages) sees each chunk on the same thread from call to call. A participant that has not
// started its chunks when another runs out of work (asleep, or preempted by another process)
// leaves them to the one that is running: no one waits for a thread that is not there. Which
// thread runs a chunk never changes what the chunk computes: callers write per-chunk results and
// combine them in chunk order, so results are the same bits for any thread count.
//
// Waiting. A thread with nothing to do spins (a pause instruction per check), then blocks in the
// kernel (std::atomic::wait: a futex on Linux) until it is woken. How long it spins adapts to its
// own recent waits (exec/wait.h, SpinBudget): up to spinNanoseconds() (100 us by default) while
// its waits end within that (the other threads are running and finish a few tens of microseconds
// apart: a futex wake-up, ~20 us here, would cost more), and kLeastSpinNanoseconds (5 us) after a
// longer wait (the awaited thread was preempted, on a machine with more runnable threads than
// cores: the waiting thread then gives its core up almost at once, instead of spinning a
// scheduler quantum away at every join). The policy is the program's, not the environment's (no
// variable is read).
#pragma once

#include <cstdint>
#include <type_traits>

namespace veridem::exec
{

/// The longest a waiting thread spins before it blocks, by default [ns].
inline constexpr std::int64_t kSpinNanoseconds = 100'000;

/// The spin of a waiting thread after a wait longer than spinNanoseconds() [ns] (or
/// spinNanoseconds() if that is less).
inline constexpr std::int64_t kLeastSpinNanoseconds = 5'000;

/// Sets the longest a waiting thread spins before it blocks [ns] (0: block at once; at most 1e7).
/// Default: kSpinNanoseconds. Takes effect at the next wait.
void setSpinNanoseconds(std::int64_t ns);

/// The longest spin, as set by setSpinNanoseconds [ns].
std::int64_t spinNanoseconds();

/// The largest thread count setThreads accepts.
inline constexpr int kMaxThreads = 256;

/// The CPUs this process may run on (its affinity mask), at least 1: the default thread count.
int availableCpus();

/// Sets the process-wide thread count of the parallel loops (1 <= n <= kMaxThreads, else
/// std::invalid_argument; n = 1: every loop runs on the calling thread). Must not be called while a run() is
/// in progress. Default: availableCpus().
void setThreads(int n);

/// The thread count a parallel loop started on this thread uses: this thread's override
/// (ThreadCountOverride) if one is set, else the process-wide count.
int threads();

/// Sets the thread count for loops started on the constructing thread for the object's lifetime
/// (e.g. 1 on each case worker of the verification runner, whose cores are taken by the other
/// cases). Restores the previous override on destruction. n as setThreads.
class ThreadCountOverride
{
  public:
    explicit ThreadCountOverride(int n);
    ~ThreadCountOverride();
    ThreadCountOverride(const ThreadCountOverride&) = delete;
    ThreadCountOverride& operator=(const ThreadCountOverride&) = delete;

  private:
    int previous_;
};

/// run() with the body as a function pointer and its context.
void runChunks(int chunks, void (*chunk)(void* context, int c), void* context) noexcept;

/// body(c) for every c in [0, chunks), chunk c on participant c % threads() if it is running
/// (see above); returns when all have returned. Runs every chunk on the calling thread, in order, if
/// threads() is 1, chunks is 1, or the pool is already running a loop (a nested call or a call from a second
/// thread). The body must not throw (an exception ends the program).
template <class Body> void run(int chunks, Body&& body)
{
    if (chunks <= 1 || threads() <= 1)
    {
        for (int c = 0; c < chunks; ++c)
            body(c);
        return;
    }
    using B = std::remove_reference_t<Body>;
    runChunks(
        chunks, [](void* context, int c) { (*static_cast<B*>(context))(c); },
        const_cast<void*>(static_cast<const void*>(&body)));
}

} // namespace veridem::exec
