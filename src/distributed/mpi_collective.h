// The collective operations of distributed/collective.h over MPI (built when CMake finds MPI). Every wait
// is a non-blocking call completed by distributed/mpi_wait.h (spin, then sleep until a partner rings), so
// that a waiting rank does not hold a core the awaited rank needs. Up to kOneRoundRanks ranks, the
// sums, maxima and exchange counts are one round of messages (each rank sends its part to every
// other rank and combines what it receives), so that every message a rank waits for is posted, and
// its bell rung, by the rank that sent it; above, MPI's non-blocking collectives. With more ranks on
// the node than cores (NodeBell::oversubscribed), MPI's blocking calls (distributed/mpi_wait.h says why).
#pragma once

#include "distributed/collective.h"
#include "distributed/mpi_wait.h"

#include <memory>
#include <mpi.h>
#include <vector>

namespace veridem::distributed
{

class MpiCollective final : public Collective
{
  public:
    /// The ranks of `comm` (MPI must be initialised). A collective call (it shares the node's bell,
    /// distributed/mpi_wait.h); destroy it before MPI_Finalize.
    explicit MpiCollective(MPI_Comm comm = MPI_COMM_WORLD);
    ~MpiCollective() override;
    void sum(std::span<std::uint64_t> values) const override;
    void max(std::span<double> values) const override;
    /// sum, max: one round (above: MPI_Iallreduce); the sum is of integers and the maximum exact, so
    /// either gives the same bits in any order. exchange: the counts in one round (above:
    /// MPI_Ialltoall), then exchangeSized: one message per non-empty buffer (MPI_Isend/Irecv).
    Buffers exchange(Buffers outgoing) const override;
    Buffers exchangeSized(Buffers outgoing, std::span<const std::size_t> incomingBytes) const override;
    int rank() const override { return rank_; }
    int size() const override { return size_; }

    /// Rank counts up to which sum, max and the exchange counts are one round of messages (size - 1
    /// sends and receives a rank; above, MPI's collectives, of logarithmic depth).
    static constexpr int kOneRoundRanks = 8;

  private:
    /// One round: sends `count` values of `type` to each other rank b (from send + b * stride) and
    /// receives `count` from each rank a (into received + a * count), then waits.
    void oneRound(const void* send, std::size_t strideBytes, void* received, int count, MPI_Datatype type,
                  const char* what) const;
    /// Waits for `requests`, every other rank its partner (a collective call).
    void waitForAll(MPI_Request& request, const char* what) const;

    MPI_Comm comm_;
    int rank_ = 0, size_ = 1;
    std::unique_ptr<NodeBell> bell_; // where a waiting rank sleeps (distributed/mpi_wait.h)
    std::vector<int> others_;        // every rank but this one
};

} // namespace veridem::distributed
