// Reading the [[insert]] and [[outlet]] tables of a 3D DEM scene into a dem::ParticleFlow (every
// key, unit and default in docs/scene-format.md); bad input is an InputError naming the key and
// its line.
#pragma once

#include "dem/particle_flow.h"
#include "io/toml_reader.h"

#include <string>

namespace veridem::io
{

/// Reads every [[insert]] and [[outlet]] of `top`; `everySteps` is when they act.
dem::ParticleFlow readParticleFlow(TableReader& top, const dem::World& world, std::uint64_t everySteps);

/// Numbers the inserters' particles after the world's, and sets the neighbour skin's default
/// (prepare(): 0.2 r_max) from the radii to come as well (a scene may start empty). Refuses an
/// energy ledger (`energy`) with inserters or outlets. `file` names the scene in messages.
void startParticleFlow(dem::ParticleFlow& flow, dem::World& world, bool energy, const std::string& file);

/// The world's particles and those the `count` and `rate` inserters are due to add in
/// `duration` [s], checked against the sphere limit (scene_limits.h) if there are inserters.
double expectedParticles(const dem::ParticleFlow& flow, const dem::World& world, Real duration,
                         const std::string& file);

/// A world for the time-step estimate of a scene that inserts particles: the scene's world plus,
/// per inserter and material, a sphere of the smallest and one of the largest radius it draws.
dem::World timeStepProbe(const dem::World& world, const dem::ParticleFlow& flow);

} // namespace veridem::io
