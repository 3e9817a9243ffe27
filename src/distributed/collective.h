// The collective operations the domain decomposition needs, behind an interface, so that the
// decomposition is written once and runs in one process (SerialCollective) or over MPI ranks
// (MpiCollective, distributed/mpi_collective.h, built when MPI is found).
//
// Only order-independent reductions are offered: sums of integers and maxima of doubles. A sum of
// doubles over ranks depends on how the values are grouped, so it would give different bits on
// different rank counts; integer sums and maxima do not, which is what lets the decomposition be
// the same bits however the particles are spread over the ranks (distributed/bisection.h).
//
// Particles and their ghosts move between ranks as bytes (exchange: each rank's buffer for each
// other rank; distributed/halo.h packs and unpacks them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace veridem::distributed
{

/// One byte buffer per rank (exchange).
using Buffers = std::vector<std::vector<std::byte>>;

class Collective
{
  public:
    virtual ~Collective() = default;
    /// Replaces each value by its sum over all ranks (exact: integers).
    virtual void sum(std::span<std::uint64_t> values) const = 0;
    /// Replaces each value by its maximum over all ranks.
    virtual void max(std::span<double> values) const = 0;
    /// Sends outgoing[b] to rank b (one buffer per rank; outgoing[rank()] stays here) and
    /// returns incoming[a], the bytes rank a sent this one. Collective: every rank calls it. The
    /// bytes are copied as they are (the ranks share one byte order and number format).
    virtual Buffers exchange(Buffers outgoing) const = 0;
    /// exchange() when each rank knows how many bytes it receives from each (incomingBytes[a]
    /// from rank a; the ghost exchanges of a step): no exchange of the counts, a message only
    /// between ranks that have bytes for each other.
    virtual Buffers exchangeSized(Buffers outgoing, std::span<const std::size_t> incomingBytes) const = 0;
    virtual int rank() const = 0;
    virtual int size() const = 0;
};

/// One process: every reduction is the identity.
class SerialCollective final : public Collective
{
  public:
    void sum(std::span<std::uint64_t>) const override {}
    void max(std::span<double>) const override {}
    Buffers exchange(Buffers outgoing) const override { return outgoing; }
    Buffers exchangeSized(Buffers outgoing, std::span<const std::size_t>) const override { return outgoing; }
    int rank() const override { return 0; }
    int size() const override { return 1; }
};

} // namespace veridem::distributed
