// Force loops: gather contact inputs, call the contact law, write per-contact outputs (stage 3),
// then sum them per particle in a fixed order (stage 4). See world.cpp for the step.
#pragma once

#include "dem/world.h"

namespace veridem::dem
{

/// Stage 3, pairs: evaluates every pair slot and writes its force and torques into the slot
/// (zero, with history cleared, when the pair is not touching). dt [s] is the step the tangential
/// spring increments over (0 for the initial evaluation). Resets and updates world.health.
void computePairForces(World& world, Real dt);

/// Stage 3, walls: the same for every particle-wall slot; continues world.health.
void computeWallForces(World& world, Real dt);

/// Stage 4: particle force and torque = sum of its slots in ascending slot order, pairs then walls
/// (bit-identical for any thread count).
void gatherContactForces(World& world);

/// All three, in order.
void computeForces(World& world, Real dt);

} // namespace veridem::dem
