// The collective operations of distributed/collective.h over MPI (built when CMake finds MPI).
#pragma once

#include "distributed/collective.h"

#include <mpi.h>

namespace veridem::distributed
{

class MpiCollective final : public Collective
{
  public:
    /// The ranks of `comm` (MPI must be initialised).
    explicit MpiCollective(MPI_Comm comm = MPI_COMM_WORLD);
    void sum(std::span<std::uint64_t> values) const override;
    void max(std::span<double> values) const override;
    /// exchange: the counts by MPI_Alltoall, then exchangeSized: one message per non-empty
    /// buffer (MPI_Isend/Irecv).
    Buffers exchange(Buffers outgoing) const override;
    Buffers exchangeSized(Buffers outgoing, std::span<const std::size_t> incomingBytes) const override;
    int rank() const override { return rank_; }
    int size() const override { return size_; }

  private:
    MPI_Comm comm_;
    int rank_ = 0, size_ = 1;
};

} // namespace veridem::distributed
