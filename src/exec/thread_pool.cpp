#include "exec/thread_pool.h"

#include "exec/wait.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <sched.h>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace veridem::exec
{

int availableCpus()
{
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0)
        return std::max(1, CPU_COUNT(&set));
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

namespace
{

constexpr std::size_t kCacheLine = 64;

std::atomic<std::int64_t> spin{kSpinNanoseconds}; // setSpinNanoseconds

/// The bounds of a waiter's spin (SpinBudget) [ns].
std::int64_t mostSpin()
{
    return spin.load(std::memory_order_relaxed);
}

std::int64_t leastSpin()
{
    return std::min(kLeastSpinNanoseconds, mostSpin());
}

std::atomic<int> processThreads{0};   // 0: not set yet (availableCpus())
thread_local int overrideThreads = 0; // 0: no override on this thread

/// Workers 1..P-1 of a pool of P participants (the caller of run() is participant 0).
///
/// A job's chunks are grouped in kSlots slots (slot b: chunks b, b + kSlots, ...). The claim
/// word holds the job's generation (high 32 bits) and a bit per slot, set when a participant has
/// claimed it (bits of slots without chunks start set). A participant claims its own slots
/// first (b % P == its index), then any slot still unclaimed: a worker that is late (asleep, or
/// preempted by another process) leaves its slots to the participants that are running, so no
/// one waits for a thread that has not started. A claim succeeds only for the generation the
/// participant saw published, so a late worker never takes a chunk of the next job. The job's
/// function and context are read only after a successful claim: the caller does not return,
/// nor publish the next job, until every slot is completed.
class Pool
{
  public:
    ~Pool() { resize(1); }

    int participants() const { return static_cast<int>(workers_.size()) + 1; }

    /// Stops the workers and starts p - 1 new ones (only between jobs).
    void resize(int p)
    {
        if (p == participants())
            return;
        if (!workers_.empty())
        {
            stop_.store(true, std::memory_order_relaxed);
            publish(0);
            for (std::thread& t : workers_)
                t.join();
            workers_.clear();
            stop_.store(false, std::memory_order_relaxed);
        }
        for (int w = 1; w < p; ++w)
            workers_.emplace_back([this, w, p, seen = generation_.load()] { work(w, p, seen); });
    }

    /// Runs chunk(context, c) for c in [0, chunks) (see the class comment for who runs which).
    void run(int chunks, void (*chunk)(void*, int), void* context)
    {
        chunk_ = chunk;
        context_ = context;
        chunks_ = chunks;
        const std::uint32_t slots = static_cast<std::uint32_t>(std::min(chunks, kSlots));
        completed_.store(0, std::memory_order_relaxed);
        const std::uint32_t g = publish(slots);
        claimAndRun(0, participants(), g);
        std::uint32_t done = completed_.load(std::memory_order_acquire);
        while (done != slots)
            done = waitWhileEqual(completed_, done, callerSleeping_, callerSpin_, leastSpin(), mostSpin());
    }

  private:
    static constexpr int kSlots = 32;

    /// Publishes a job of `slots` slots (the job's fields already written); returns its generation.
    std::uint32_t publish(std::uint32_t slots)
    {
        const std::uint32_t g = generation_.load(std::memory_order_relaxed) + 1;
        const std::uint32_t none = slots >= 32 ? 0u : ~((1u << slots) - 1u); // slots without chunks
        claim_.store((std::uint64_t{g} << 32) | none, std::memory_order_seq_cst);
        generation_.store(g, std::memory_order_seq_cst);
        wakeWaiters(generation_, workersSleeping_);
        return g;
    }

    /// Claims and runs slots of job `g` as participant `index` of `p` until none is left.
    void claimAndRun(int index, int p, std::uint32_t g)
    {
        std::uint32_t own = 0; // this participant's slots
        for (int b = index; b < kSlots; b += p)
            own |= 1u << b;
        std::uint64_t word = claim_.load(std::memory_order_acquire);
        for (;;)
        {
            if (static_cast<std::uint32_t>(word >> 32) != g)
                return; // a later job: this one is complete
            const std::uint32_t free = ~static_cast<std::uint32_t>(word);
            if (free == 0)
                return;
            const int b = std::countr_zero((free & own) != 0 ? free & own : free);
            if (!claim_.compare_exchange_weak(word, word | (std::uint64_t{1} << b), std::memory_order_acq_rel,
                                              std::memory_order_acquire))
                continue;
            for (int c = b; c < chunks_; c += kSlots)
                chunk_(context_, c);
            completed_.fetch_add(1, std::memory_order_seq_cst);
            wakeWaiters(completed_, callerSleeping_);
            word = claim_.load(std::memory_order_acquire);
        }
    }

    /// Worker `index` of a pool of `p` participants, last job seen: `seen`.
    void work(int index, int p, std::uint32_t seen)
    {
        SpinBudget budget;
        for (;;)
        {
            seen = waitWhileEqual(generation_, seen, workersSleeping_, budget, leastSpin(), mostSpin());
            if (stop_.load(std::memory_order_relaxed))
                return;
            claimAndRun(index, p, seen);
        }
    }

    std::vector<std::thread> workers_;
    // The job: written by the caller before it is published, read by a participant after it has
    // claimed a slot of it.
    void (*chunk_)(void*, int) = nullptr;
    void* context_ = nullptr;
    int chunks_ = 0;
    std::atomic<bool> stop_{false}; // (published with the job that ends the workers)
    alignas(kCacheLine) std::atomic<std::uint64_t> claim_{0};
    alignas(kCacheLine) std::atomic<std::uint32_t> generation_{0};
    std::atomic<std::uint32_t> workersSleeping_{0};
    alignas(kCacheLine) std::atomic<std::uint32_t> completed_{0};
    std::atomic<std::uint32_t> callerSleeping_{0};
    SpinBudget callerSpin_; // (of the thread that holds the pool)
};

/// The pool, and a flag held by the thread whose job it runs: a second caller (a nested call,
/// or another thread) runs its loop on its own thread instead of waiting.
struct Shared
{
    std::atomic_flag busy;
    Pool pool;
};

Shared& shared()
{
    static Shared s;
    return s;
}

} // namespace

void setSpinNanoseconds(std::int64_t ns)
{
    if (ns < 0 || ns > 10'000'000)
        throw std::invalid_argument("spin must be from 0 to 1e7 ns, got " + std::to_string(ns));
    spin.store(ns, std::memory_order_relaxed);
}

std::int64_t spinNanoseconds()
{
    return spin.load(std::memory_order_relaxed);
}

void setThreads(int n)
{
    if (n < 1 || n > kMaxThreads)
        throw std::invalid_argument("thread count must be from 1 to " + std::to_string(kMaxThreads) +
                                    ", got " + std::to_string(n));
    processThreads.store(n, std::memory_order_relaxed);
}

int threads()
{
    if (overrideThreads > 0)
        return overrideThreads;
    int n = processThreads.load(std::memory_order_relaxed);
    if (n == 0)
    {
        n = availableCpus();
        int unset = 0;
        if (!processThreads.compare_exchange_strong(unset, n, std::memory_order_relaxed))
            n = unset;
    }
    return n;
}

ThreadCountOverride::ThreadCountOverride(int n) : previous_(overrideThreads)
{
    if (n < 1 || n > kMaxThreads)
        throw std::invalid_argument("thread count must be from 1 to " + std::to_string(kMaxThreads) +
                                    ", got " + std::to_string(n));
    overrideThreads = n;
}

ThreadCountOverride::~ThreadCountOverride()
{
    overrideThreads = previous_;
}

void runChunks(int chunks, void (*chunk)(void*, int), void* context) noexcept
{
    Shared& s = shared();
    if (s.busy.test_and_set(std::memory_order_acquire))
    {
        for (int c = 0; c < chunks; ++c)
            chunk(context, c);
        return;
    }
    s.pool.resize(threads());
    s.pool.run(chunks, chunk, context);
    s.busy.clear(std::memory_order_release);
}

} // namespace veridem::exec
