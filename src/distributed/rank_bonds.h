// Bonds (dem/bonds/bond_set.h) on several MPI ranks (docs/architecture.md, "MPI"). A rank holds
// every bond with a partner it owns; a partner owned elsewhere is a ghost here, whose position,
// velocity and angular velocity are its owner's bits (refreshGhosts) and whose radius, mass and
// inertia came with its row, so the two ranks holding a bond advance its state to the same bits
// and break it at the same step; each adds the loads to its own partner only (no force travels).
//
//   halo      the ghosts must hold every bond partner of an owned particle until the next
//             exchange: bondHalo widens the halo to r_max + gap + skin + the largest stretch
//             (sigma_c / kn, the strain of an intact bond's normal stress alone; without a
//             tensile strength, kOverstretch of the longest rest length); a bond whose partner is
//             beyond it all the same (a weak bond pulled far without breaking) stops the run with
//             an error naming it, at the exchange that finds it.
//   exchange  at each exchange of particles (RankStep::exchange) a migrant's bonds go with it to
//             its new owner, like its contact history (distributed/rank_history.h): routeBonds,
//             before the store changes, sends each bond to the new owners of the partners this
//             rank owns (a copy from each holder: identical, the first kept), and drops the bonds
//             of particles an outlet removed (known to all ranks first); adoptBonds, after,
//             takes them in and indexes them.
//   counts    formed, broken, dropped, overstretched: each rank counts the events of the bonds
//             whose lower-id partner it owns (dem::countsBond); gatherBonds sums them (and takes
//             the largest strain) with each bond once, for the outputs, the checkpoint and the
//             run summary.
#pragma once

#include "dem/bonds/bond_set.h"
#include "distributed/collective.h"

#include <cstddef>
#include <optional>
#include <span>

namespace veridem::distributed
{

/// Bytes a bond takes in an exchange (its ids, cached indices and state, as in a checkpoint).
inline constexpr std::size_t kBondBytes = sizeof(dem::Bond);

/// The halo width [m] a rank's bonds need, particles of radius up to `largestRadius` [m] and a
/// neighbour list skin [m] (file comment); 0 without bonds.
Real bondHalo(const dem::BondSet& set, Real largestRadius, Real skin);

/// On a world every rank holds whole (RankStep::distribute, before the split): drops the bonds
/// whose partner is gone from the store (an outlet removed it), counted as dropped by the first
/// rank (`firstRank`), which keeps the restored totals while the others start from zero.
void startBondCounts(dem::BondSet& set, const dem::ParticleStore& p, bool firstRank);

/// Keeps the bonds with a partner among the store's first `owned`, in their order, each indexed
/// in the store; a partner not in it (beyond the halo) is a SimulationError naming the bond.
void keepOwnedBonds(dem::BondSet& set, const dem::ParticleStore& p, std::size_t owned);

/// At an exchange, before the store changes: dest[i], the rank that owns the store's owned
/// particle i next (-1: it leaves, retired). Drops the bonds of leaving particles (on every rank:
/// collective), keeps the ones that stay here and returns for each other rank the bonds it
/// receives. Collective.
Buffers routeBonds(dem::BondSet& set, const dem::ParticleStore& p, std::span<const int> dest,
                   const Collective& comm);

/// After the exchange of particles: the bonds `in` brings (from each rank) join the ones kept (a
/// bond already held is not taken twice), then keepOwnedBonds.
void adoptBonds(dem::BondSet& set, const dem::ParticleStore& p, std::size_t owned, const Buffers& in);

/// On rank `root` (every rank with a negative one: rank_gather.h's kEveryRank): the bonds of every
/// rank, each once, ordered by their partners' ids (their cached indices left as they are: index
/// them in a gathered store with keepOwnedBonds), with the counts summed and the largest strain;
/// elsewhere nullopt. Collective.
std::optional<dem::BondSet> gatherBonds(const dem::BondSet& set, const dem::ParticleStore& p,
                                        std::size_t owned, const Collective& comm, int root);

} // namespace veridem::distributed
