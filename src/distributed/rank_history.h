// Contact history keyed by global particle ids (ParticleStore::id), so that it can leave one
// rank's store and enter another's (docs/architecture.md, "MPI"): at an exchange, a migrant's
// pair and wall contacts travel with it, and each rank then gives its lists the entries whose
// particles it holds, under its new local indices, before the rebuild that carries them by key.
//
// A pair entry is stored as the pair (lo, hi) of ids, lo < hi, with its springs as the contact
// law sees them with lo first: a rank whose local order is the other way round negates them, as
// NeighborList::renameParticles does. A wall entry is (id, wall) with the slot's mesh normal and
// flat triangle, in slot order (a mesh group's slots together).
#pragma once

#include "core/vec3.h"
#include "dem/world.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace veridem::distributed
{

struct PairHistoryEntry
{
    std::uint32_t lo = 0, hi = 0; // the two particles' ids, lo < hi
    Vec3 spring, rolling;         // tangential spring [m] and EPSD rolling spring [N m], lo first
    std::uint8_t formed = 0;      // NeighborList's formed flag
    std::array<Real, dem::kHistoryScalarRoom> scalars{}; // the history scalars (KeyedHistory::scalarCount)
};

struct WallHistoryEntry
{
    std::uint32_t id = 0, wall = 0; // the particle's id, the wall's index
    Vec3 spring, rolling;           // [m], [N m]
    Vec3 normal;                    // the slot's mesh normal (zero if none)
    std::uint32_t flat = 0;         // the slot's flat triangle (WallContactList::kNotFlat if none)
    Vec3 loadForce, loadMoment;     // the slot's recorded load [N], [N m] (zero unless recorded)
    std::array<Real, dem::kHistoryScalarRoom> scalars{}; // the history scalars (KeyedHistory::scalarCount)
};

struct KeyedHistory
{
    std::vector<PairHistoryEntry> pairs;
    std::vector<WallHistoryEntry> walls;
    unsigned scalarCount = 0; // history scalars per entry (ContactHistoryStore::scalarCount)
};

/// Bytes a pair entry and a wall entry take in an exchange.
inline constexpr std::size_t kPairEntryBytes = 4 + 4 + 6 * 8 + 1;
inline constexpr std::size_t kWallEntryBytes = 4 + 4 + 9 * 8 + 4 + 6 * 8;

/// Appends to `out` the history of world's pair candidates that may be formed and have some
/// particle i with take(i), and of the wall slots of each particle i with take(i).
template <class Take> void exportHistory(const dem::World& world, Take&& take, KeyedHistory& out);

/// The entries as bytes (the scalar count, a pair count, then the entries, each with its scalars)
/// and back.
void packHistory(const KeyedHistory& h, std::vector<std::byte>& out);
KeyedHistory unpackHistory(std::span<const std::byte> in, int from);

/// Gives world's contact lists the entries of `sources` whose particles it holds, under their
/// local indices, replacing the lists' own candidates and slots (and emptying the periodic pairs:
/// their entries become candidates, which PeriodicPairs::rebuild takes over by key) (an entry whose key came
/// earlier, in an earlier source or the same one, wins; a wall group is kept whole from one source). The
/// rebuild of the contact lists must follow (it carries the history by key).
void adoptHistory(dem::World& world, std::span<const KeyedHistory> sources);

// ---

void exportPair(const dem::World& world, std::size_t a, KeyedHistory& out);
/// Periodic pair k (World::periodicPairs) as a pair entry: its history continues through the
/// candidates it is adopted into (PeriodicPairs::rebuild takes it from them by key).
void exportPeriodicPair(const dem::World& world, std::size_t k, KeyedHistory& out);
/// True if entry a of `h` may hold a contact (formed, or a non-zero spring where not kept).
inline bool mayBeFormed(const dem::ContactHistoryStore& h, std::size_t a)
{
    return h.keepFormed && h.formed.size() == h.spring.size() ? h.formed[a] != 0
                                                              : lengthSquared(h.spring[a]) > 0;
}
void exportWallSlot(const dem::World& world, std::size_t k, KeyedHistory& out);

template <class Take> void exportHistory(const dem::World& world, Take&& take, KeyedHistory& out)
{
    const dem::NeighborList& list = world.neighbors;
    const dem::ContactHistoryStore& h = world.pairHistory;
    for (std::size_t a = 0; a < list.activeFirst.size() && a < h.size(); ++a)
        if (mayBeFormed(h, a) && (take(list.activeFirst[a]) || take(list.activeSecond[a])))
            exportPair(world, a, out);
    const dem::PeriodicPairs& periodic = world.periodicPairs;
    for (std::size_t k = 0; k < periodic.size() && k < periodic.history.size(); ++k)
        if (mayBeFormed(periodic.history, k) && (take(periodic.first[k]) || take(periodic.second[k])))
            exportPeriodicPair(world, k, out);
    const dem::WallContactList& walls = world.wallContacts;
    for (std::size_t k = 0; k < walls.particle.size() && k < world.wallHistory.size(); ++k)
        if (take(walls.particle[k]))
            exportWallSlot(world, k, out);
}

} // namespace veridem::distributed
