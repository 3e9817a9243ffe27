// Reading the [[insert]] and [[outlet]] tables of a 3D DEM scene into a dem::ParticleFlow (every
// key, unit and default in docs/scene-format.md); bad input is an InputError naming the key and
// its line.
#pragma once

#include "dem/particle_flow.h"
#include "io/toml_reader.h"

namespace veridem::io
{

/// Reads every [[insert]] and [[outlet]] of `top`; `everySteps` is when they act.
dem::ParticleFlow readParticleFlow(TableReader& top, const dem::World& world, std::uint64_t everySteps);

/// A world for the time-step estimate of a scene that inserts particles: the scene's world plus,
/// per inserter and material, a sphere of the smallest and one of the largest radius it draws.
dem::World timeStepProbe(const dem::World& world, const dem::ParticleFlow& flow);

} // namespace veridem::io
