// A rank's part of a distributed DEM run (`mpirun -np N veridem run SCENE`; docs/architecture.md,
// "MPI"). Each rank holds a dem::World whose store is the particles it owns, then ghost copies of
// the other ranks' particles within the halo of its region (distributed/halo.h), and runs the ordinary
// step on it: the pair stage finds every contact of an owned particle among its owned particles
// and ghosts, and evaluates a contact between an owned particle and a ghost on both ranks (each
// keeps its own share: no forces travel). The step calls RankStep at two points (dem::RankExchange):
//   - after the kick-drift, the ghosts take their owners' motion (refreshGhosts), and the ranks
//     decide together whether the contact lists are rebuilt (the largest of their criteria). At a
//     rebuild the particles are exchanged: those that left the region migrate with their pair and
//     wall contact history keyed by global ids (distributed/rank_history.h), the ghosts are made afresh,
//     and every `rebalanceEvery`-th time the regions are first cut again by recursive bisection
//     of the particles weighted by their contacts (distributed/bisection.h), so the regions follow a pour
//     or a draining silo;
//     with [bonds], a migrant's bonds go with it too and the halo covers the bonds' reach
//     (distributed/rank_bonds.h);
//   - after the step, the ranks combine their health, so that every rank stops at the same step.
//
// Bits. On a given rank count a run gives the same bits every time and on any thread count (each
// rank's sums have a fixed order, the exchanges a fixed order by rank). Another rank count gives
// another order of each particle's contact sum, so its results differ at round-off
// (docs/architecture.md; measured in tests/distributed/mpi_step_check.cpp).
#pragma once

#include "dem/world.h"
#include "distributed/bisection.h"
#include "distributed/collective.h"
#include "distributed/halo.h"

#include <cstdint>
#include <span>

namespace veridem::distributed
{

class RankStep final : public dem::RankExchange
{
  public:
    /// `rebalanceEvery` >= 1: exchanges from one cut of the regions to the next.
    RankStep(const Collective& comm, std::uint64_t rebalanceEvery = 10);

    /// Keeps this rank's part of a world that every rank holds whole and identical (read from the
    /// same scene, or restored from one checkpoint): the regions cut, the store reduced to the
    /// owned particles and their ghosts (rows whole). A world not prepared is then prepared (only
    /// this part: its lists and initial forces; the skin and touch reach set from all the
    /// particles); a prepared or restored one takes in its contact history keyed by id and
    /// rebuilds its lists. Sets world.ranks. Collective.
    void distribute(dem::World& world);

    bool afterDrift(dem::World& world, bool rebuild) override;

    /// Between steps: the particles `arrivals` (every rank passes the same rows, e.g. those an
    /// inserter made) join the ranks whose regions hold them, with an exchange of particles (the
    /// ones that left their region migrate, retired ones leave) and a rebuild of the contact
    /// lists. Collective.
    void admit(dem::World& world, const dem::ParticleStore& arrivals);
    /// r_max + skin + touch reach [m]: how far from a region its ghosts reach.
    Real haloWidth() const { return haloWidth_; }
    void combineHealth(dem::World& world) override;
    std::size_t ownedParticles() const override { return halo_.owned; }
    void velocitiesAfterStep(const dem::World& world, std::vector<Vec3>& velocity,
                             std::vector<Vec3>& angularVelocity) override;

    /// After a step whose combined health is bad: the id of the particle it names (the first
    /// non-finite one, else the one with the largest overlap; the lowest id on a tie). Collective.
    std::uint32_t failedParticleId(const dem::World& world) const;

    /// This rank's owned particles: the store's first owned().
    std::size_t owned() const { return halo_.owned; }
    const Halo& halo() const { return halo_; }
    const Decomposition& decomposition() const { return decomposition_; }
    const Collective& comm() const { return comm_; }
    /// Exchanges of particles so far (one per rebuild of the contact lists) and cuts of the regions.
    std::uint64_t exchanges() const { return exchanges_; }
    std::uint64_t cuts() const { return cuts_; }
    /// Bytes this rank sent in exchanges of particles and history, and in ghost refreshes [B].
    std::uint64_t exchangeBytes() const { return exchangeBytes_; }
    std::uint64_t refreshBytes() const { return refreshBytes_; }
    /// Wall time this rank spent in its exchanges so far [s]: the ghost refreshes, the rebuild
    /// decision and the health (each a collective: the waits for slower ranks included), and the
    /// exchanges of particles with their history (and the cuts).
    struct Times
    {
        double refresh = 0, decision = 0, health = 0, exchange = 0;
    };
    const Times& times() const { return times_; }

  private:
    void cut(const dem::World& world, std::span<const std::uint8_t> gone);
    /// The exchange of particles at a rebuild; `arrivals` (may be null: inside a step): rows that
    /// join the ranks whose regions hold them, between steps (admit), when migrants carry their
    /// force and torque (exchangeParticles' betweenSteps).
    void exchange(dem::World& world, const dem::ParticleStore* arrivals = nullptr);

    const Collective& comm_;
    std::uint64_t rebalanceEvery_;
    Decomposition decomposition_;
    Halo halo_;
    Real haloWidth_ = 0; // r_max + skin + touch reach [m]
    std::uint64_t exchanges_ = 0, cuts_ = 0, exchangeBytes_ = 0, refreshBytes_ = 0;
    Times times_;
    // This rank's own health of the last step (combineHealth), for failedParticleId.
    Real localRatio_ = 0;
    std::uint32_t localWorst_ = 0, localFirstNonFinite_ = 0;
    bool localFinite_ = true;
};

} // namespace veridem::distributed
