// The collective operations of dist/collective.h over MPI (built when CMake finds MPI). Every wait
// is a non-blocking call completed by dist/mpi_wait.h (spin, then sleep until a rank of the node
// rings), so that a waiting rank does not hold a core the awaited rank needs.
#pragma once

#include "dist/collective.h"
#include "dist/mpi_wait.h"

#include <memory>
#include <mpi.h>

namespace veridem::dist
{

class MpiCollective final : public Collective
{
  public:
    /// The ranks of `comm` (MPI must be initialised). A collective call (it shares the node's bell,
    /// dist/mpi_wait.h); destroy it before MPI_Finalize.
    explicit MpiCollective(MPI_Comm comm = MPI_COMM_WORLD);
    ~MpiCollective() override;
    void sum(std::span<std::uint64_t> values) const override;
    void max(std::span<double> values) const override;
    /// sum, max: MPI_Iallreduce. exchange: the counts by MPI_Ialltoall, then exchangeSized: one message per
    /// non-empty buffer (MPI_Isend/Irecv).
    Buffers exchange(Buffers outgoing) const override;
    Buffers exchangeSized(Buffers outgoing, std::span<const std::size_t> incomingBytes) const override;
    int rank() const override { return rank_; }
    int size() const override { return size_; }

  private:
    MPI_Comm comm_;
    int rank_ = 0, size_ = 1;
    std::unique_ptr<NodeBell> bell_; // where a waiting rank sleeps (dist/mpi_wait.h)
};

} // namespace veridem::dist
