// The cost of one flow event against the bed's size (docs/performance.md, "Particles in and
// out"): in a bed of N spheres (r 0.9-1.1 mm on a cubic lattice of pitch 2.2 mm, 50 x 50 a layer,
// in a box of five plane walls, no gravity, so nothing moves between events), the time of
//   - an insertion event of K spheres just above the bed (ParticleFlow::apply, 5 events: the
//     first one bins the particles on the insertion grid, the later ones reuse it);
//   - the rebuild of the contact lists that insertion would cost with a rebuild
//     (rebuildAfterParticleChange), for comparison;
//   - a removal event of K spheres of the bottom layer (an outlet, ParticleFlow::apply: the
//     particles retired, dem/particle_changes.h), against the same removal made at once on a copy
//     of the world (removeParticles and rebuildAfterParticleChange: what an event cost before
//     retirement);
//   - the steps after it (velocity Verlet over the bed, retired particles in it; the mean of 10)
//     against the copy's, and the next rebuild of the lists (which removes the retired particles from the
//     store) against a rebuild of the copy.
//
//   veridem_flow_event_bench [--particles N] [--count K] [--threads T]
//
// N defaults to 1e5, K to 1000. Times are wall-clock on the given threads (default 1), and, for
// the removal part, also the calling thread's CPU time (one thread: the machine may be shared).
#include "bench_args.h"
#include "dem/particle_changes.h"
#include "dem/particle_flow.h"
#include "dem/world.h"
#include "exec/thread_pool.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <time.h>
#include <vector>

using namespace veridem;
using bench::seconds;
using bench::wholeNumber;

namespace
{

/// Wall-clock and calling-thread CPU seconds between laps.
class Timer
{
  public:
    struct Lap
    {
        double wall, cpu;
    };
    Timer() : wall_(std::chrono::steady_clock::now()), cpu_(threadCpu()) {}
    Lap lap()
    {
        const double cpu = threadCpu();
        const Lap l{seconds(wall_), cpu - cpu_};
        wall_ = std::chrono::steady_clock::now();
        cpu_ = threadCpu();
        return l;
    }

