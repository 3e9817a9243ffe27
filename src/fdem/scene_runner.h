// `veridem run` for 2D FEM/DEM scenes ([simulation] type = "fdem2d").
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace veridem::fdem
{

/// Checkpoint and restart of a run (docs/fdem.md): continue from `restartFile` (if not empty),
/// stop after step `stopAtStep` (counted from t = 0 after the settling) with a checkpoint.
struct RunControl
{
    std::string restartFile;
    std::optional<std::uint64_t> stopAtStep;
};

/// Reads the scene, prints the stable time step (and refuses a larger one unless
/// allowUnstableTimeStep), settles if asked, runs for the duration and writes the output to outDir.
/// Returns the process exit code (0 on success). Input errors throw InputError.
/// On SIGINT or SIGTERM it writes DIR/checkpoint.bin, closes the output and returns 128 + the signal.
int runScene(const toml::table& scene, const std::string& sceneFile, const std::filesystem::path& outDir,
             bool progress, bool allowUnstableTimeStep, const RunControl& control = {});

} // namespace veridem::fdem
