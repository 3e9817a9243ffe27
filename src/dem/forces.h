// Force loops: gather contact inputs, call the contact law, scatter forces and torques.
#pragma once

#include "dem/world.h"

namespace veridem::dem
{

/// Clears forces and torques, then adds all pair and wall contact forces for the current state.
/// dt [s] is the step the tangential spring increments over (0 for the initial evaluation).
void computeForces(World& world, Real dt);

} // namespace veridem::dem
