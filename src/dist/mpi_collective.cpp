#include "dist/mpi_collective.h"

#include "exec/wait.h"

#include <climits>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

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
/// Waits for `requests` to complete without holding a core: MPI_Testall in a loop (each call also
/// drives MPI's progress) for the rank's spin budget, then with sleeps that double from 20 us to
/// kLongestSleep between tests. OpenMPI's blocking calls poll without ever yielding, so a rank
/// waiting for another took the core that rank needed when the machine had other work (2 ranks
/// on 2 busy cores: 4 times slower than one process, docs/performance.md). The budget follows
/// exec::SpinBudget: a wait that ended within kLongestSpin raises it to twice that wait (the
/// partner was running, a little behind), a longer one drops it to kShortestSpin.
void waitAll(std::span<MPI_Request> requests, const char* what)
{
    constexpr std::int64_t kShortestSpin = 5'000, kLongestSpin = 200'000; // [ns]
    constexpr auto kLongestSleep = std::chrono::microseconds(500);
    thread_local exec::SpinBudget budget;
    const auto start = std::chrono::steady_clock::now();
    const auto waited = [&] { return (std::chrono::steady_clock::now() - start).count(); };
    const std::int64_t spin = std::clamp(budget.ns, kShortestSpin, kLongestSpin);
    auto sleep = std::chrono::microseconds(20);
    for (;;)
    {
        int done = 0;
        check(MPI_Testall(int(requests.size()), requests.data(), &done, MPI_STATUSES_IGNORE), what);
        if (done)
            break;
        if (waited() < spin)
            exec::relax();
        else
        {
            std::this_thread::sleep_for(sleep);
            sleep = std::min(2 * sleep, kLongestSleep);
        }
    }
    budget.update(waited(), kShortestSpin, kLongestSpin);
}

} // namespace

MpiCollective::MpiCollective(MPI_Comm comm) : comm_(comm)
{
    check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

void MpiCollective::sum(std::span<std::uint64_t> values) const
{
    if (values.empty())
        return;
    MPI_Request request;
    check(MPI_Iallreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_UINT64_T, MPI_SUM,
                         comm_, &request),
          "MPI_Iallreduce (sum)");
    waitAll({&request, 1}, "MPI_Iallreduce (sum)");
}

void MpiCollective::max(std::span<double> values) const
{
    if (values.empty())
        return;
    MPI_Request request;
    check(MPI_Iallreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX,
                         comm_, &request),
          "MPI_Iallreduce (max)");
    waitAll({&request, 1}, "MPI_Iallreduce (max)");
}

Buffers MpiCollective::exchange(Buffers outgoing) const
{
    if (outgoing.size() != std::size_t(size_))
        throw std::invalid_argument("MPI exchange: " + std::to_string(outgoing.size()) + " buffers for " +
                                    std::to_string(size_) + " ranks");
    std::vector<std::uint64_t> sendCount(size_), receiveCount(size_);
    for (int b = 0; b < size_; ++b)
        sendCount[b] = outgoing[b].size();
    MPI_Request request;
    check(MPI_Ialltoall(sendCount.data(), 1, MPI_UINT64_T, receiveCount.data(), 1, MPI_UINT64_T, comm_,
                        &request),
          "MPI_Ialltoall (exchange counts)");
    waitAll({&request, 1}, "MPI_Ialltoall (exchange counts)");
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
    waitAll(requests, "MPI_Testall (exchange)");
    incoming[rank_] = std::move(outgoing[rank_]);
    return incoming;
}

} // namespace veridem::dist