  private:
    static double threadCpu()
    {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
    }
    std::chrono::steady_clock::time_point wall_;
    double cpu_;
};

dem::Wall plane(const char* name, const Vec3& point, const Vec3& normal)
{
    dem::Wall w;
    w.name = name;
    w.shape = dem::PlaneShape{point, normal};
    return w;
}

int run(std::size_t n, std::size_t k, int threads)
{
    exec::setThreads(threads);
    constexpr std::size_t kSide = 50;       // spheres along x and y
    constexpr Real kPitch = 2.2e-3;         // [m]
    const Real side = Real(kSide) * kPitch; // [m]
    const std::size_t layers = (n + kSide * kSide - 1) / (kSide * kSide);
    dem::World world;
    dem::Material glass;
    glass.name = "glass";
    glass.density = 2500;
    glass.normalStiffness = 1000;
    glass.restitution = 0.5;
    glass.friction = 0.5;
    world.addMaterial(glass);
    world.gravity = {0, 0, 0};
    world.neighbors.skin = 5e-4;
    world.walls = {plane("floor", {0, 0, 0}, {0, 0, 1}), plane("west", {0, 0, 0}, {1, 0, 0}),
                   plane("east", {side, 0, 0}, {-1, 0, 0}), plane("south", {0, 0, 0}, {0, 1, 0}),
                   plane("north", {0, side, 0}, {0, -1, 0})};
    dem::Random random(7);
    world.particles.reserve(n + 6 * k);
    for (std::size_t i = 0; i < n; ++i)
    {
        const std::size_t x = i % kSide, y = (i / kSide) % kSide, z = i / (kSide * kSide);
        const Real r = random.uniform(0.9e-3, 1.1e-3);
        world.particles.add({(Real(x) + 0.5) * kPitch, (Real(y) + 0.5) * kPitch, (Real(z) + 0.5) * kPitch},
                            {}, {}, r, 2500, 0);
    }
    auto start = std::chrono::steady_clock::now();
    dem::prepare(world);
    const double prepareSeconds = seconds(start);
    const Real top = (Real(layers) - 0.5) * kPitch + 1.1e-3; // the top of the highest spheres [m]

    dem::ParticleFlow flow;
    dem::Inserter in;
    in.name = "above";
    in.region.kind = dem::FlowRegion::Kind::Box;
    in.region.min = {0, 0, top + 0.5e-3}; // within the pair search of the top layer
    in.region.max = {side, side, top + 0.5e-3 + 0.03};
    in.mode = dem::Inserter::Mode::Rate;
    in.rate = Real(k) / 1e-3; // k an event, one event a millisecond
    in.from = 0;
    in.until = 1;
    in.radius.kind = dem::RadiusDistribution::Kind::Uniform;
    in.radius.min = 0.9e-3;
    in.radius.max = 1.1e-3;
    in.materials = {0};
    in.materialCumulative = {1};
    in.random = dem::Random(11);
    flow.inserters.push_back(in);
    double insertSeconds[5] = {};
    const std::size_t rebuilds = world.neighbors.rebuildCount();
    for (int e = 0; e < 5; ++e)
    {
        world.time = 1e-3 * Real(e + 1);
        start = std::chrono::steady_clock::now();
        flow.apply(world, 1e-5);
        insertSeconds[e] = seconds(start);
    }
    if (world.neighbors.rebuildCount() != rebuilds)
        std::printf("  (the insertion events rebuilt the contact lists)\n");
    const std::size_t inserted = world.particles.size() - n;
    start = std::chrono::steady_clock::now();
    dem::rebuildAfterParticleChange(world);
    const double rebuildSeconds = seconds(start);

    dem::ParticleFlow out;
    dem::Outlet corner;
    corner.region.kind = dem::FlowRegion::Kind::Box;
    const Real width = Real(std::max<std::size_t>(1, k / kSide)) * kPitch;
    corner.region.min = {-1, -1, -1};
    corner.region.max = {width, side, kPitch}; // the bottom layer's first k / 50 rows
    out.outlets.push_back(corner);
    std::vector<std::uint32_t> doomed; // the outlet's particles, for the removal at once
    for (std::size_t i = 0; i < world.particles.size(); ++i)
        if (corner.region.contains(world.particles.position[i]))
            doomed.push_back(static_cast<std::uint32_t>(i));
    dem::World atOnce = world;
    Timer timer;
    out.apply(world, 1e-5);
    const Timer::Lap retire = timer.lap();
    dem::removeParticles(atOnce, doomed);
    dem::rebuildAfterParticleChange(atOnce);
    const Timer::Lap remove = timer.lap();
    Timer::Lap stepRetired{0, 0}, stepAtOnce{0, 0}; // (mean of kSteps steps, alternated)
    constexpr int kSteps = 10;
    for (int s = 0; s < kSteps; ++s)
    {
        dem::step(world, 1e-5);
        const Timer::Lap a = timer.lap();
        dem::step(atOnce, 1e-5);
        const Timer::Lap b = timer.lap();
        stepRetired = {stepRetired.wall + a.wall / kSteps, stepRetired.cpu + a.cpu / kSteps};
        stepAtOnce = {stepAtOnce.wall + b.wall / kSteps, stepAtOnce.cpu + b.cpu / kSteps};
    }
    dem::rebuildAfterParticleChange(world); // (the rebuild the step makes: the retired leave)
    const Timer::Lap compact = timer.lap();
    dem::rebuildAfterParticleChange(atOnce);
    const Timer::Lap rebuild = timer.lap();
    if (world.particles.size() != atOnce.particles.size())
        throw std::runtime_error("the retired particles did not leave the store");

    std::printf("N %zu  K %zu  threads %d  (prepare %.3f s)\n", n, k, threads, prepareSeconds);
    std::printf("  insertion events: %zu inserted; first %.3f ms (bins the bed), then", inserted,
                1e3 * insertSeconds[0]);
    for (int e = 1; e < 5; ++e)
        std::printf(" %.3f", 1e3 * insertSeconds[e]);
    std::printf(" ms\n");
    std::printf("  a rebuild of the contact lists: %.3f ms\n", 1e3 * rebuildSeconds);
    std::printf("  removal event: %llu removed; ms wall (thread CPU):\n",
                static_cast<unsigned long long>(out.outlets[0].count));
    std::printf("    retired %.3f (%.3f), at once %.3f (%.3f)\n", 1e3 * retire.wall, 1e3 * retire.cpu,
                1e3 * remove.wall, 1e3 * remove.cpu);
    std::printf("    a step after (mean of 10): retired %.3f (%.3f), at once %.3f (%.3f)\n",
                1e3 * stepRetired.wall, 1e3 * stepRetired.cpu, 1e3 * stepAtOnce.wall, 1e3 * stepAtOnce.cpu);
    std::printf("    the next rebuild: removing the retired %.3f (%.3f), plain %.3f (%.3f)\n",
                1e3 * compact.wall, 1e3 * compact.cpu, 1e3 * rebuild.wall, 1e3 * rebuild.cpu);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    try
    {
        long long n = 100000, k = 1000, threads = 1;
        for (int a = 1; a < argc; ++a)
        {
            const std::string key = argv[a];
            if (a + 1 >= argc)
                throw std::runtime_error(key + ": expected a value (usage: veridem_flow_event_bench "
                                               "[--particles N] [--count K] [--threads T])");
            const std::string value = argv[++a];
            if (key == "--particles")
                n = wholeNumber(key, value, 1, 100000000);
            else if (key == "--count")
                k = wholeNumber(key, value, 1, 10000000);
            else if (key == "--threads")
                threads = wholeNumber(key, value, 1, 1024);
            else
                throw std::runtime_error("unknown option '" + key +
                                         "' (expected --particles, --count or --threads)");
        }
        return run(static_cast<std::size_t>(n), static_cast<std::size_t>(k), static_cast<int>(threads));
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "veridem_flow_event_bench: %s\n", e.what());
        return 1;
    }
}
