// `veridem run` for 3D DEM scenes: read, check the time step (or restore a checkpoint), step with
// output and checkpoints between steps, stop cleanly on a blow-up (keeping the output written so
// far) or on SIGINT/SIGTERM (with a checkpoint), print a summary.
#include "app/rolling_note.h"
#include "app/run_scene.h"
#include "app/silenced_stream.h"
#include "app/time_step_note.h"
#include "core/error.h"
#include "dem/time_step.h"
#include "dist/rank_flow.h"
#include "dist/rank_gather.h"
#include "dist/rank_step.h"
#include "dist/rank_sums.h"
#include "exec/thread_pool.h"
#include "io/contact_output.h"
#include "io/dem_checkpoint.h"
#include "io/dem_scene.h"
#include "io/outlet_output.h"
#include "io/particle_flow_keys.h"
#include "io/particle_output.h"
#include "io/plausibility.h"
#include "io/progress_line.h"
#include "io/region_output.h"
#include "io/run_control.h"
#include "io/thermo_output.h"
#include "io/wall_output.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>

namespace veridem::app
{

namespace
{

void checkTimeStep(const io::DemScene& scene, const RunOptions& options, bool speak)
{
    const dem::TimeStepEstimate estimate =
        scene.flow.inserters.empty()
            ? dem::estimateTimeStep(scene.world, scene.characteristicSpeed)
            : dem::estimateTimeStep(io::timeStepProbe(scene.world, scene.flow), scene.characteristicSpeed);
    if (speak) // (app/time_step_note.h)
        std::fprintf(
            stderr, "%s\n",
            timeStepNote(scene.dt, estimate, scene.world.particles.size(), scene.world.walls.size()).c_str());
    if (scene.dt > estimate.critical)
    {
        std::ostringstream s;
        s << options.sceneFile << ": [simulation] dt = " << scene.dt << " s exceeds the stability limit "
          << estimate.critical << " s (" << estimate.limitedBy << "); use dt <= " << estimate.recommended
          << " s (tc/50)";
        if (!options.allowUnstableTimeStep)
            throw InputError(s.str() + ", or --force-dt to run anyway");
        if (speak)
            std::fprintf(stderr, "veridem: warning: %s; running anyway (--force-dt)\n", s.str().c_str());
    }
    else if (speak && scene.dt > estimate.contactTime / 20)
        std::fprintf(
            stderr,
            "veridem: warning: dt is more than tc/20: contacts are resolved by fewer than 20 steps\n");
}

} // namespace

int runDemScene(const toml::table& table, const RunOptions& options)
{
    const bool severalRanks = options.ranks && options.ranks->size() > 1;
    const bool root = !severalRanks || options.ranks->rank() == 0; // prints and writes the files
    io::DemScene scene = [&]
    {
        const SilencedStream quiet(stderr,
                                   !root); // (every rank reads the scene; the first prints its warnings)
        return io::readDemScene(table, options.sceneFile);
    }();
    dem::World& world = scene.world;
    io::reportPlausibility(scene, options.sceneFile, options.strict, root); // (io/plausibility.h)
    checkTimeStep(scene, options, root);
    if (root)
        printRollingFrictionNote(world); // (app/rolling_note.h)
    const std::uint64_t sceneHash = io::sceneFileHash(options.sceneFile);

    const auto totalSteps = static_cast<std::uint64_t>(std::llround(scene.duration / scene.dt));
    const auto outputEvery = std::max<std::uint64_t>(1, std::llround(scene.outputInterval / scene.dt));
    const std::uint64_t checkpointEvery =
        scene.checkpointInterval > 0
            ? std::max<std::uint64_t>(1, std::llround(scene.checkpointInterval / scene.dt))
            : 0;
    std::optional<io::ParticleRecorder::Resume> resume;
    std::optional<std::uint64_t> thermoBytes, regionBytes, wallBytes;
    const io::MeasurementOptions& measure = scene.measurements;
    dem::EnergyLedger ledger; // with `[output] energy = true`: world.observer
    // On several ranks each books its share (energy_ledger.h); the files get their sum.
    dem::EnergyLedger ledgerTotals;
    dem::EnergyLedgerState* const ledgerState = measure.energy ? &ledger.state : nullptr;
    // particles.csv, thermo.csv, region.csv (if measured), walls.csv (if there are walls),
    // outlets.csv (if there are outlets), in this order in the checkpoint
    const bool wallLoads = !world.walls.empty();
    dem::ParticleFlow& flow = scene.flow;
    const bool outlets = !flow.outlets.empty();
    const std::size_t outputFiles =
        2 + std::size_t(measure.region) + std::size_t(wallLoads) + std::size_t(outlets);
    std::optional<std::uint64_t> outletBytes;
    if (!options.restartFile.empty())
    {
        const io::CheckpointOutputs saved =
            io::readDemCheckpoint(options.restartFile, world, sceneHash, ledgerState, &flow);
        if (saved.fileBytes.size() != outputFiles)
            throw InputError("checkpoint '" + options.restartFile + "' is corrupt: it records " +
                             std::to_string(saved.fileBytes.size()) + " output files, this run has " +
                             std::to_string(outputFiles));
        resume = io::ParticleRecorder::Resume{saved.frameTimes, saved.fileBytes[0]};
        thermoBytes = saved.fileBytes[1];
        if (measure.region)
            regionBytes = saved.fileBytes[2];
        if (wallLoads)
            wallBytes = saved.fileBytes[2 + std::size_t(measure.region)];
        if (outlets)
            outletBytes = saved.fileBytes.back();
        if (world.stepCount > totalSteps)
            throw InputError("checkpoint '" + options.restartFile + "' is at step " +
                             std::to_string(world.stepCount) + ", after the scene's last step " +
                             std::to_string(totalSteps));
        if (root)
            std::fprintf(stderr, "veridem: restarting from '%s' at step %llu (t = %.9g s)\n",
                         options.restartFile.c_str(), static_cast<unsigned long long>(world.stepCount),
                         world.time);
    }
    else if (!severalRanks) // (on several ranks, each prepares its part: RankStep::distribute)
    {
        dem::prepare(world);
        if (!flow.empty())
            flow.apply(world, scene.dt); // (step 0 is a flow step)
    }
    // Several ranks: each keeps its region's particles and their ghosts (dist/rank_step.h).
    std::optional<dist::RankStep> rankStep;
    if (severalRanks)
    {
        rankStep.emplace(*options.ranks, options.rebalanceEvery);
        rankStep->distribute(world);
        if (!resume && !flow.empty())
            dist::applyFlow(flow, world, *rankStep, scene.dt); // (step 0 is a flow step)
        if (resume) // (the checkpoint's totals are counted once, by the first rank)
        {
            dist::countOnFirstRank(flow.outlets, *options.ranks);
            if (!root)
                dem::forEachAmount(ledger.state, [](Real& a) { a = 0; });
        }
    }
    world.wallContacts.setRecordLoads(wallLoads);
    if (options.stopAtStep && *options.stopAtStep <= world.stepCount)
        throw InputError("--stop-at-step " + std::to_string(*options.stopAtStep) +
                         " is not after the start step " + std::to_string(world.stepCount));

    if (measure.energy)
    {
        ledger.start(world); // (a restored ledger keeps its state)
        world.observer = &ledger;
    }

    // The files are written by the first rank only, from the whole world gathered (dist/rank_gather.h).
    std::optional<io::ParticleRecorder> recorder;
    std::optional<io::ThermoRecorder> thermo;
    std::optional<io::ContactRecorder> contacts;
    std::optional<io::RegionRecorder> region;
    std::optional<io::WallLoadRecorder> walls;
    std::optional<io::OutletRecorder> outletRecorder;
    if (root)
    {
        recorder.emplace(options.outDir, scene.writeVtk, scene.vtkFormat, resume ? &*resume : nullptr);
        thermo.emplace(options.outDir, thermoBytes,
                       measure.energy ? (severalRanks ? &ledgerTotals : &ledger) : nullptr);
        if (measure.contacts)
            contacts.emplace(options.outDir, scene.vtkFormat,
                             resume ? resume->frameTimes : std::vector<double>{});
        if (measure.region)
            region.emplace(options.outDir, measure.regionMin, measure.regionMax, regionBytes);
        if (wallLoads)
            walls.emplace(options.outDir, wallBytes);
        if (outlets)
            outletRecorder.emplace(options.outDir, outletBytes);
    }
    // The world the outputs and checkpoints read: this one, or on several ranks the whole world
    // gathered on the first (nullopt on the others). Collective.
    const auto wholeWorld = [&] { return dist::gatherWorld(world, *rankStep); };
    // The outlets' totals: this process's, or on several ranks their sum (on the first). Collective.
    const auto outletState = [&]
    { return rankStep ? dist::outletTotals(flow.outlets, *options.ranks) : flow.outlets; };
    // The ledger's amounts summed over the ranks, on the first (collective).
    const auto sumLedger = [&]
    {
        if (rankStep && measure.energy)
            ledgerTotals.state = dist::ledgerTotals(ledger.state, *options.ranks);
    };
    const auto recordOutputs = [&]
    {
        const std::vector<dem::Outlet> outletTotals =
            outletRecorder || rankStep ? outletState() : flow.outlets;
        sumLedger();
        std::optional<dem::World> gathered;
        if (rankStep && !(gathered = wholeWorld()))
            return;
        const dem::World& w = gathered ? *gathered : world;
        recorder->record(w);
        const std::vector<dem::ContactRecord> now = dem::evaluateContacts(w, 0.0);
        if (gathered) // the step's contact counts, as one process counts them
        {
            gathered->health.touchingPairs = gathered->health.touchingWalls = 0;
            for (const dem::ContactRecord& c : now)
                ++(c.wall ? gathered->health.touchingWalls : gathered->health.touchingPairs);
        }
        thermo->record(w, now);
        if (contacts)
            contacts->record(w, now);
        if (region)
            region->record(w, now);
        if (walls)
            walls->record(w);
        if (outletRecorder)
            outletRecorder->record(w.time, outletTotals);
    };
    const auto closeOutputs = [&]
    {
        if (!root)
            return;
        recorder->close();
        thermo->close();
        if (region)
            region->close();
        if (walls)
            walls->close();
        if (outletRecorder)
            outletRecorder->close();
    };
    if (!resume)
        recordOutputs();
    const std::filesystem::path checkpointPath = options.outDir / "checkpoint.bin";
    const auto writeCheckpoint = [&]
    {
        dem::ParticleFlow saved = flow; // (on several ranks, with the outlets' totals)
        saved.outlets = outletState();
        sumLedger();
        std::optional<dem::World> gathered;
        if (rankStep && !(gathered = wholeWorld()))
            return;
        std::vector<std::uint64_t> bytes = {recorder->csvBytes(), thermo->size()};
        if (region)
            bytes.push_back(region->size());
        if (walls)
            bytes.push_back(walls->size());
        if (outletRecorder)
            bytes.push_back(outletRecorder->size());
        io::writeDemCheckpoint(checkpointPath, gathered ? *gathered : world, sceneHash,
                               {recorder->frameTimes(), bytes, 0},
                               ledgerState && rankStep ? &ledgerTotals.state : ledgerState, &saved);
    };
    io::stopOnSignals();

    const auto start = std::chrono::steady_clock::now();
    io::ProgressLine progress(root && options.progress); // (io/progress_line.h)
    const std::uint64_t firstStep = world.stepCount;
    // In runs of steps up to the next output, checkpoint or stop (dem::advance: the bits of step()
    // calls, the kick passes fused), stopping after the first step whose state is not finite or
    // whose overlap exceeds the limit. A run is at most `chunk` steps, sized to ~10-50 ms of wall
    // time, so that a signal is seen soon (the bits do not depend on where the runs end).
    std::uint64_t chunk = 1;
    constexpr std::uint64_t kMaxChunk = 1024;
    double particleSteps = 0;
    for (std::uint64_t s = world.stepCount; s < totalSteps;)
    {
        std::uint64_t runEnd = std::min({(s / outputEvery + 1) * outputEvery, s + chunk, totalSteps});
        if (checkpointEvery)
            runEnd = std::min(runEnd, (s / checkpointEvery + 1) * checkpointEvery);
        if (options.stopAtStep)
            runEnd = std::min(runEnd, *options.stopAtStep);
        if (!flow.empty()) // particles come and go between runs of steps
            runEnd = std::min(runEnd, (s / flow.everySteps + 1) * flow.everySteps);
        const auto runStart = std::chrono::steady_clock::now();
        const std::uint64_t done = dem::advance(world, scene.dt, runEnd - s, scene.maxOverlapFraction);
        s += done;
        // (the count changes with a flow; on several ranks, this rank's own particles)
        particleSteps += double(done) * double(rankStep ? rankStep->owned() : world.particles.size());
        if (s < runEnd || !world.health.finite || world.health.maxOverlapRatio > scene.maxOverlapFraction)
        {
            // (particles named by their stable id, as in the output; on several ranks the health is
            // every rank's, so all stop here and the first reports)
            const auto id = [&](std::uint32_t i)
            { return i < world.particles.size() ? world.particles.id[i] : i; };
            const std::uint32_t failed =
                rankStep ? rankStep->failedParticleId(world)
                         : id(world.health.finite ? world.health.worstParticle : world.health.firstNonFinite);
            if (!root)
                return 3;
            std::ostringstream m;
            m << "step " << world.stepCount << " (t = " << world.time << " s), particle " << failed;
            if (!world.health.finite)
                m << ": position or velocity is not finite (NaN or infinity)";
            else
                m << ": overlap is " << world.health.maxOverlapRatio
                  << " of the radius (limit max_overlap_fraction = " << scene.maxOverlapFraction
                  << "): the time step is too large for the stiffness or the particles are too fast";
            m << "; the " << recorder->framesWritten() << " outputs written so far are in "
              << options.outDir.string();
            if (rankStep)
                throw RanksStopped(m.str());
            throw SimulationError(m.str());
        }
        const auto now = std::chrono::steady_clock::now();
        double runSeconds = std::chrono::duration<double>(now - runStart).count();
        // Several ranks agree on the next run's length and on a stop (a signal reaches each rank
        // at its own moment): the largest of their values.
        double agreed[2] = {runSeconds, double(io::stopSignal())};
        if (rankStep)
            options.ranks->max(agreed);
        runSeconds = agreed[0];
        const int signal = static_cast<int>(agreed[1]);
        if (runSeconds < 0.01 && chunk < kMaxChunk)
            chunk *= 2;
        else if (runSeconds > 0.05 && chunk > 1)
            chunk /= 2;
        if (!flow.empty() && s % flow.everySteps == 0)
        {
            if (rankStep)
                dist::applyFlow(flow, world, *rankStep, scene.dt);
            else
                flow.apply(world, scene.dt);
        }
        if (s % outputEvery == 0 || s == totalSteps)
            recordOutputs();
        bool checkpointed = false;
        if (checkpointEvery && (s % checkpointEvery == 0 || s == totalSteps))
        {
            writeCheckpoint();
            checkpointed = true;
        }
        const bool stop = signal || (options.stopAtStep && s == *options.stopAtStep);
        if (stop && !checkpointed)
            writeCheckpoint();
        if (stop && s < totalSteps)
        {
            closeOutputs();
            if (!root)
                return signal ? io::kInterruptedBase + signal : 0;
            progress.finish();
            std::fprintf(stderr,
                         "veridem: %s at step %llu of %llu (t = %.9g s); checkpoint written; continue with: "
                         "veridem run %s --restart %s --out %s\n",
                         signal ? (std::string("stopped by ") + io::signalName(signal)).c_str() : "stopped",
                         static_cast<unsigned long long>(s), static_cast<unsigned long long>(totalSteps),
                         world.time, options.sceneFile.c_str(), checkpointPath.string().c_str(),
                         options.outDir.string().c_str());
            return signal ? io::kInterruptedBase + signal : 0;
        }
        progress.update(s, totalSteps, world.time);
    }
    closeOutputs();
    const std::uint64_t stepsRun = totalSteps - firstStep;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::uint64_t counts[2] = {rankStep ? rankStep->owned() : world.particles.liveCount(),
                               static_cast<std::uint64_t>(particleSteps)};
    if (rankStep)
        options.ranks->sum(counts);
    if (!root)
        return 0;
    progress.finish();
    std::printf("veridem: %llu steps of %.4g s (t = %.6g s), %llu particles, %zu outputs in %s\n",
                static_cast<unsigned long long>(stepsRun), scene.dt, world.time,
                static_cast<unsigned long long>(counts[0]), recorder->framesWritten(),
                options.outDir.string().c_str());
    if (rankStep)
        std::printf(
            "veridem: wall time %.3f s on %d MPI ranks of up to %d thread(s), %.3g particle-steps/s, %zu "
            "neighbour rebuilds, regions cut %llu times\n",
            wall, options.ranks->size(), exec::threads(), wall > 0 ? double(counts[1]) / wall : 0.0,
            world.neighbors.rebuildCount(), static_cast<unsigned long long>(rankStep->cuts()));
    else
        std::printf("veridem: wall time %.3f s on up to %d thread(s), %.3g particle-steps/s, %zu neighbour "
                    "rebuilds\n",
                    wall, exec::threads(), wall > 0 ? particleSteps / wall : 0.0,
                    world.neighbors.rebuildCount());
    return 0;
}

} // namespace veridem::app
