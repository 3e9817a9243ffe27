#include "dist/mpi_collective.h"

#include <stdexcept>
#include <string>

namespace veridem::dist
{

namespace
{
void check(int code, const char* what)
{
    if (code != MPI_SUCCESS)
        throw std::runtime_error(std::string("MPI: ") + what + " failed (error code " + std::to_string(code) +
                                 ")");
}
} // namespace

MpiCollective::MpiCollective(MPI_Comm comm) : comm_(comm)
{
    check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

void MpiCollective::sum(std::span<std::uint64_t> values) const
{
    if (!values.empty())
        check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_UINT64_T,
                            MPI_SUM, comm_),
              "MPI_Allreduce (sum)");
}

void MpiCollective::max(std::span<double> values) const
{
    if (!values.empty())
        check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX,
                            comm_),
              "MPI_Allreduce (max)");
}

} // namespace veridem::dist
