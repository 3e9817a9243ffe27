// How a rank waits for MPI requests: it spins briefly, then yields its core, then sleeps, so that
// a rank waiting for another does not hold a core that the awaited rank (or other work on the
// machine) needs.
//
// OpenMPI's blocking calls (MPI_Wait*, MPI_Allreduce, ...) poll in a loop that never gives the core
// up. On a machine with more runnable processes than cores, a rank waiting for a preempted partner
// then spins its time slice away at every exchange: 2 ranks beside one other CPU-bound process on
// 2 cores ran a pour 4 times slower than one process (docs/performance.md, "Ranks on a shared
// machine"). The policy (waitForRequests), by the time the wait has lasted:
//   - up to kSpinNanoseconds: MPI_Testall in a loop (each call drives MPI's progress), a pause
//     between tests. Two ranks that both run meet within a few tens of microseconds (the health
//     all-reduce waits 17 us a step on the 20k bed): this stage keeps their latency.
//   - up to kYieldNanoseconds: MPI_Testall, then sched_yield(). On a core with nothing else to run,
//     sched_yield returns at once (the stage is a spin at ~1 us a test); on a core shared with the
//     awaited rank or another process, it gives them the core for their slice.
//   - after: MPI_Testall, then a sleep that doubles from kFirstSleep to kLongestSleep. The core is
//     idle for the scheduler, which can move other work onto it (a long wait: the other rank is
//     writing output, or was preempted on a core the waiting rank cannot reach).
// A rank that sleeps does not progress its messages; the bound on the sleep bounds the latency
// that adds to the partner (the previous design, sleeping after a 5 us spin, made a step-by-step
// run on 2 ranks many times slower: every collective paid a sleep of >= 60 us).
// A signal (SIGINT, SIGTERM) ends a sleep early; the wait goes on until the requests are complete,
// and the run stops at its next check of io::stopSignal() (between pieces of advance(), in every
// rank at the same step), as in one process. The policy is the program's: no variable is read.
#pragma once

#include <cstdint>
#include <span>

#include <mpi.h>

namespace veridem::dist
{

/// Spinning stage of a wait [ns].
inline constexpr std::int64_t kSpinNanoseconds = 50'000;
/// Yielding stage of a wait: until the wait has lasted this long [ns].
inline constexpr std::int64_t kYieldNanoseconds = 2'000'000;
/// First and longest sleep between tests in the sleeping stage [ns].
inline constexpr std::int64_t kFirstSleepNanoseconds = 50'000;
inline constexpr std::int64_t kLongestSleepNanoseconds = 1'000'000;

/// Waits until every request is complete (as MPI_Waitall, statuses ignored), by the policy above.
/// Throws std::runtime_error naming `what` if MPI reports an error.
void waitForRequests(std::span<MPI_Request> requests, const char* what);

} // namespace veridem::dist
