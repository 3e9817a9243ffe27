#include "distributed/mpi_collective.h"

#include "distributed/mpi_wait.h"

#include <climits>

#include <algorithm>
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
    bell_ = std::make_unique<NodeBell>(comm_);
    for (int r = 0; r < size_; ++r)
        if (r != rank_)
            others_.push_back(r);
}

MpiCollective::~MpiCollective() = default;

void MpiCollective::waitForAll(MPI_Request& request, const char* what) const
{
    waitForRequests({&request, 1}, others_, *bell_, what);
}

void MpiCollective::oneRound(const void* send, std::size_t strideBytes, void* received, int count,
                             MPI_Datatype type, const char* what) const
{
    int typeBytes = 0;
    MPI_Type_size(type, &typeBytes);
    std::vector<MPI_Request> requests(2 * others_.size());
    constexpr int kTag = 8; // (exchangeSized: 7)
    for (std::size_t k = 0; k < others_.size(); ++k)
        check(
            MPI_Irecv(static_cast<char*>(received) + std::size_t(others_[k]) * std::size_t(count * typeBytes),
                      count, type, others_[k], kTag, comm_, &requests[k]),
            what);
    for (std::size_t k = 0; k < others_.size(); ++k)
        check(MPI_Isend(static_cast<const char*>(send) + std::size_t(others_[k]) * strideBytes, count, type,
                        others_[k], kTag, comm_, &requests[others_.size() + k]),
              what);
    waitForRequests(requests, others_, *bell_, what);
}

void MpiCollective::sum(std::span<std::uint64_t> values) const
{
    if (values.empty() || size_ == 1)
        return;
    const int n = static_cast<int>(values.size());
    if (bell_->oversubscribed())
    {
        check(MPI_Allreduce(MPI_IN_PLACE, values.data(), n, MPI_UINT64_T, MPI_SUM, comm_),
              "MPI_Allreduce (sum)");
        return;
    }
    if (size_ > kOneRoundRanks)
    {
        MPI_Request request;
        check(MPI_Iallreduce(MPI_IN_PLACE, values.data(), n, MPI_UINT64_T, MPI_SUM, comm_, &request),
              "MPI_Iallreduce (sum)");
        waitForAll(request, "MPI_Iallreduce (sum)");
        return;
    }
    std::vector<std::uint64_t> received(std::size_t(size_) * values.size());
    oneRound(values.data(), 0, received.data(), n, MPI_UINT64_T, "MPI_Isend/Irecv (sum)");
    for (int a = 0; a < size_; ++a) // (integers: any order gives the same sum, modulo 2^64 as MPI's)
        if (a != rank_)
            for (std::size_t k = 0; k < values.size(); ++k)
                values[k] += received[std::size_t(a) * values.size() + k];
}

void MpiCollective::max(std::span<double> values) const
{
    if (values.empty() || size_ == 1)
        return;
    const int n = static_cast<int>(values.size());
    if (bell_->oversubscribed())
    {
        check(MPI_Allreduce(MPI_IN_PLACE, values.data(), n, MPI_DOUBLE, MPI_MAX, comm_),
              "MPI_Allreduce (max)");
        return;
    }
    if (size_ > kOneRoundRanks)
    {
        MPI_Request request;
        check(MPI_Iallreduce(MPI_IN_PLACE, values.data(), n, MPI_DOUBLE, MPI_MAX, comm_, &request),
              "MPI_Iallreduce (max)");
        waitForAll(request, "MPI_Iallreduce (max)");
        return;
    }
    std::vector<double> received(std::size_t(size_) * values.size());
    oneRound(values.data(), 0, received.data(), n, MPI_DOUBLE, "MPI_Isend/Irecv (max)");
    for (int a = 0; a < size_; ++a)
        if (a != rank_)
            for (std::size_t k = 0; k < values.size(); ++k)
                values[k] = std::max(values[k], received[std::size_t(a) * values.size() + k]);
}

Buffers MpiCollective::exchange(Buffers outgoing) const
{
    if (outgoing.size() != std::size_t(size_))
        throw std::invalid_argument("MPI exchange: " + std::to_string(outgoing.size()) + " buffers for " +
                                    std::to_string(size_) + " ranks");
    std::vector<std::uint64_t> sendCount(size_), receiveCount(size_);
    for (int b = 0; b < size_; ++b)
        sendCount[b] = outgoing[b].size();
    if (bell_->oversubscribed())
        check(MPI_Alltoall(sendCount.data(), 1, MPI_UINT64_T, receiveCount.data(), 1, MPI_UINT64_T, comm_),
              "MPI_Alltoall (exchange counts)");
    else if (size_ > kOneRoundRanks)
    {
        MPI_Request request;
        check(MPI_Ialltoall(sendCount.data(), 1, MPI_UINT64_T, receiveCount.data(), 1, MPI_UINT64_T, comm_,
                            &request),
              "MPI_Ialltoall (exchange counts)");
        waitForAll(request, "MPI_Ialltoall (exchange counts)");
    }
    else
        oneRound(sendCount.data(), sizeof(std::uint64_t), receiveCount.data(), 1, MPI_UINT64_T,
                 "MPI_Isend/Irecv (exchange counts)");
    receiveCount[rank_] = sendCount[rank_];
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
    std::vector<int> partners; // (the ranks this one sends to or receives from)
    std::vector<MPI_Request> requests;
    requests.reserve(2 * std::size_t(size_));
    constexpr int kTag = 7;
    for (int a = 0; a < size_; ++a)
    {
        if (a == rank_ || incomingBytes[a] == 0)
            continue;
        incoming[a].resize(incomingBytes[a]);
        partners.push_back(a);
        requests.emplace_back();
        check(MPI_Irecv(incoming[a].data(), messageSize(incomingBytes[a], a), MPI_BYTE, a, kTag, comm_,
                        &requests.back()),
              "MPI_Irecv (exchange)");
    }
    for (int b = 0; b < size_; ++b)
    {
        if (b == rank_ || outgoing[b].empty())
            continue;
        if (std::find(partners.begin(), partners.end(), b) == partners.end())
            partners.push_back(b);
        requests.emplace_back();
        check(MPI_Isend(outgoing[b].data(), messageSize(outgoing[b].size(), b), MPI_BYTE, b, kTag, comm_,
                        &requests.back()),
              "MPI_Isend (exchange)");
    }
    waitForRequests(requests, partners, *bell_, "MPI_Testall (exchange)");
    incoming[rank_] = std::move(outgoing[rank_]);
    return incoming;
}

} // namespace veridem::distributed
