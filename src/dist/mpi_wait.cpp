#include "dist/mpi_wait.h"

#include "exec/wait.h"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

namespace veridem::dist
{

void waitForRequests(std::span<MPI_Request> requests, const char* what)
{
    const auto test = [&]
    {
        int done = 0;
        const int code = MPI_Testall(int(requests.size()), requests.data(), &done, MPI_STATUSES_IGNORE);
        if (code != MPI_SUCCESS)
            throw std::runtime_error(std::string("MPI: ") + what + " failed (error code " + std::to_string(code) +
                                     ")");
        return done != 0;
    };
    if (test())
        return;
    const auto start = std::chrono::steady_clock::now();
    const auto waited = [&] { return (std::chrono::steady_clock::now() - start).count(); };
    // (a clock read is ~20 ns, an MPI_Testall with nothing arrived ~50-100 ns: one read per test)
    while (waited() < kSpinNanoseconds)
    {
        exec::relax();
        if (test())
            return;
    }
    while (waited() < kYieldNanoseconds)
    {
        sched_yield();
        if (test())
            return;
    }
    std::int64_t sleep = kFirstSleepNanoseconds;
    for (;;)
    {
        std::this_thread::sleep_for(std::chrono::nanoseconds(sleep));
        if (test())
            return;
        sleep = std::min(2 * sleep, kLongestSleepNanoseconds);
    }
}

} // namespace veridem::dist
