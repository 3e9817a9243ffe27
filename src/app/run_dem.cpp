// `veridem run` for 3D DEM scenes, on the public API (api::Simulation): read (or restore), step
// with output and checkpoints at their times, stop cleanly on a blow-up (keeping the output
// written so far) or on SIGINT/SIGTERM (with a checkpoint), show progress, print a summary.
#include "api/simulation.h"
#include "app/run_scene.h"
#include "core/error.h"
#include "distributed/rank_bonds.h"
#include "exec/thread_pool.h"
#include "io/progress_line.h"
#include "io/run_control.h"

#include <chrono>
#include <cstdio>
#include <string>

namespace veridem::app
{

int runDemScene(const toml::table& table, const RunOptions& options)
{
    const bool severalRanks = options.ranks && options.ranks->size() > 1;
    const bool root = !severalRanks || options.ranks->rank() == 0; // prints
    api::SimulationOptions simulationOptions;
    simulationOptions.outDir = options.outDir;
    simulationOptions.allowUnstableTimeStep = options.allowUnstableTimeStep;
    simulationOptions.strict = options.strict;
    simulationOptions.restartFile = options.restartFile;
    simulationOptions.ranks = options.ranks;
    simulationOptions.rebalanceEvery = options.rebalanceEvery;
    api::Simulation sim = api::Simulation::fromTable(table, options.sceneFile, simulationOptions);
    const std::uint64_t totalSteps = sim.lastStep();
    if (options.stopAtStep && *options.stopAtStep <= sim.step())
        throw InputError("--stop-at-step " + std::to_string(*options.stopAtStep) +
                         " is not after the start step " + std::to_string(sim.step()));
    io::stopOnSignals();

    const auto start = std::chrono::steady_clock::now();
    io::ProgressLine progress(root && options.progress); // (io/progress_line.h)
    const std::uint64_t firstStep = sim.step();
    const std::uint64_t end = options.stopAtStep ? std::min(*options.stopAtStep, totalSteps) : totalSteps;
    // In pieces of about a second, between which the progress line is drawn: advance() asks
    // every ~10-50 ms of stepping whether to pause, for a signal or at the end of the piece.
    while (sim.step() < end)
    {
        try
        {
            const auto pieceStart = std::chrono::steady_clock::now();
            sim.advance(end - sim.step(), nullptr,
                        [&] {
                            return io::stopSignal() != 0 ||
                                   std::chrono::steady_clock::now() - pieceStart > std::chrono::seconds(1);
                        });
        }
        catch (const api::BlowUp& e)
        {
            if (!root)
                return 3;
            if (e.allRanks)
                throw RanksStopped(e.what());
            throw SimulationError(e.what());
        }
        const int signal = io::stopSignal();
        if ((signal && sim.step() < totalSteps) ||
            (options.stopAtStep && sim.step() == *options.stopAtStep && sim.step() < totalSteps))
        {
            if (!sim.checkpointIsCurrent()) // (one due at this very step was written by advance())
                sim.writeCheckpoint();
            sim.close();
            if (!root)
                return signal ? io::kInterruptedBase + signal : 0;
            progress.finish();
            const std::uint64_t s = sim.step();
            std::fprintf(stderr,
                         "veridem: %s at step %llu of %llu (t = %.9g s); checkpoint written; continue with: "
                         "veridem run %s --restart %s --out %s\n",
                         signal ? (std::string("stopped by ") + io::signalName(signal)).c_str() : "stopped",
                         static_cast<unsigned long long>(s), static_cast<unsigned long long>(totalSteps),
                         sim.time(), options.sceneFile.c_str(), sim.checkpointPath().string().c_str(),
                         options.outDir.string().c_str());
            return signal ? io::kInterruptedBase + signal : 0;
        }
        progress.update(sim.step(), totalSteps, sim.time());
    }
    sim.close();
    const std::uint64_t stepsRun = sim.step() - firstStep;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const dem::World& world = sim.world();
    std::uint64_t counts[2] = {severalRanks ? sim.ownedParticles() : world.particles.liveCount(),
                               static_cast<std::uint64_t>(sim.particleSteps())};
    if (severalRanks)
        options.ranks->sum(counts);
    std::optional<dem::BondSet> bonds; // (on several ranks, every rank's: distributed/rank_bonds.h)
    if (world.bonds.enabled)
        bonds = severalRanks ? distributed::gatherBonds(world.bonds, world.particles, sim.ownedParticles(),
                                                        *options.ranks, 0)
                             : world.bonds;
    if (!root)
        return 0;
    progress.finish();
    std::printf("veridem: %llu steps of %.4g s (t = %.6g s), %llu particles, %zu outputs in %s\n",
                static_cast<unsigned long long>(stepsRun), sim.dt(), sim.time(),
                static_cast<unsigned long long>(counts[0]), sim.outputsWritten(),
                options.outDir.string().c_str());
    if (severalRanks)
        std::printf(
            "veridem: wall time %.3f s on %d MPI ranks of up to %d thread(s), %.3g particle-steps/s, %zu "
            "neighbour rebuilds, regions cut %llu times\n",
            wall, options.ranks->size(), exec::threads(), wall > 0 ? double(counts[1]) / wall : 0.0,
            world.neighbors.rebuildCount(), static_cast<unsigned long long>(sim.regionCuts()));
    else
        std::printf("veridem: wall time %.3f s on up to %d thread(s), %.3g particle-steps/s, %zu neighbour "
                    "rebuilds\n",
                    wall, exec::threads(), wall > 0 ? sim.particleSteps() / wall : 0.0,
                    world.neighbors.rebuildCount());
    if (bonds) // (dem/bonds/bond_set.h)
    {
        const dem::BondSet& b = *bonds;
        std::printf("veridem: bonds: %llu formed, %llu broken, %llu dropped with a removed particle, %zu "
                    "intact\n",
                    static_cast<unsigned long long>(b.formed), static_cast<unsigned long long>(b.broken),
                    static_cast<unsigned long long>(b.dropped), b.bonds.size());
        if (b.overstretched > 0)
            std::printf("veridem: warning: %llu intact bonds are stretched beyond %.0f %% of their rest "
                        "length (largest strain %.3g) without breaking: their partners drifted apart (no "
                        "tensile_strength, or one too high for the load)\n",
                        static_cast<unsigned long long>(b.overstretched), 100 * dem::BondSet::kOverstretch,
                        b.maxStrain);
    }
    return 0;
}

} // namespace veridem::app
