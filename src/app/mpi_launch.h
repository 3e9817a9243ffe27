// The MPI job this process belongs to, when an MPI launcher started it (`mpirun -np N veridem run
// SCENE`): MPI is initialised on construction and finalised on destruction. A process started
// otherwise (no OMPI_COMM_WORLD_SIZE or PMI_SIZE in its environment) never touches MPI and runs as
// one process, as does a build without MPI (which refuses to be one of several processes).
#pragma once

#include "distributed/collective.h"

#include <memory>

namespace veridem::app
{

class MpiLaunch
{
  public:
    MpiLaunch(int& argc, char**& argv);
    ~MpiLaunch();
    MpiLaunch(const MpiLaunch&) = delete;
    MpiLaunch& operator=(const MpiLaunch&) = delete;

    /// The ranks of the job, or null when this process runs alone.
    const distributed::Collective* collective() const { return collective_.get(); }
    int rank() const { return collective_ ? collective_->rank() : 0; }
    int size() const { return collective_ ? collective_->size() : 1; }
    /// Ends every rank of the job with `code` (an error found on one rank only: the others would
    /// wait for it in their next collective).
    [[noreturn]] void abort(int code) const;

  private:
    std::unique_ptr<distributed::Collective> collective_;
    bool initialised_ = false;
};

} // namespace veridem::app
