// How a rank waits for MPI requests: it spins briefly, then sleeps on its own bell in shared memory
// (a futex) until a rank it exchanges with rings it or a short timeout ends, so that a rank waiting
// for another does not hold a core that the awaited rank (or other work on the machine) needs, and
// wakes as soon as its partner has posted. With more ranks on the node than cores: MPI's own wait.
//
// OpenMPI's blocking calls (MPI_Wait*, MPI_Allreduce, ...) poll in a loop that never gives the core
// up. On a machine with more runnable processes than cores, a rank waiting for a preempted partner
// then spins its time slice away at every exchange (docs/performance.md, "Ranks on a shared
// machine": 2 ranks ran the 20k bed 3 times slower than one process beside a CPU-bound process).
// The policy (waitForRequests):
//   - first, the rank rings the bells of its partners (it has posted its sends: a sleeping partner
//     should test now);
//   - MPI_Testall in a loop (each call drives MPI's progress) for kSpinNanoseconds: two ranks that
//     both run meet within a few tens of microseconds, and this stage keeps their latency;
//   - then it sleeps on its own bell (FUTEX_WAIT on a word of memory shared by the node's ranks,
//     MPI_Win_allocate_shared; a word per rank, so that a ring wakes only the rank it is for) for
//     kFirstSleepNanoseconds, doubling up to kLongestSleepNanoseconds while nothing rings. A rank
//     woken by an event is placed by the kernel's scheduler ahead of CPU-bound work that kept
//     running (it has run less than its share), so the exchange goes on without waiting for a time
//     slice to end. After a wake-up it spins again, then sleeps again;
//   - once done, it rings its partners again (its messages are through: a partner may wait for
//     their completion).
// Every message a rank waits for is posted by the rank that rings: distributed::MpiCollective's sums,
// maxima and counts are one round of point-to-point messages (MPI's non-blocking collectives
// forward in rounds from inside another rank's test, which rings no one). The timeout bounds what
// a missed event costs (ranks on other nodes ring no bell; a long message moves in pieces, each
// needing its sender's progress).
// With more ranks on the node than online cores (4 ranks on 2 cores), a wait is MPI_Waitall and
// distributed::MpiCollective uses MPI's blocking collectives: OpenMPI then yields the core between tests
// (mpi_yield_when_idle, on when it starts more ranks than cores), handing it to another rank of the
// run, whereas a sleeping rank held up the pieces of the long messages it took part in: 4 ranks on
// 2 cores ran tests/distributed/mpi_step_check in 62-67 s with the bell, 13 s with a loop of MPI_Testall
// and sched_yield, and 8.2-8.3 s as OpenMPI's blocking calls do (docs/performance.md).
// A signal (SIGINT, SIGTERM) ends a sleep early; the wait goes on until the requests are complete,
// and the run stops at its next check of io::stopSignal() (between pieces of advance(), agreed by
// all ranks at the same step), as in one process. The policy is the program's: no variable is read.
#pragma once

#include <atomic>
#include <cstdint>
#include <mpi.h>
#include <span>
#include <vector>

namespace veridem::distributed
{

/// Spinning stage of a wait, and after each wake-up [ns].
inline constexpr std::int64_t kSpinNanoseconds = 50'000;
/// First and longest sleep on the bell [ns].
inline constexpr std::int64_t kFirstSleepNanoseconds = 50'000;
inline constexpr std::int64_t kLongestSleepNanoseconds = 1'000'000;

/// A word per rank of one node, in memory shared by the node's ranks, on which the rank sleeps while
/// it waits and which its partners ring when they post messages to it. Made by all ranks of `comm`
/// together (a collective call); without shared memory (or alone on its node) it rings nothing and
/// a wait sleeps its timeout.
class NodeBell
{
  public:
    explicit NodeBell(MPI_Comm comm);
    ~NodeBell();
    NodeBell(const NodeBell&) = delete;
    NodeBell& operator=(const NodeBell&) = delete;

    /// Wakes rank `rank` of `comm` if it shares this node and sleeps on its bell.
    void ring(int rank) const;
    /// This rank's count of rings (read before the last test, then given to sleep()).
    std::uint32_t rings() const;
    /// Sleeps until this rank's bell has rung since `seen` was read, a signal, or `ns` nanoseconds.
    void sleep(std::uint32_t seen, std::int64_t ns) const;
    /// Whether the node has more ranks than online cores.
    bool oversubscribed() const { return oversubscribed_; }

  private:
    struct alignas(64) Slot // (a cache line each: a ring writes only its rank's line)
    {
        std::atomic<std::uint32_t> rings;    // the futex word
        std::atomic<std::uint32_t> sleeping; // 1 while the rank is inside sleep()
    };
    MPI_Comm node_ = MPI_COMM_NULL;
    MPI_Win window_ = MPI_WIN_NULL;
    Slot* slots_ = nullptr;       // one per rank of the node
    std::vector<int> nodeRankOf_; // rank of comm -> rank of the node, -1 on another node
    int nodeRank_ = 0;
    bool oversubscribed_ = false;
};

/// Waits until every request is complete (as MPI_Waitall, statuses ignored), by the policy above;
/// `partners`: the ranks of the bell's communicator whose messages it waits for or that wait for
/// its messages (their bells are rung). Throws std::runtime_error naming `what` if MPI reports an
/// error.
void waitForRequests(std::span<MPI_Request> requests, std::span<const int> partners, const NodeBell& bell,
                     const char* what);

} // namespace veridem::distributed
