// The force stages of the step (world.cpp), each summing contacts in a fixed order: stage 3, the
// pairs (forces.cpp, with pair_kernel.h); stage 4a, the cross-block shares
// (exec/cross_block_sums.cpp); stage 4b, the walls (wall_forces.cpp).
#pragma once

#include "dem/world.h"

namespace veridem::dem
{

/// Stage 3, pairs: sets every particle's force [N] and torque [N m] (ParticleStore, padded rows)
/// to the sum of its touching pair contacts inside its block (neighbor_list.h), in slot order, and leaves the
/// cross-block shares in the slots' deferred entries; clears the history of slots that opened. dt [s] is the
/// step the tangential spring increments over (0 for the initial evaluation). Resets and updates
/// world.health. `sumsAreZero`: every particle's force and torque rows are zero already (advance()'s
/// fused particle pass zeroes them after its last read), so they are not zeroed again.
void computePairForces(World& world, Real dt, bool sumsAreZero = false);

/// Adds the particles' external loads (ParticleStore::externalForce, externalTorque) of
/// [begin, end) to their force and torque sums, if the store keeps them; else does nothing.
void addExternalLoads(ParticleStore& particles, std::size_t begin, std::size_t end);

/// Brings external loads changed since the last force evaluation into the force and torque rows
/// (the next step's first half kick reads them), if the store keeps them. For a driver that
/// changes them between steps (api::Simulation). O(N).
void syncExternalLoads(ParticleStore& particles);

/// Stage 4a, particles [begin, end): adds the incoming cross-block contacts to the force and
/// torque stage 3 left, in slot order (bit-identical for any thread count).
void addCrossBlockForces(World& world, std::size_t begin, std::size_t end);

/// Stage 4b, particles [begin, end): adds each one's touching wall contacts, in slot order.
ContactHealth computeWallForces(World& world, Real dt, std::size_t begin, std::size_t end);

/// The wall contacts of particle i (its slots in world.wallContacts, in slot order) through the
/// general contact law, with its state read from `s` instead of the store (the one-particle step
/// holds it in registers): their forces [N] and torques [N m] added to `force` and `torque`, the
/// operations of computeWallForces. Returns their health.
ContactHealth wallContactsOf(World& world, Real dt, std::uint32_t i, const ParticleState& s, Vec3& force,
                             Vec3& torque);

/// Folds per-chunk wall health into world health in chunk order (sets touchingWalls).
void mergeWallHealth(StepHealth& health, const ContactHealth* chunk, int chunks);

/// Stages 3 and 4 for all particles, serially (no kick): the initial evaluation.
void computeForces(World& world, Real dt);

} // namespace veridem::dem
