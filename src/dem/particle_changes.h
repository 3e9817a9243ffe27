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
// Removal (removeParticles). A removed particle's place is taken by the last particle
// (ParticleStore::swapRemove), so the store stays dense; the contact lists' keys are renamed to
// the new indices (NeighborList, WallContactList, PeriodicPairs::renameParticles) and the
// history follows its pair through the rebuild that must follow (rebuildAfterParticleChange,
// world.h). The cost is the removed particles' own plus one pass over the contact keys and a
// rebuild: O(N) per event that removes.
#pragma once

#include "dem/particle_index.h"
#include "dem/world.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// Removes the particles `doomed` (indices, each once, any order). The contact lists must be
/// rebuilt before the next step (rebuildAfterParticleChange).
void removeParticles(World& world, std::vector<std::uint32_t> doomed);

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
