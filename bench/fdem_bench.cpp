// fdem_bench: throughput of the 2D FEM/DEM engine and the time of the paper's Fig. 1 sweep.
//   fdem_bench            element kernel, contact-bound sliding block, and the dt = 1e-6 s sweep
//   fdem_bench --no-sweep the first two only
//   fdem_bench --block [--threads N] [--steps S] [--cells C]
//                         the jointed block alone: C x C cells (default 224: 100,352 triangles) with
//                         joints on every interior edge, dropped at 2 m/s onto a fixed platen; S steps
//                         (default 60) on N threads (default 1), timed per phase of the step
// Prints element-steps/s (triangles x steps per wall second) and the sweep's wall and CPU time.
#include "bench_args.h"
#include "exec/thread_pool.h"
#include "fdem/mesher.h"
#include "fdem/scenarios.h"
#include "fdem/time_step.h"
#include "fdem/world.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <future>
#include <mutex>
#include <stdexcept>
#include <string>
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

void jointedBlock(int threads, int steps, int cells)
{
    // A 0.5 m square rock block of cells x cells right-pattern cells (2 triangles each), every interior
    // edge a joint (all intact joints are evaluated every step), falling at 2 m/s onto a fixed platen
    // it starts touching, its right edge pulled at 20 m/s: the joints beside that edge open past
    // o_c ~ 2 G_f / f_t within ~2 us and break (each break re-runs the detection in its step). Inside
    // the block every pair of triangles that meet only at a corner is a couple of the contact list,
    // and the compression of the impact makes many of them touch.
    veridem::exec::setThreads(threads);
    WorldSettings s;
    s.gravity = {0, -9.81};
    s.contact.normalPenalty = 1e11; // 10 E
    s.contact.tangentialPenalty = 1e11;
    s.contact.friction = 0.5;
    World world(s);
    Material rock{2500, 1e10, 0.2, 0, StressLaw::FiniteStrain, PlaneModel::Strain};
    rock.fracture.tensileStrength = 3e6;
    rock.fracture.fractureEnergy = 50;
    rock.fracture.shearFractureEnergy = 80;
    rock.fracture.cohesion = 6e6;
    rock.fracture.frictionAngle = 0.5;
    rock.fracture.penalty = 1e11;
    rock.fracture.curve = SofteningCurve::Linear;
    const auto m = world.addMaterial(rock, "rock");
    // The platen's cells are the block's size: the broad phase's cell is the largest triangle's box
    // (broadphase.h), and 5 cm platen cells put ~1000 block triangles in a cell (a detection took
    // ~0.85 s, 6 detections 60 % of 60 steps).
    const double h = 0.5 / cells;
    BodyDefinition platen{"platen",
                          meshRectangle({-0.05, -4 * h}, {0.6, 4 * h}, static_cast<int>(0.6 / h), 4), m};
    platen.fixed = true;
    world.addBody(platen);
    // The stable step from a 4 x 4-cell block of the same cells (the same elements, masses and
    // joints: the same limit), so that the large block is built once, in a world with that step.
    BodyDefinition small{
        "block",
        meshRectangle({0, 0}, {0.5 * 4 / cells, 0.5 * 4 / cells}, 4, 4, DiagonalPattern::Right),
        m,
        {0, -2}};
    small.cracks = true;
    world.addBody(small);
    WorldSettings stepped = s;
    stepped.timeStep = 0.9 * stableTimeStep(world).limit;
    World timed(stepped);
    timed.addMaterial(rock, "rock");
    timed.addBody(platen);
    BodyDefinition block = small;
    block.mesh = meshRectangle({0, 0}, {0.5, 0.5}, cells, cells, DiagonalPattern::Right);
    const auto setupStart = std::chrono::steady_clock::now();
    const auto id = timed.addBody(block);
    timed.prescribeNodes(id, {0.5 - 1e-9, -1}, {1, 1}, {20, -2});
    const double setup = veridem::bench::seconds(setupStart);
    timed.step(); // first detection, slot tables
    const StepTimes before = timed.stepTimes();
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = cpuSeconds();
    for (int i = 0; i < steps; ++i)
        timed.step();
    const double wall = veridem::bench::seconds(start), cpu = cpuSeconds() - cpuStart;
    const double triangles = static_cast<double>(timed.triangles().size());
    std::printf(
        "jointed block    : %zu triangles, %zu nodes, %zu joints (%zu broken), %zu couples, %zu touching "
        "edge contacts, %zu detections; dt = %.3g s; set-up %.2f s\n",
        timed.triangles().size(), timed.nodes().size(), timed.joints().size(), timed.fractureState().broken,
        timed.coupleCount(), timed.frictionDiagnostics().contacts, timed.detections(), stepped.timeStep,
        setup);
    std::printf(
        "  %d threads, %d steps in %.3f s wall (%.3f s CPU): %.4g element-steps/s, %.1f ms per step\n",
        threads, steps, wall, cpu, steps * triangles / wall, 1e3 * wall / steps);
    const StepTimes& t = timed.stepTimes();
    const double phases[6] = {t.elements - before.elements,     t.joints - before.joints,
                              t.nodeForces - before.nodeForces, t.detection - before.detection,
                              t.contacts - before.contacts,     t.integration - before.integration};
    const char* names[6] = {"elements", "joints", "node sums", "detection", "contacts", "integration"};
    double total = 0;
    for (double p : phases)
        total += p;
    for (int i = 0; i < 6; ++i)
        std::printf("  %-12s %8.2f ms per step  %5.1f %%\n", names[i], 1e3 * phases[i] / steps,
                    100 * phases[i] / total);
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
    if (argc > 1 && std::strcmp(argv[1], "--block") == 0)
    {
        int threads = 1, steps = 60, cells = 224;
        try
        {
            for (int i = 2; i < argc; ++i)
            {
                const std::string option = argv[i];
                if (i + 1 >= argc)
                    throw std::runtime_error(option + ": expected a value");
                const std::string value = argv[++i];
                if (option == "--threads")
                    threads = static_cast<int>(veridem::bench::wholeNumber(option, value, 1, 256));
                else if (option == "--steps")
                    steps = static_cast<int>(veridem::bench::wholeNumber(option, value, 1, 1000000));
                else if (option == "--cells")
                    cells = static_cast<int>(veridem::bench::wholeNumber(option, value, 2, 2000));
                else
                    throw std::runtime_error("unknown option '" + option +
                                             "' (expected --threads, --steps, --cells)");
            }
        }
        catch (const std::exception& e)
        {
            std::fprintf(stderr, "fdem_bench: %s\n", e.what());
            return 2;
        }
        jointedBlock(threads, steps, cells);
        return 0;
    }
    const bool doSweep = !(argc > 1 && std::strcmp(argv[1], "--no-sweep") == 0);
    elementKernel();
    slidingBlockStep();
    if (doSweep)
        sweep();
    return 0;
}
