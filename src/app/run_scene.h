// Scene runners called by `veridem run`. The scene's [simulation] type picks one.
#pragma once

#include "core/error.h"
#include "distributed/collective.h"

#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace veridem::app
{

struct RunOptions
{
    std::string sceneFile;
    std::filesystem::path outDir;                   // created if missing
    bool progress = true;                           // progress with ETA on stderr
    bool allowUnstableTimeStep = false;             // --force-dt: run above the stability limit (warned)
    bool strict = false;                            // --strict: the plausibility warnings are errors
    std::string restartFile;                        // --restart: continue from this checkpoint (empty: none)
    std::optional<std::uint64_t> stopAtStep;        // --stop-at-step: stop after this step (counted from
                                                    // the scene's start) with a checkpoint, as on SIGINT
    const distributed::Collective* ranks = nullptr; // the MPI job's ranks (mpirun); null: one process
    std::uint64_t rebalanceEvery = 10;              // exchanges of particles between cuts of the regions
};

/// A stop every rank of an MPI job reached at the same step (a blow-up): the first rank reports it,
/// the others end with its exit code and no message.
class RanksStopped : public SimulationError
{
  public:
    using SimulationError::SimulationError;
};

/// 3D sphere DEM scene (type = "dem"). Returns the exit code.
int runDemScene(const toml::table& scene, const RunOptions& options);

} // namespace veridem::app
