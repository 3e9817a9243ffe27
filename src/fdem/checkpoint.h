// Checkpoint of a 2D FEM/DEM world (io/checkpoint_file.h holds the container): the node state
// (positions, velocities, forces, prescribed flags and inverse masses), the triangles' last
// stresses, the active node and triangle lists, the couples with their friction history (springs,
// previous depths), the broad phase's positions at the last detection and its buffer, time, step
// count, detection count, the dissipated works and the last step's friction diagnostics, and the
// driver's output counters. A restarted run takes the same code path with the same data, so it
// continues with the same bits. What the scene rebuilds identically (meshes, materials, masses,
// reference geometry) is not saved.
#pragma once

#include "fdem/world.h"
#include "io/checkpoint_file.h"

#include <filesystem>

namespace veridem::fdem
{

/// Writes `world` and `outputs` to `path` atomically; throws OutputError.
void writeCheckpoint(const std::filesystem::path& path, const World& world, std::uint64_t sceneHash,
                     const io::CheckpointOutputs& outputs);

/// Restores a world built from the same scene (buildWorld) to the checkpoint's state; returns the
/// output counters. Throws InputError (one line) for another scene, another format version or a
/// truncated or corrupt file.
io::CheckpointOutputs readCheckpoint(const std::filesystem::path& path, World& world,
                                     std::uint64_t sceneHash);

} // namespace veridem::fdem
