// `veridem run` for 2D FEM/DEM scenes ([simulation] type = "fdem2d").
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <string>

namespace veridem::fdem
{

/// Reads the scene, prints the stable time step (and refuses a larger one unless
/// allowUnstableTimeStep), settles if asked, runs for the duration and writes the output to outDir.
/// Returns the process exit code (0 on success). Input errors throw InputError.
int runScene(const toml::table& scene, const std::string& sceneFile, const std::filesystem::path& outDir,
             bool progress, bool allowUnstableTimeStep);

} // namespace veridem::fdem
