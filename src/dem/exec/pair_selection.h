// The selection pass of the pair stage: over a run of neighbour candidates (NeighborList's
// touching-candidate sub-list), the ones within the touch criterion r_i + r_j + reach are appended
// to a batch (PairBatch) for the pair kernel, and the ones found open that may have been in contact
// are recorded, so their history is cleared. In an AVX2 variant (four distance tests at once, the
// bookkeeping by shuffles) and a portable one: the same IEEE operations, so the same choices.
#pragma once

#include "core/vec3.h"
#include "dem/exec/law_batch.h"
#include "exec/isa.h"

#include <cstdint>

namespace veridem::dem::batch
{

inline constexpr std::size_t kPrefetchAhead = 16; // candidates between a prefetch and its use

/// A batch of touching pair contacts: their candidate indices (NeighborList::activeSlots) and
/// particles, and the geometry the selection pass computed for its distance test: the separation
/// x_i - x_j [m] and the radii r_i, r_j [m] (the same values the kernel would compute again, so
/// it reads them here instead of gathering both particles' positions and radii a second time).
/// The kernel loads the rest straight into lanes.
struct PairBatch
{
    std::uint32_t candidate[kBatch], i[kBatch], j[kBatch];
    alignas(32) double sx[kBatch], sy[kBatch], sz[kBatch], ri[kBatch], rj[kBatch];
};

/// The touching-candidate sub-list of a chunk as the selection pass reads it (array bases in one
/// place: NeighborList::activeFirst/activeSecond and ContactHistoryStore::formed, the particles' positions
/// [m] and radii [m]).
struct Candidates
{
    const std::uint32_t* first;
    const std::uint32_t* second;
    const Vec3* position;
    const Real* radius;
    const PaddedVec3* positionRadius; // (x, y, z, r) per particle: position and radius in one row
    const std::uint8_t* mayBeActive;
    std::size_t end; // one past the chunk's last candidate
    Real reach;      // NeighborList::reach [m]: a pair within r_i + r_j + reach is passed to the law
};

/// A selection pass (selectTouchingScalar in pair_selection.cpp): from candidate a on, appends the
/// touching ones to the batch at m and the opened ones to opened[o]; returns where it stopped.
using SelectPass = std::size_t (*)(const Candidates&, std::size_t, std::size_t, PairBatch&, std::size_t&,
                                   std::uint32_t*, std::size_t&);

/// The selection pass compiled for `isa`.
SelectPass selectPassFor(exec::Isa isa);

} // namespace veridem::dem::batch
