#include "distributed/mpi_wait.h"

#include "exec/wait.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <linux/futex.h>
#include <new>
#include <stdexcept>
#include <string>
#include <sys/syscall.h>
#include <thread>
#include <unistd.h>

namespace veridem::distributed
{

static_assert(std::atomic<std::uint32_t>::is_always_lock_free && sizeof(std::atomic<std::uint32_t>) == 4,
              "the bell's futex word is a plain 32-bit word");

NodeBell::NodeBell(MPI_Comm comm)
{
    int size = 1;
    MPI_Comm_size(comm, &size);
    nodeRankOf_.assign(std::size_t(size), -1);
    if (MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node_) != MPI_SUCCESS)
        return;
    int nodeSize = 1;
    MPI_Comm_rank(node_, &nodeRank_);
    MPI_Comm_size(node_, &nodeSize);
    const long cores = sysconf(_SC_NPROCESSORS_ONLN);
    oversubscribed_ = cores > 0 && nodeSize > cores;
    if (nodeSize < 2)
        return;
    MPI_Group group = MPI_GROUP_NULL, nodeGroup = MPI_GROUP_NULL;
    MPI_Comm_group(comm, &group);
    MPI_Comm_group(node_, &nodeGroup);
    std::vector<int> ranks(std::size_t(size), 0);
    for (int r = 0; r < size; ++r)
        ranks[std::size_t(r)] = r;
    MPI_Group_translate_ranks(group, size, ranks.data(), nodeGroup, nodeRankOf_.data());
    MPI_Group_free(&group);
    MPI_Group_free(&nodeGroup);
    for (int& r : nodeRankOf_)
        if (r == MPI_UNDEFINED)
            r = -1;
    void* base = nullptr;
    const MPI_Aint bytes = nodeRank_ == 0 ? MPI_Aint(nodeSize) * MPI_Aint(sizeof(Slot)) : 0;
    if (MPI_Win_allocate_shared(bytes, 1, MPI_INFO_NULL, node_, &base, &window_) != MPI_SUCCESS)
        return;
    MPI_Aint got = 0;
    int unit = 0;
    MPI_Win_shared_query(window_, 0, &got, &unit, &base);
    if (nodeRank_ == 0)
        for (int r = 0; r < nodeSize; ++r)
            new (static_cast<Slot*>(base) + r) Slot{};
    MPI_Barrier(node_); // (the words exist before any rank rings)
    slots_ = static_cast<Slot*>(base);
}

NodeBell::~NodeBell()
{
    if (window_ != MPI_WIN_NULL)
        MPI_Win_free(&window_);
    if (node_ != MPI_COMM_NULL)
        MPI_Comm_free(&node_);
}

void NodeBell::ring(int rank) const
{
    if (!slots_ || rank < 0 || std::size_t(rank) >= nodeRankOf_.size() || nodeRankOf_[std::size_t(rank)] < 0)
        return;
    Slot& s = slots_[nodeRankOf_[std::size_t(rank)]];
    s.rings.fetch_add(1, std::memory_order_seq_cst);
    if (s.sleeping.load(std::memory_order_seq_cst) != 0)
        syscall(SYS_futex, &s.rings, FUTEX_WAKE, 1, nullptr, nullptr, 0);
}

std::uint32_t NodeBell::rings() const
{
    return slots_ ? slots_[nodeRank_].rings.load(std::memory_order_seq_cst) : 0;
}

void NodeBell::sleep(std::uint32_t seen, std::int64_t ns) const
{
    if (!slots_)
    {
        std::this_thread::sleep_for(std::chrono::nanoseconds(ns));
        return;
    }
    // The ringer adds to `rings`, then loads `sleeping`; the sleeper stores `sleeping`, then the
    // kernel compares `rings` with `seen` (all sequentially consistent): one of the two sees the
    // other's write, so no ring is lost.
    Slot& s = slots_[nodeRank_];
    s.sleeping.store(1, std::memory_order_seq_cst);
    const timespec timeout{time_t(ns / 1'000'000'000), long(ns % 1'000'000'000)};
    syscall(SYS_futex, &s.rings, FUTEX_WAIT, seen, &timeout, nullptr, 0);
    s.sleeping.store(0, std::memory_order_seq_cst);
}

void waitForRequests(std::span<MPI_Request> requests, std::span<const int> partners, const NodeBell& bell,
                     const char* what)
{
    const auto test = [&]
    {
        int done = 0;
        const int code = MPI_Testall(int(requests.size()), requests.data(), &done, MPI_STATUSES_IGNORE);
        if (code != MPI_SUCCESS)
            throw std::runtime_error(std::string("MPI: ") + what + " failed (error code " +
                                     std::to_string(code) + ")");
        return done != 0;
    };
    const auto ringPartners = [&]
    {
        for (const int r : partners)
            bell.ring(r);
    };
    if (bell.oversubscribed())
    {
        // (more ranks than cores: MPI's own wait, which OpenMPI makes yield the core between tests
        // when it starts more ranks than cores, mpi_yield_when_idle)
        const int code = MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
        if (code != MPI_SUCCESS)
            throw std::runtime_error(std::string("MPI: ") + what + " failed (error code " +
                                     std::to_string(code) + ")");
        return;
    }
    ringPartners();
    std::int64_t sleep = kFirstSleepNanoseconds;
    for (;;)
    {
        // (a clock read is ~20 ns, an MPI_Testall with nothing arrived ~50-100 ns: one read per test)
        const auto spinStart = std::chrono::steady_clock::now();
        while ((std::chrono::steady_clock::now() - spinStart).count() < kSpinNanoseconds)
        {
            if (test())
            {
                ringPartners();
                return;
            }
            exec::relax();
        }
        const std::uint32_t seen = bell.rings();
        if (test())
        {
            ringPartners();
            return;
        }
        bell.sleep(seen, sleep);
        sleep = bell.rings() != seen ? kFirstSleepNanoseconds : std::min(2 * sleep, kLongestSleepNanoseconds);
    }
}

} // namespace veridem::distributed
