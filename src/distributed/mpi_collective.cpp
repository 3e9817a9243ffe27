#include "distributed/mpi_collective.h"

#include <climits>

#include <stdexcept>
#include <string>

namespace veridem::distributed
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

Buffers MpiCollective::exchange(Buffers outgoing) const
{
    if (outgoing.size() != std::size_t(size_))
        throw std::invalid_argument("MPI exchange: " + std::to_string(outgoing.size()) + " buffers for " +
                                    std::to_string(size_) + " ranks");
    std::vector<std::uint64_t> sendCount(size_), receiveCount(size_);
    for (int b = 0; b < size_; ++b)
        sendCount[b] = outgoing[b].size();
    check(MPI_Alltoall(sendCount.data(), 1, MPI_UINT64_T, receiveCount.data(), 1, MPI_UINT64_T, comm_),
          "MPI_Alltoall (exchange counts)");
    const std::vector<std::size_t> incomingBytes(receiveCount.begin(), receiveCount.end());
    return exchangeSized(std::move(outgoing), incomingBytes);
}

Buffers MpiCollective::exchangeSized(Buffers outgoing, std::span<const std::size_t> incomingBytes) const
{
    if (outgoing.size() != std::size_t(size_) || incomingBytes.size() != std::size_t(size_))
        throw std::invalid_argument("MPI exchange: " + std::to_string(outgoing.size()) + " buffers and " +
                                    std::to_string(incomingBytes.size()) + " sizes for " +
                                    std::to_string(size_) + " ranks");
    const auto messageSize = [](std::size_t bytes, int rank)
    {
        if (bytes > std::size_t(INT_MAX)) // (MPI counts are ints)
            throw std::runtime_error("MPI exchange: " + std::to_string(bytes) + " bytes with rank " +
                                     std::to_string(rank) + " exceed one message's limit of 2^31 - 1");
        return int(bytes);
    };
    Buffers incoming(size_);
    std::vector<MPI_Request> requests;
    requests.reserve(2 * std::size_t(size_));
    constexpr int kTag = 7;
    for (int a = 0; a < size_; ++a)
    {
        if (a == rank_ || incomingBytes[a] == 0)
            continue;
        incoming[a].resize(incomingBytes[a]);
        requests.emplace_back();
        check(MPI_Irecv(incoming[a].data(), messageSize(incomingBytes[a], a), MPI_BYTE, a, kTag, comm_,
                        &requests.back()),
              "MPI_Irecv (exchange)");
    }
    for (int b = 0; b < size_; ++b)
    {
        if (b == rank_ || outgoing[b].empty())
            continue;
        requests.emplace_back();
        check(MPI_Isend(outgoing[b].data(), messageSize(outgoing[b].size(), b), MPI_BYTE, b, kTag, comm_,
                        &requests.back()),
              "MPI_Isend (exchange)");
    }
    check(MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall (exchange)");
    incoming[rank_] = std::move(outgoing[rank_]);
    return incoming;
}

} // namespace veridem::distributed
