// The pour benchmark (docs/performance.md, "Particles in and out"): a scene with [[insert]] and
// [[outlet]] (default bench/scenes/pour_1e5.toml: 100,000 beads poured into a box, an outlet in a
// corner of the floor) run as `veridem run` runs it, in runs of steps between the flow events,
// timing the steps (dem::advance) and the events (ParticleFlow::apply: the outlets' removals, the
// insertions and the contact-list rebuild that follows) apart. The events' share of the run is
// what insertion and removal add to the step time.
//
//   veridem_pour_bench [--scene TOML] [--threads T] [--steps S]
//
// --steps S stops after S steps (default: the scene's duration). Prints the particle count, the
// particle-steps per second of the steps alone, the events' time against the steps' time, the
// peak RSS per particle at the largest count, and the kinetic energy at the end (the same bits on
// any thread count).
#include "bench_args.h"
#include "dem/particle_changes.h"
#include "dem/world.h"
#include "exec/thread_pool.h"
#include "io/dem_scene.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <sys/resource.h>

using namespace veridem;
using bench::wholeNumber;

namespace
{

struct Options
{
    std::string scene = VERIDEM_POUR_SCENE;
    int threads = 1;
    long long steps = 0; // 0: the scene's duration
};

Options parse(int argc, char** argv)
{
    Options o;
    for (int a = 1; a < argc; ++a)
    {
        const std::string key = argv[a];
        if (a + 1 >= argc)
            throw std::runtime_error(key + ": expected a value (usage: veridem_pour_bench [--scene TOML] "
                                           "[--threads T] [--steps S])");
        const std::string value = argv[++a];
        if (key == "--scene")
            o.scene = value;
        else if (key == "--threads")
            o.threads = static_cast<int>(wholeNumber(key, value, 1, 1024));
        else if (key == "--steps")
            o.steps = wholeNumber(key, value, 1, 1000000000);
        else
            throw std::runtime_error("unknown option '" + key + "' (expected --scene, --threads or --steps)");
    }
    return o;
}

double peakResidentBytes()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) * 1024.0; // Linux: kilobytes
}

int run(const Options& o)
{
    exec::setThreads(o.threads);
    toml::table table;
    try
    {
        table = toml::parse_file(o.scene);
    }
    catch (const toml::parse_error& e)
    {
        throw std::runtime_error(o.scene + ": " + std::string(e.description()));
    }
    io::DemScene scene = io::readDemScene(table, o.scene);
    dem::World& world = scene.world;
    dem::ParticleFlow& flow = scene.flow;
    if (flow.empty())
        throw std::runtime_error(o.scene + ": no [[insert]] or [[outlet]]: nothing to measure");
    const auto total = o.steps > 0 ? static_cast<std::uint64_t>(o.steps)
                                   : static_cast<std::uint64_t>(std::llround(scene.duration / scene.dt));
    using Clock = std::chrono::steady_clock;
    double stepSeconds = 0, flowSeconds = 0, particleSteps = 0;
    std::size_t events = 0, changes = 0, largest = world.particles.size();
    double peakAtLargest = peakResidentBytes();
    for (std::uint64_t s = world.stepCount; s < total;)
    {
        if (s % flow.everySteps == 0)
        {
            const auto t0 = Clock::now();
            changes += flow.apply(world, scene.dt) ? 1 : 0;
            flowSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
            ++events;
            if (world.particles.size() >= largest)
            {
                largest = world.particles.size();
                peakAtLargest = peakResidentBytes();
            }
        }
        const std::uint64_t end = std::min(total, (s / flow.everySteps + 1) * flow.everySteps);
        const auto t0 = Clock::now();
        const std::uint64_t done = dem::advance(world, scene.dt, end - s, scene.maxOverlapFraction);
        stepSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
        particleSteps += double(done) * double(world.particles.size());
        s += done;
        if (s < end)
            throw std::runtime_error("the run stopped at step " + std::to_string(world.stepCount) +
                                     " (not finite or overlap above max_overlap_fraction)");
    }
    dem::compactRetiredParticles(world); // (the count and the energy below: live particles only)
    std::uint64_t inserted = 0, removed = 0;
    for (const dem::Inserter& in : flow.inserters)
        inserted += in.inserted;
    for (const dem::Outlet& out : flow.outlets)
        removed += out.count;
    std::printf("scene %s  threads %d  steps %llu  dt %g s\n", o.scene.c_str(), o.threads,
                static_cast<unsigned long long>(total), scene.dt);
    std::printf("  particles: %llu inserted, %llu removed, %zu at the end, %zu at most\n",
                static_cast<unsigned long long>(inserted), static_cast<unsigned long long>(removed),
                world.particles.size(), largest);
    std::printf("  steps: %.3f s, %.4g particle-steps/s\n", stepSeconds, particleSteps / stepSeconds);
    std::printf("  flow events: %zu (%zu changed the particles), %.3f s = %.2f %% of the steps' time "
                "(%.3g ms an event)\n",
                events, changes, flowSeconds, 100 * flowSeconds / stepSeconds,
                1e3 * flowSeconds / double(std::max<std::size_t>(events, 1)));
    std::printf("  peak RSS %.1f MB when the count was largest = %.0f B/particle\n", peakAtLargest / 1e6,
                peakAtLargest / double(std::max<std::size_t>(largest, 1)));
    std::printf("  kinetic energy at the end %.9e J\n", dem::kineticEnergy(world));
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    try
    {
        return run(parse(argc, argv));
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "veridem_pour_bench: %s\n", e.what());
        return 2;
    }
}
