// The collective operations the domain decomposition needs, behind an interface, so that the
// decomposition is written once and runs in one process (SerialCollective) or over MPI ranks
// (MpiCollective, dist/mpi_collective.h, built when MPI is found).
//
// Only order-independent reductions are offered: sums of integers and maxima of doubles. A sum of
// doubles over ranks depends on how the values are grouped, so it would give different bits on
// different rank counts; integer sums and maxima do not, which is what lets the decomposition be
// the same bits however the particles are spread over the ranks (dist/bisection.h).
#pragma once

#include <cstdint>
#include <span>

namespace veridem::dist
{

class Collective
{
  public:
    virtual ~Collective() = default;
    /// Replaces each value by its sum over all ranks (exact: integers).
    virtual void sum(std::span<std::uint64_t> values) const = 0;
    /// Replaces each value by its maximum over all ranks.
    virtual void max(std::span<double> values) const = 0;
    virtual int rank() const = 0;
    virtual int size() const = 0;
};

/// One process: every reduction is the identity.
class SerialCollective final : public Collective
{
  public:
    void sum(std::span<std::uint64_t>) const override {}
    void max(std::span<double>) const override {}
    int rank() const override { return 0; }
    int size() const override { return 1; }
};

} // namespace veridem::dist
