// Checkpoint of a 3D DEM world (io/checkpoint_file.h holds the container): every array the next
// step reads, written as it is in memory, so a restarted run takes the same code path with the
// same data and continues with the same bits as the run that wrote it.
//
// Saved: time and step count; the step's health (thermo output); every particle array but the
// (x, y, z, r) rows, which are refilled from position and radius; each wall's motion state
// (displacement, clock, velocity, angular velocity: an oscillating plate's phase is its clock);
// the neighbour list (slots, blocks, cross-block entries with their deferred shares, the candidate
// sub-list with its contact history and may-be-active flags, the positions of the last builds and
// the rebuild bookkeeping); the wall-contact list with its history; the energy ledger's
// accumulators when the run keeps one (dem/energy_ledger.h); the particles' ids and frozen flags
// and the state of the inserters and outlets (dem/particle_flow.h: each inserter's generator,
// counts and inserted mass, each outlet's removed count and mass, the next id); the driver's
// output counters. The particle count is the checkpoint's (particles may have come and gone).
// Not saved: what the scene rebuilds identically (materials, the pair table, wall shapes), the
// thread schedules (they change which thread computes a block, never the bits) and the profile.
#pragma once

#include "dem/energy_ledger.h"
#include "dem/particle_flow.h"
#include "dem/world.h"
#include "io/checkpoint_file.h"

#include <filesystem>

namespace veridem::io
{

/// Writes `world` and `outputs` to `path` atomically (CheckpointWriter); throws OutputError.
void writeDemCheckpoint(const std::filesystem::path& path, const dem::World& world, std::uint64_t sceneHash,
                        const CheckpointOutputs& outputs, const dem::EnergyLedgerState* ledger = nullptr,
                        const dem::ParticleFlow* flow = nullptr);

/// Restores a world built from the same scene (io::readDemScene: materials, pair table, walls and
/// particles in place) to the checkpoint's state; returns the output counters. Throws InputError
/// (one line) for another scene, another format version or a truncated or corrupt file. `ledger`:
/// where to restore the energy ledger (the run keeps one; null: it does not). `flow`: the scene's
/// inserters and outlets (null: none).
CheckpointOutputs readDemCheckpoint(const std::filesystem::path& path, dem::World& world,
                                    std::uint64_t sceneHash, dem::EnergyLedgerState* ledger = nullptr,
                                    dem::ParticleFlow* flow = nullptr);

} // namespace veridem::io
