// How a rank waits for MPI requests: it spins briefly, then sleeps until a rank of its node rings
// a bell in shared memory (a futex) or a short timeout ends, so that a rank waiting for another
// does not hold a core that the awaited rank (or other work on the machine) needs, and wakes as
// soon as the awaited rank has posted its part.
//
// OpenMPI's blocking calls (MPI_Wait*, MPI_Allreduce, ...) poll in a loop that never gives the core
// up. On a machine with more runnable processes than cores, a rank waiting for a preempted partner
// then spins its time slice away at every exchange (docs/performance.md, "Ranks on a shared
// machine": 2 ranks ran the 20k bed 3 times slower than one process). The policy
// (waitForRequests):
//   - first, the rank rings its node's bell (it has posted its sends or its part of a collective:
//     a sleeping peer should test now);
//   - MPI_Testall in a loop (each call drives MPI's progress) for kSpinNanoseconds: two ranks that
//     both run meet within a few tens of microseconds (the health all-reduce waits 17 us a step on
//     the 20k bed), and this stage keeps their latency;
//   - then it sleeps on the bell (FUTEX_WAIT on a word of memory shared by the node's ranks,
//     MPI_Win_allocate_shared) for kFirstSleepNanoseconds, doubling up to kLongestSleepNanoseconds
//     while nothing rings. A peer that posts rings the bell and wakes it at once: a rank woken by
//     an event is placed by the kernel's scheduler ahead of the CPU-bound work that kept running
//     (it has run less than its share), so the exchange goes on without waiting for a time slice
//     to end. After a wake-up it spins again for kSpinNanoseconds, then sleeps again.
//   - once done, it rings again (its messages are through: a peer may wait for their completion).
// The timeout bounds what a missed event costs (ranks on other nodes ring no bell, and a rank whose
// send needs its partner's progress sleeps at most that long). A yielding stage (sched_yield
// between tests for 2 ms before sleeping, no bell) was measured first: it keeps the rank runnable,
// and under load the waiting rank then waited out other processes' time slices: 2 ranks at 0.32x
// one process on the 20k bed beside a CPU-bound process, against 1.18-1.28x with the bell
// (bench/results/2026-12-07-cpp-2core-ranks-under-load.txt).
// A signal (SIGINT, SIGTERM) ends a sleep early; the wait goes on until the requests are complete,
// and the run stops at its next check of io::stopSignal() (between pieces of advance(), agreed by
// all ranks at the same step), as in one process. The policy is the program's: no variable is read.
#pragma once

#include <atomic>
#include <cstdint>
#include <mpi.h>
#include <span>

namespace veridem::dist
{

/// Spinning stage of a wait, and after each wake-up [ns].
inline constexpr std::int64_t kSpinNanoseconds = 50'000;
/// First and longest sleep on the bell [ns].
inline constexpr std::int64_t kFirstSleepNanoseconds = 50'000;
inline constexpr std::int64_t kLongestSleepNanoseconds = 1'000'000;

/// A word of memory shared by the ranks of one node, on which a waiting rank sleeps and which every
/// rank rings when it posts messages. Made by all ranks of `comm` together (a collective call);
/// without shared memory (or alone on its node) it rings nothing and a wait sleeps its timeout.
class NodeBell
{
  public:
    explicit NodeBell(MPI_Comm comm);
    ~NodeBell();
    NodeBell(const NodeBell&) = delete;
    NodeBell& operator=(const NodeBell&) = delete;

    /// Wakes every rank of the node sleeping on the bell.
    void ring() const;
    /// The bell's count of rings (read before the last test, then given to sleep()).
    std::uint32_t rings() const;
    /// Sleeps until the bell has rung since `seen` was read, a signal, or `ns` nanoseconds.
    void sleep(std::uint32_t seen, std::int64_t ns) const;

  private:
    struct Shared
    {
        std::atomic<std::uint32_t> rings;    // the futex word
        std::atomic<std::uint32_t> sleepers; // ranks of the node inside sleep()
    };
    MPI_Comm node_ = MPI_COMM_NULL;
    MPI_Win window_ = MPI_WIN_NULL;
    Shared* shared_ = nullptr;
};

/// Waits until every request is complete (as MPI_Waitall, statuses ignored), by the policy above.
/// Throws std::runtime_error naming `what` if MPI reports an error.
void waitForRequests(std::span<MPI_Request> requests, const NodeBell& bell, const char* what);

} // namespace veridem::dist
