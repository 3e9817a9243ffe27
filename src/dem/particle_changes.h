// Particles in and out of the contact lists between steps (inserters and outlets,
// dem/particle_flow.h).
//
// Insertion, without a rebuild (addInsertedParticles). The new particles are appended to the
// store, so every existing index, slot and history entry stays as it is. Their pairs (with the
// particles near them and with each other) are found on a grid kept between events
// (ParticleIndex) and join the list of pairs evaluated after the pair stage (World::periodicPairs:
// the same law through pairContactAt, history by (i, j); shift 0, or in a periodic box the shift
// of the partner's image, looked for near each image of the new particle); their wall candidates are
// appended to the wall-contact list; their displacement is measured from where they were
// inserted. Until the next rebuild of the contact lists, which the step makes when some particle
// has moved more than skin/2 (world.cpp), no particle or wall moves far enough to reach an
// inserted particle unseen (the search distances below). That rebuild takes the pairs into the
// neighbour list with their history (PeriodicPairs::handOver). The cost is the inserted
// particles' own: their neighbourhood, their walls and the pairs listed since the last rebuild.
//
// Removal, in two parts. An outlet's particle is first retired (retireParticles), at its own
// cost: it is parked at P = (kParkedCoordinate, kParkedCoordinate, kParkedCoordinate) with zero
// velocity, angular velocity, force and torque and radius 0 (the mark of a retired particle,
// ParticleStore::retired), and its neighbour-list references move with it
// (NeighborList::parkParticle). Its pair slots and wall slots stay in the lists but can give no
// contact:
//   - a pair slot touches only if |x_i - x_j| < r_i + r_j + reach: a live particle is ~1e30 m
//     away; two retired ones share P, and 0 < 0 + 0 + reach fails since retirement needs a zero
//     reach (retiresWithoutRebuild);
//   - with radius 0 no wall touches: a plane needs -r <= s < r for the signed distance s, a
//     cylinder an overlap in (0, 2r], a mesh face, edge or vertex a distance below r, all empty
//     for r = 0; a dish touches only below its rim, and P is above every rim.
// The next force stage finds its contacts open and drops their history, as for any contact that
// opens, so its partners feel nothing from that step on. It does not move: a drift adds dt v to a
// coordinate of 1e30, whose spacing is 2^47 m (1.4e14 m), and rounds back to it while |dt v| is
// below 7e13 m (v grows by |g| dt a step from 0), so its displacement from its reference stays 0
// and it never triggers the rebuild. Its state stays finite and touches nothing, so the health
// checks pass over it.
//
// The retired particles leave the store at the next rebuild of the contact lists, the one the
// step makes when some particle or wall has moved more than skin/2 (world.cpp,
// rebuildContactLists; O(N) anyway): removeParticles moves the last particle into each one's place
// (ParticleStore::swapRemove) and renames the lists' keys (NeighborList, WallContactList,
// PeriodicPairs::renameParticles); the rebuild carries the history by key. Nothing else
// compacts: the outputs skip them (ParticleStore::retired; the particle rows, the ParaView frames
// and the thermo count list only the others) and a checkpoint saves them as they are (the store,
// the references, the lists), so neither the output interval nor a restart changes the run. A
// verification case whose sampler reads the store by slot may compact first
// (compactRetiredParticles). Where retiring is not possible (retiresWithoutRebuild: a
// StepObserver, e.g. the energy ledger, reads every particle each step; a touch reach) an event
// removes at once and rebuilds (rebuildAfterParticleChange).
//
// Bits. A removal acts at the same step as a removal at once, but the slots differ until the
// compaction (the retired particle keeps its slot, the last particle stays where it is, particles
// inserted meanwhile come after it), and a particle's force is summed in slot order
// (neighbor_list.h): a scene with outlets gives other bits than removal at once, the same physics
// to round-off. The thread count, the output interval and a checkpoint's restart do not change
// them.
#pragma once

#include "dem/particle_index.h"
#include "dem/world.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// Removes the particles `doomed` (indices, each once, any order) from the store and renames the
/// contact lists' keys. The contact lists must be rebuilt before the next force stage
/// (rebuildAfterParticleChange, or the step's rebuild). O(N).
void removeParticles(World& world, std::vector<std::uint32_t> doomed);

/// Where a retired particle is parked on every axis [m] (file comment).
inline constexpr Real kParkedCoordinate = 1e30;

/// True if particles of `world` can be retired (retireParticles) instead of removed at once: the
/// world is prepared and its contact lists are built for its particles, no StepObserver reads it
/// (it would see the retired particles) and the touch reach is 0 (file comment).
bool retiresWithoutRebuild(const World& world);

/// Retires the particles `doomed` (indices, each once, none fixed or retired): out of the physics
/// from the next step on, out of the store at the next rebuild (file comment). Needs
/// retiresWithoutRebuild(world). O(doomed).
void retireParticles(World& world, const std::vector<std::uint32_t>& doomed);

/// Removes the retired particles from the store (removeParticles); returns false, changing
/// nothing, if there are none. The contact lists must then be rebuilt. O(N).
bool removeRetiredParticles(World& world);

/// If some particles are retired: removes them and rebuilds the contact lists
/// (rebuildAfterParticleChange). For a caller that reads every particle by slot (a verification
/// sampler); the run's outputs skip retired particles instead.
/// O(N).
void compactRetiredParticles(World& world);

/// The search distance beyond r_i + r_j [m] for an inserted particle's pairs: 1.5 skin + reach.
/// Until the next rebuild an inserted particle moves at most skin/2 from where it is inserted
/// and any other at most skin/2 from its reference, which is itself within skin/2 of where it is
/// now: together 1.5 skin.
inline Real insertedPairSearch(const NeighborList& list)
{
    return 1.5 * list.skin + list.reach;
}

/// True if particles of radius up to `largestRadius` [m] (the largest of the particles near them
/// too: ParticleIndex::largestRadius) can be inserted into `world` without a rebuild
/// (addInsertedParticles): the contact lists are built for its `particleCount` particles, each
/// periodic axis is at least twice 2 largestRadius + insertedPairSearch long (a pair then has at
/// most one image within reach, as PeriodicPairs needs), and the list's touch reach
/// (NeighborList::reach, JKR adhesion) covers the pairs of the particles appended since
/// [particleCount, size) with every material at that radius.
bool insertsWithoutRebuild(const World& world, std::size_t particleCount, Real largestRadius);

/// Takes the particles [from, size) appended to the store since the last step into the contact
/// lists without a rebuild (file comment); in a periodic box their pairs through a face too, with
/// their image shifts. `index` holds every particle near the inserted ones and their images
/// (ParticleIndex, valid for the list with the extra reach insertedPairSearch). Needs
/// insertsWithoutRebuild(world, from, index.largestRadius()).
void addInsertedParticles(World& world, std::size_t from, const ParticleIndex& index);

} // namespace veridem::dem
