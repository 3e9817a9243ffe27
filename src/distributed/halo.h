// A rank's particles after a decomposition (distributed/bisection.h): the ones it owns, then ghost copies
// of the other ranks' particles that can touch them (distributed/exchange_plan.h), in one ParticleStore,
// and the three exchanges a distributed step needs (docs/architecture.md, "MPI"):
//   - exchangeParticles, at a decomposition or a rebuild of the contact lists: particles that left
//     the rank's region migrate to their owner with their whole row (113 bytes: every array of the
//     store but force and torque, which are added between steps: 161 bytes), and the ghosts are
//     made afresh (113 bytes);
//   - refreshGhosts, every step after the drift: each ghost's position, velocity and angular
//     velocity from its owner, 72 bytes a ghost;
//   - returnGhostForces, every step after the pair stage: the force and torque a rank summed on
//     its ghosts go back and are added to the owners' sums, 48 bytes a ghost.
//
// Order. Owned particles keep their order (the ones that stay, then the ones that arrived, by
// sending rank and then the sender's order); ghosts come by sending rank, each rank's in its own
// slot order. The shares returned to an owner are added in ascending rank order. So a fixed rank
// count and decomposition give the same bits on every run; another rank count gives another
// order of the particles and of the sums (docs/architecture.md).
//
// Halo width. A ghost goes to each rank whose region comes within r_i + halo of it, halo =
// r_max + skin + touch reach (exchange_plan.h): the ghosts then hold every partner of a contact of
// an owned particle until the next rebuild of the contact lists, when exchangeParticles runs
// again.
#pragma once

#include "dem/particles.h"
#include "distributed/bisection.h"
#include "distributed/collective.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace veridem::distributed
{

/// Bytes a particle's row takes as a new ghost: id, material, fixed flag, position, velocity,
/// angular velocity, radius, mass, 1/mass, 1/inertia.
inline constexpr std::size_t kRowBytes = 4 + 4 + 1 + 9 * 8 + 4 * 8;
/// Bytes a migrant's row takes between steps: a ghost's, then its force and torque (the step's
/// totals, which the next kick-drift reads).
inline constexpr std::size_t kMigrantBytes = kRowBytes + 6 * 8;
/// Bytes a ghost's motion takes (refreshGhosts): position, velocity, angular velocity.
inline constexpr std::size_t kMotionBytes = 9 * 8;
/// Bytes a ghost's force and torque take (returnGhostForces).
inline constexpr std::size_t kForceBytes = 6 * 8;

/// Appends particle i's row to `out` (kRowBytes; with `withForce`, kMigrantBytes: its force and
/// torque too).
void putParticleRow(std::vector<std::byte>& out, const dem::ParticleStore& p, std::size_t i, bool withForce);
/// Appends the rows in `in` (sent by rank `from`, each with force and torque if `withForce`, else
/// with zero ones) to the store; returns how many. A size that is not a whole number of rows is a
/// SimulationError naming the rank.
std::size_t addParticleRows(std::span<const std::byte> in, dem::ParticleStore& p, int from, bool withForce);

struct Halo
{
    std::size_t owned = 0; // the store's first `owned` particles are this rank's; the rest ghosts
    /// Per rank b: the owned particles (store indices) whose ghost b holds, in b's ghost order.
    std::vector<std::vector<std::uint32_t>> sent;
    /// Per rank a: the store index of a's first ghost and how many there are (a's order).
    std::vector<std::size_t> ghostFirst, ghostCount;
    /// Bytes this rank sent at the last exchangeParticles (migrants and ghost rows).
    std::uint64_t bytesSent = 0;

    std::size_t ghosts() const;
    /// The ranks this one exchanges ghosts with (sends to or receives from).
    int neighbours() const;
};

/// Migrates the store's particles to their owners under `d` and makes the ghosts afresh (file
/// comment). On entry the store holds this rank's particles (owned or not, ghosts dropped: pass
/// the previous Halo's owned count in `keep`); on return it holds the owned ones, then the
/// ghosts. halo [m] > 0. `betweenSteps`: the force and torque rows are the step's totals, which
/// the next kick-drift reads, and migrants carry them (kMigrantBytes); inside a step (after the
/// kick-drift) they arrive zero, as the pair stage expects of the rows it does not zero (a rank
/// whose previous step was fused left its own rows zero, while its neighbour's may hold sums).
/// Collective.
Halo exchangeParticles(dem::ParticleStore& p, std::size_t keep, const Decomposition& d, Real halo,
                       const Collective& comm, bool betweenSteps = false);

/// The Halo of rank `me` when every rank holds every particle (all read the same scene or
/// checkpoint): the store keeps the particles `d` gives this rank, in their order, then the ghosts
/// of each other rank's, by rank and in the store's order: the layout exchangeParticles would
/// make from that start, with no message. Rows are kept whole (force and torque included).
Halo splitWholeStore(dem::ParticleStore& p, const Decomposition& d, Real halo, int me);

/// Copies each ghost's position, velocity and angular velocity from its owner. Collective.
void refreshGhosts(dem::ParticleStore& p, const Halo& h, const Collective& comm);

/// The ghosts' motion as their owners hold it now, written at the ghosts' slots of `position` (if
/// not null), `velocity` and `angularVelocity` (arrays of the store's size); refreshGhosts with
/// the store's own arrays. Collective.
void ghostMotion(const dem::ParticleStore& p, const Halo& h, const Collective& comm, Vec3* position,
                 Vec3* velocity, Vec3* angularVelocity);

/// Adds the force and torque summed on each ghost to its owner's sums (ascending sending rank)
/// and zeroes the ghosts' sums. Collective.
void returnGhostForces(dem::ParticleStore& p, const Halo& h, const Collective& comm);

} // namespace veridem::distributed
