// DIR/state.csv, the particles of a DEM run at one instant, written so that a scene reloads them
// with `[[particles]] file = "DIR/state.csv"` (io/particle_file.h): a comment line with the time and
// step, the header `id,material,radius,x,y,z,vx,vy,vz,wx,wy,wz,fixed`, then one row per particle
// (retired ones left out) in store order: its stable id, its material's name, radius [m], position
// [m] (wrapped into a periodic box, as in particles.csv), velocity [m/s], angular velocity [rad/s]
// and frozen flag (0 or 1), every number in its shortest round-trip form (it reads back to the same
// double). Written under a temporary name and renamed (AtomicFile): the file on disk is always
// complete. `veridem run` writes it at the end of a run and with every checkpoint.
#pragma once

#include "core/vec3.h"
#include "dem/world.h"

#include <filesystem>
#include <string>

namespace veridem::io
{

/// Writes `world`'s particles to `path` (the time in its first line is outputTime(stepCount, dt),
/// dt [s]). Throws OutputError on a failed write.
void writeParticleState(const std::filesystem::path& path, const dem::World& world, Real dt);

/// The header line of a state file (without its line end).
inline constexpr const char* kParticleStateHeader = "id,material,radius,x,y,z,vx,vy,vz,wx,wy,wz,fixed";

} // namespace veridem::io
