// The state behind api::Simulation (simulation.h): the scene, its outputs and, on several MPI
// ranks, this rank's part; internal to src/api (simulation.cpp steps it, simulation_access.cpp
// reads and changes it between steps).
#pragma once

#include "api/simulation.h"
#include "app/silenced_stream.h"
#include "core/error.h"
#include "dem/forces.h"
#include "dem/particle_changes.h"
#include "distributed/rank_flow.h"
#include "distributed/rank_gather.h"
#include "distributed/rank_step.h"
#include "distributed/rank_sums.h"
#include "io/contact_output.h"
#include "io/dem_checkpoint.h"
#include "io/dem_scene.h"
#include "io/outlet_output.h"
#include "io/particle_flow_keys.h"
#include "io/particle_output.h"
#include "io/particle_state.h"
#include "io/region_output.h"
#include "io/species_output.h"
#include "io/thermo_output.h"
#include "io/toml_reader.h"
#include "io/wall_output.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace veridem::api
{

struct Simulation::State
{
    std::string name;
    SimulationOptions options;
    io::DemScene scene;
    std::uint64_t hash = 0;
    bool severalRanks = false, root = true;
    std::uint64_t totalSteps = 0, outputEvery = 1, checkpointEvery = 0;
    std::uint64_t chunk = 1;        // steps per run, sized to ~10-50 ms of wall time
    double particleSteps = 0;       // run by advance() on this rank
    dem::EnergyLedger ledger;       // with `[output] energy = true`: world.observer
    dem::EnergyLedger ledgerTotals; // on several ranks, the ranks' sum (the files read it)
    std::optional<distributed::RankStep> rankStep;
    // The files (the first rank only; none without an output directory)
    std::optional<io::ParticleRecorder> recorder;
    std::optional<io::ThermoRecorder> thermo;
    std::optional<io::ContactRecorder> contacts;
    std::optional<io::RegionRecorder> region;
    std::optional<io::WallLoadRecorder> walls;
    std::optional<io::OutletRecorder> outlets;
    std::optional<io::SpeciesRecorder> species;
    std::optional<io::ZoneRecorder> zones;
    std::optional<io::TrackRecorder> tracked;
    bool closed = false;
    // The step at which checkpointPath() was last written, by advance()'s schedule or by
    // writeCheckpoint() (none since the start or a restore)
    std::optional<std::uint64_t> ownCheckpointStep;

    dem::World& world() { return scene.world; }
    bool files() const { return !options.outDir.empty(); }
    bool wallLoads() const { return !scene.world.walls.empty(); }
    dem::EnergyLedgerState* ledgerState() { return scene.measurements.energy ? &ledger.state : nullptr; }

    /// The number of output files in a checkpoint: particles.csv, thermo.csv, region.csv (if
    /// measured), walls.csv (if there are walls), outlets.csv (if there are outlets), then
    /// species.csv, zones.csv and tracked.csv (if asked for), in order.
    std::size_t outputFiles() const
    {
        if (!files())
            return 0;
        const io::MeasurementOptions& m = scene.measurements;
        return 2 + std::size_t(m.region) + std::size_t(wallLoads()) +
               std::size_t(!scene.flow.outlets.empty()) + std::size_t(m.species) +
               std::size_t(!m.zones.empty()) + std::size_t(!m.track.empty());
    }

    void openOutputs(const io::CheckpointOutputs* saved)
    {
        if (!root || !files())
            return;
        std::optional<io::ParticleRecorder::Resume> resume;
        std::optional<std::uint64_t> thermoBytes, regionBytes, wallBytes, outletBytes, speciesBytes,
            zoneBytes, trackBytes;
        const io::MeasurementOptions& measure = scene.measurements;
        if (saved)
        {
            resume = io::ParticleRecorder::Resume{saved->frameTimes, saved->fileBytes[0]};
            thermoBytes = saved->fileBytes[1];
            if (scene.measurements.region)
                regionBytes = saved->fileBytes[2];
            if (wallLoads())
                wallBytes = saved->fileBytes[2 + std::size_t(scene.measurements.region)];
            std::size_t next = 2 + std::size_t(measure.region) + std::size_t(wallLoads());
            if (!scene.flow.outlets.empty())
                outletBytes = saved->fileBytes[next++];
            if (measure.species)
                speciesBytes = saved->fileBytes[next++];
            if (!measure.zones.empty())
                zoneBytes = saved->fileBytes[next++];
            if (!measure.track.empty())
                trackBytes = saved->fileBytes[next++];
        }
        const std::filesystem::path& dir = options.outDir;
        recorder.emplace(dir, scene.output, resume ? &*resume : nullptr);
        thermo.emplace(dir, scene.output, thermoBytes,
                       measure.energy ? (severalRanks ? &ledgerTotals : &ledger) : nullptr,
                       scene.world.bonds.enabled);
        if (measure.contacts)
            contacts.emplace(dir, scene.output, resume ? resume->frameTimes : std::vector<double>{});
        if (measure.region)
            region.emplace(dir, scene.output, measure.regionMin, measure.regionMax, regionBytes);
        if (wallLoads())
            walls.emplace(dir, scene.output, wallBytes);
        if (!scene.flow.outlets.empty())
            outlets.emplace(dir, scene.output, outletBytes);
        if (measure.species)
            species.emplace(dir, scene.output, speciesBytes);
        if (!measure.zones.empty())
            zones.emplace(dir, scene.output, measure.zones, zoneBytes);
        if (!measure.track.empty())
            tracked.emplace(dir, scene.output, measure.track, trackBytes);
    }

    /// The outlets' totals: this process's, or on several ranks their sum (on the first). Collective.
    std::vector<dem::Outlet> outletState()
    {
        return rankStep ? distributed::outletTotals(scene.flow.outlets, *options.ranks) : scene.flow.outlets;
    }
    /// The ledger's amounts summed over the ranks, on the first (collective).
    void sumLedger()
    {
        if (rankStep && scene.measurements.energy)
            ledgerTotals.state = distributed::ledgerTotals(ledger.state, *options.ranks);
    }

    void recordOutputs()
    {
        if (!files())
            return;
        const std::vector<dem::Outlet> outletTotals =
            outlets || rankStep ? outletState() : scene.flow.outlets;
        sumLedger();
        std::optional<dem::World> gathered;
        if (rankStep && !(gathered = distributed::gatherWorld(world(), *rankStep)))
            return; // (not the first rank)
        const dem::World& w = gathered ? *gathered : world();
        const std::vector<dem::ContactRecord> now = dem::evaluateContacts(w, 0.0);
        recorder->record(w, &now);
        if (w.stepCount == totalSteps) // (the last state, for a scene that starts from it)
            io::writeParticleState(options.outDir / "state.csv", w, scene.dt);
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
        if (outlets)
            outlets->record(w, outletTotals);
        if (species)
            species->record(w);
        if (zones)
            zones->record(w);
        if (tracked)
            tracked->record(w);
    }

    void writeCheckpoint(const std::filesystem::path& path)
    {
        dem::ParticleFlow saved = scene.flow; // (on several ranks, with the outlets' totals)
        saved.outlets = outletState();
        sumLedger();
        std::optional<dem::World> gathered;
        if (rankStep && !(gathered = distributed::gatherWorld(world(), *rankStep)))
            return;
        io::CheckpointOutputs outputs;
        if (recorder)
        {
            outputs.frameTimes = recorder->frameTimes();
            outputs.fileBytes = {recorder->csvBytes(), thermo->size()};
            if (region)
                outputs.fileBytes.push_back(region->size());
            if (walls)
                outputs.fileBytes.push_back(walls->size());
            if (outlets)
                outputs.fileBytes.push_back(outlets->size());
            if (species)
                outputs.fileBytes.push_back(species->size());
            if (zones)
                outputs.fileBytes.push_back(zones->size());
            if (tracked)
                outputs.fileBytes.push_back(tracked->size());
        }
        if (files())
            io::writeParticleState(options.outDir / "state.csv", gathered ? *gathered : world(), scene.dt);
        io::writeDemCheckpoint(path, gathered ? *gathered : world(), hash, outputs,
                               ledgerState() && rankStep ? &ledgerTotals.state : ledgerState(), &saved);
    }

    void closeOutputs()
    {
        if (closed || !root)
            return;
        closed = true;
        if (!recorder)
            return;
        recorder->close();
        thermo->close();
        if (region)
            region->close();
        if (walls)
            walls->close();
        if (outlets)
            outlets->close();
        if (species)
            species->close();
        if (zones)
            zones->close();
        if (tracked)
            tracked->close();
    }

    void applyFlow()
    {
        if (rankStep)
            distributed::applyFlow(scene.flow, world(), *rankStep, scene.dt);
        else
            scene.flow.apply(world(), scene.dt);
    }

    /// Throws BlowUp for the last step's bad health (particles named by their stable id, as in the
    /// output; on several ranks the health is every rank's, so all stop here and the first
    /// reports), after flushing the outputs written so far.
    [[noreturn]] void blowUp()
    {
        dem::World& w = world();
        const auto id = [&](std::uint32_t i) { return i < w.particles.size() ? w.particles.id[i] : i; };
        const std::uint32_t failed =
            rankStep ? rankStep->failedParticleId(w)
                     : id(w.health.finite ? w.health.worstParticle : w.health.firstNonFinite);
        std::ostringstream m;
        m << "step " << w.stepCount << " (t = " << w.time << " s), particle " << failed;
        if (!w.health.finite)
            m << ": position or velocity is not finite (NaN or infinity)";
        else
            m << ": overlap is " << w.health.maxOverlapRatio
              << " of the radius (limit max_overlap_fraction = " << scene.maxOverlapFraction
              << "): the time step is too large for the stiffness or the particles are too fast";
        if (recorder)
            m << "; the " << recorder->framesWritten() << " outputs written so far are in "
              << options.outDir.string();
        closeOutputs();
        throw BlowUp(m.str(), rankStep.has_value());
    }
};

} // namespace veridem::api
