// Force loops: contact inputs, the contact law, and the per-particle sums in a fixed order
// (stages 3-5 of the step, world.cpp).
#pragma once

#include "dem/world.h"

namespace veridem::dem
{

/// Stage 3, pairs: sets every particle's force [N] and torque [N m] to the sum of its touching
/// pair contacts inside its block (neighbor_list.h), in slot order, and leaves the cross-block
/// shares in the slots' deferred entries; clears the history of slots that opened. dt [s] is the
/// step the tangential spring increments over (0 for the initial evaluation). Resets and updates
/// world.health.
void computePairForces(World& world, Real dt);

/// Stage 4: adds each particle's incoming cross-block contacts, in slot order (bit-identical for
/// any thread count).
void addCrossBlockForces(World& world);

/// Stage 5, walls: adds every touching particle-wall contact to its particle, in slot order;
/// continues world.health.
void computeWallForces(World& world, Real dt);

/// All three, in order.
void computeForces(World& world, Real dt);

} // namespace veridem::dem
