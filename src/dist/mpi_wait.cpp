#include "dist/mpi_wait.h"

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

namespace veridem::dist
{

static_assert(std::atomic<std::uint32_t>::is_always_lock_free && sizeof(std::atomic<std::uint32_t>) == 4,
              "the bell's futex word is a plain 32-bit word");

NodeBell::NodeBell(MPI_Comm comm)
{
    if (MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node_) != MPI_SUCCESS)
        return;
    int nodeRank = 0, nodeSize = 1;
    MPI_Comm_rank(node_, &nodeRank);
    MPI_Comm_size(node_, &nodeSize);
    if (nodeSize < 2)
        return;
    void* base = nullptr;
    const MPI_Aint bytes = nodeRank == 0 ? MPI_Aint(sizeof(Shared)) : 0;
    if (MPI_Win_allocate_shared(bytes, 1, MPI_INFO_NULL, node_, &base, &window_) != MPI_SUCCESS)
        return;
    MPI_Aint size = 0;
    int unit = 0;
    MPI_Win_shared_query(window_, 0, &size, &unit, &base);
    if (nodeRank == 0)
        new (base) Shared{};
    MPI_Barrier(node_); // (the words exist before any rank rings)
    shared_ = static_cast<Shared*>(base);
}

NodeBell::~NodeBell()
{
    if (window_ != MPI_WIN_NULL)
        MPI_Win_free(&window_);
    if (node_ != MPI_COMM_NULL)
        MPI_Comm_free(&node_);
}

void NodeBell::ring() const
{
    if (!shared_)
        return;
    shared_->rings.fetch_add(1, std::memory_order_seq_cst);
    if (shared_->sleepers.load(std::memory_order_seq_cst) != 0)
        syscall(SYS_futex, &shared_->rings, FUTEX_WAKE, INT32_MAX, nullptr, nullptr, 0);
}

std::uint32_t NodeBell::rings() const
{
    return shared_ ? shared_->rings.load(std::memory_order_seq_cst) : 0;
}

void NodeBell::sleep(std::uint32_t seen, std::int64_t ns) const
{
    if (!shared_)
    {
        std::this_thread::sleep_for(std::chrono::nanoseconds(ns));
        return;
    }
    // The ringer adds to `rings`, then loads `sleepers`; the sleeper adds to `sleepers`, then the
    // kernel compares `rings` with `seen` (all sequentially consistent): one of the two sees the
    // other's write, so no ring is lost.
    shared_->sleepers.fetch_add(1, std::memory_order_seq_cst);
    const timespec timeout{time_t(ns / 1'000'000'000), long(ns % 1'000'000'000)};
    syscall(SYS_futex, &shared_->rings, FUTEX_WAIT, seen, &timeout, nullptr, 0);
    shared_->sleepers.fetch_sub(1, std::memory_order_seq_cst);
}

void waitForRequests(std::span<MPI_Request> requests, const NodeBell& bell, const char* what)
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
    bell.ring();
    std::int64_t sleep = kFirstSleepNanoseconds;
    for (;;)
    {
        // (a clock read is ~20 ns, an MPI_Testall with nothing arrived ~50-100 ns: one read per test)
        const auto spinStart = std::chrono::steady_clock::now();
        while ((std::chrono::steady_clock::now() - spinStart).count() < kSpinNanoseconds)
        {
            if (test())
            {
                bell.ring();
                return;
            }
            exec::relax();
        }
        const std::uint32_t seen = bell.rings();
        if (test())
        {
            bell.ring();
            return;
        }
        bell.sleep(seen, sleep);
        sleep = bell.rings() != seen ? kFirstSleepNanoseconds : std::min(2 * sleep, kLongestSleepNanoseconds);
    }
}

} // namespace veridem::dist
