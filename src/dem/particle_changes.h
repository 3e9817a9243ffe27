// Removing particles between steps (outlets, dem/particle_flow.h). A removed particle's place is
// taken by the last particle (ParticleStore::swapRemove), so the store stays dense; the contact
// lists' keys are renamed to the new indices (NeighborList and WallContactList::renameParticles)
// and the history follows its pair through the rebuild that follows (rebuildAfterParticleChange,
// world.h). The cost is the removed particles' own plus one pass over the contact keys, which the
// rebuild makes anyway.
#pragma once

#include "dem/world.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// Removes the particles `doomed` (indices, each once, any order). The contact lists must be
/// rebuilt before the next step (rebuildAfterParticleChange).
void removeParticles(World& world, std::vector<std::uint32_t> doomed);

} // namespace veridem::dem
