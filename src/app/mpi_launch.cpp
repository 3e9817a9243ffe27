#include "app/mpi_launch.h"

#include "core/error.h"

#include <cstdlib>
#include <string>

#if VERIDEM_HAVE_MPI
#include "distributed/mpi_collective.h"

#include <mpi.h>
#endif

namespace veridem::app
{

namespace
{

/// The job size an MPI launcher gave this process (OpenMPI: OMPI_COMM_WORLD_SIZE; MPICH, Intel MPI
/// and other PMI launchers: PMI_SIZE), or 0 if none did.
int launcherSize()
{
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* value = std::getenv(name))
            return std::atoi(value);
    return 0;
}

} // namespace

MpiLaunch::MpiLaunch([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv)
{
    const int size = launcherSize();
    if (size == 0)
        return;
#if VERIDEM_HAVE_MPI
    int provided = 0; // (MPI calls come from the main thread only; the thread pool never calls MPI)
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    initialised_ = true;
    collective_ = std::make_unique<distributed::MpiCollective>(MPI_COMM_WORLD);
#else
    if (size > 1)
        throw InputError("started as one of " + std::to_string(size) +
                         " MPI processes, but this veridem was built without MPI (install libopenmpi-dev "
                         "and configure again): each process would run the whole scene and write the same "
                         "files; run one process, with --threads N for the cores");
#endif
}

MpiLaunch::~MpiLaunch()
{
#if VERIDEM_HAVE_MPI
    collective_.reset();
    if (initialised_)
        MPI_Finalize();
#endif
}

void MpiLaunch::abort(int code) const
{
#if VERIDEM_HAVE_MPI
    if (initialised_)
        MPI_Abort(MPI_COMM_WORLD, code);
#endif
    std::exit(code);
}

} // namespace veridem::app
