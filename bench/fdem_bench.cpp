// fdem_bench: throughput of the 2D FEM/DEM engine and the time of the paper's Fig. 1 sweep.
//   fdem_bench            element kernel, contact-bound sliding block, and the dt = 1e-6 s sweep
//   fdem_bench --no-sweep the first two only
// Prints element-steps/s (triangles x steps per wall second) and the sweep's wall and CPU time.
#include "fdem/mesher.h"
#include "fdem/scenarios.h"
#include "fdem/world.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <future>
#include <mutex>
#include <vector>

using namespace veridem::fdem;

namespace
{

double seconds(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double cpuSeconds()
{
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

void elementKernel()
{
    // A free 100 x 100 block (20000 triangles) in free fall: element forces + integration only.
    WorldSettings s;
    s.timeStep = 1e-7;
    s.contact.normalPenalty = 1e10;
    World world(s);
    const auto m = world.addMaterial({2650, 1e9, 0.25, 100, StressLaw::FiniteStrain, PlaneModel::Strain});
    world.addBody({"block", meshRectangle({0, 0}, {0.5, 0.5}, 100, 100), m, {1, 0}, false});
    world.step(); // first detection
    const int steps = 300;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i)
        world.step();
    const double wall = seconds(start);
    std::printf("element kernel   : %zu triangles, %d steps in %.3f s: %.3g element-steps/s (%.1f ns per "
                "element-step)\n",
                world.triangles().size(), steps, wall,
                steps * static_cast<double>(world.triangles().size()) / wall,
                1e9 * wall / (steps * static_cast<double>(world.triangles().size())));
}

void slidingBlockStep()
{
    SlidingBlockSetup s;
    s.velocity = 2;
    World world = makeSlidingBlockWorld(s);
    world.setBodyVelocity(1, {s.velocity, 0});
    const int steps = 200000;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i)
        world.step();
    const double wall = seconds(start);
    std::printf("sliding block    : 32 block triangles, %zu couples, %d steps in %.3f s: %.2f us per step, "
                "%.0f ns per "
                "block element-step (contact included)\n",
                world.coupleCount(), steps, wall, 1e6 * wall / steps, 1e9 * wall / (steps * 32.0));
}

void sweep()
{
    const std::vector<double> velocities{0.5, 1, 2, 3, 4, 5, 6};
    std::vector<SlidingBlockResult> results(velocities.size());
    std::size_t next = 0;
    std::mutex lock;
    const auto worker = [&]()
    {
        for (;;)
        {
            std::size_t i;
            {
                std::lock_guard<std::mutex> guard(lock);
                if (next == velocities.size())
                    return;
                i = velocities.size() - 1 - next++;
            }
            SlidingBlockSetup s;
            s.velocity = velocities[i];
            s.timeStep = 1e-6;
            results[i] = runSlidingBlock(s);
        }
    };
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = cpuSeconds();
    auto other = std::async(std::launch::async, worker);
    worker();
    other.get();
    const double wall = seconds(start), cpu = cpuSeconds() - cpuStart;
    std::uint64_t steps = 0;
    for (std::size_t i = 0; i < velocities.size(); ++i)
    {
        steps += results[i].steps;
        const double theory = velocities[i] * velocities[i] / (2 * 0.5 * 9.81);
        std::printf("  v = %.1f m/s: L = %.7f m, theory %.7f m, error %+.2e, %llu steps, %.2f s\n",
                    velocities[i], results[i].stopDistance, theory, results[i].stopDistance / theory - 1,
                    static_cast<unsigned long long>(results[i].steps), results[i].wallSeconds);
    }
    std::printf(
        "Fig. 1 sweep     : 7 runs at dt = 1e-6 s on 2 threads: %.2f s wall, %.2f s CPU, %llu steps, %.2f us "
        "CPU per step\n",
        wall, cpu, static_cast<unsigned long long>(steps), 1e6 * cpu / static_cast<double>(steps));
}

} // namespace

int main(int argc, char** argv)
{
    const bool doSweep = !(argc > 1 && std::strcmp(argv[1], "--no-sweep") == 0);
    elementKernel();
    slidingBlockStep();
    if (doSweep)
        sweep();
    return 0;
}
