// The whole world of a distributed run on one rank, for output and checkpoints (issue: output and
// checkpoints on any rank count): every rank's owned particles, ordered by id, with their contact
// history keyed by id (distributed/rank_history.h), the contact lists rebuilt, and each wall slot's load
// as the owner of its particle recorded it in the step. So the recorders and the checkpoint writer
// of one process (src/io/) run unchanged on it, and a checkpoint written on N ranks is one a run on
// any number of ranks restores (RankStep::distribute after readDemCheckpoint).
#pragma once

#include "dem/world.h"
#include "distributed/rank_step.h"

#include <optional>

namespace veridem::distributed
{

/// A world with no particles and `local`'s walls, materials, pair table, domain, time, skin and
/// touch reach (the state every rank shares), for a world of other particles (the gathered
/// world, the inserters' probe: distributed/rank_flow.h).
dem::World worldLike(const dem::World& local);

/// `root` for a gather whose result every rank gets.
inline constexpr int kEveryRank = -1;

/// On rank `root` (every rank with kEveryRank): a world holding `local`'s state that every rank
/// shares (walls, materials, pair table, time, step count, skin and reach, gravity), every rank's
/// owned particles by id (rows whole, force and torque included), their contacts' history, their
/// bonds with the bond counts (distributed/rank_bonds.h), and
/// the wall loads (with recordLoads); lists rebuilt, not distributed (world.ranks null).
/// Elsewhere: nullopt. Collective. O(N) on each receiving rank.
std::optional<dem::World> gatherWorld(const dem::World& local, const RankStep& ranks, int root = 0);

/// On rank `root`: the owned particles of every rank whose centre lies in the box [lo, hi] [m]
/// (rows whole), by rank and in each rank's order; elsewhere an empty store. Collective.
dem::ParticleStore gatherParticlesIn(const dem::ParticleStore& local, std::size_t owned, const Vec3& lo,
                                     const Vec3& hi, const Collective& comm, int root = 0);

/// Every rank gets `rows` as rank `root` holds them (the other ranks' argument is ignored).
/// Collective.
dem::ParticleStore broadcastParticles(const dem::ParticleStore& rows, const Collective& comm, int root = 0);

} // namespace veridem::distributed
