// The DEM world: particles, walls, materials, contacts, and the step.
#pragma once

#include "core/vec3.h"
#include "dem/bonds/bond_set.h"
#include "dem/contact_history.h"
#include "dem/exec/block_partition.h"
#include "dem/materials.h"
#include "dem/neighbor_list.h"
#include "dem/particles.h"
#include "dem/periodic.h"
#include "dem/wall_contacts.h"
#include "dem/walls/wall.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace veridem::dem
{

/// Health of the last force evaluation, checked by the driver after each step.
struct StepHealth
{
    Real maxOverlapRatio = 0;         // max over contacts of overlap / smaller radius [-]
    std::uint32_t worstParticle = 0;  // particle with that overlap
    std::size_t touchingPairs = 0;    // particle pairs in contact
    std::size_t touchingWalls = 0;    // particle-wall contacts
    bool finite = true;               // all positions and velocities finite
    std::uint32_t firstNonFinite = 0; // first particle that is not
};

/// Contact health of one chunk of particles or run of blocks (combined in their order:
/// mergeWallHealth, the pair stage).
struct ContactHealth
{
    Real maxOverlapRatio;        // largest overlap / radius in the chunk [-]
    std::uint32_t worstParticle; // its particle (the first in slot order on ties)
    bool found;                  // some contact of the chunk touched
    std::size_t touching;        // contacts touching
};

/// Wall-clock time spent in each stage of step() [s], accumulated while `enabled` (off by
/// default: reading the clock costs ~20 ns a stage, which a one-ball run would notice).
struct StepProfile
{
    bool enabled = false;
    double integration = 0;  // kick-drift (in advance(), only its first step's), wall motion
    double neighbours = 0;   // rebuild test + Verlet list rebuild + history merge
    double pairForces = 0;   // pair contacts, summed within blocks (stage 3)
    double particlePass = 0; // cross-block sums, wall contacts, kick (stage 4; in advance(), also the
                             // next step's kick-drift)
    // With more than one thread: each thread's busy time in the two parallel stages [s], by thread
    // (chunk) index; threads beyond kThreads are not recorded. A stage's wall time above its
    // busiest thread's is its serial part and the cost of entering and leaving the parallel
    // region; threads far apart in busy time mean one ran slower (a shared core) or had more work.
    static constexpr int kThreads = 8;
    std::array<double, kThreads> pairBusy{}, particlePassBusy{};
};

/// Adds the wall-clock time of its scope to `busy[thread]` if the profile is enabled (a thread's
/// part of a parallel stage; see StepProfile).
class ThreadBusyTimer
{
  public:
    ThreadBusyTimer(const StepProfile& profile, std::array<double, StepProfile::kThreads>& busy, int thread)
        : slot_(profile.enabled && thread < StepProfile::kThreads ? &busy[static_cast<std::size_t>(thread)]
                                                                  : nullptr)
    {
        if (slot_)
            start_ = std::chrono::steady_clock::now();
    }
    ~ThreadBusyTimer()
    {
        if (slot_)
            *slot_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    ThreadBusyTimer(const ThreadBusyTimer&) = delete;
    ThreadBusyTimer& operator=(const ThreadBusyTimer&) = delete;

  private:
    double* slot_;
    std::chrono::steady_clock::time_point start_;
};

/// Which thread evaluates which block of the pair stage (block_partition.h), balanced by touching
/// candidates, a cross-block one counting three, in proportion to each thread's measured speed
/// (exec/pair_schedule.h, scheduleBlocks and adaptSchedule); recomputed when the candidate sub-list, the
/// slots or the thread count change, and moved when the speeds predict a shorter stage.
struct PairSchedule
{
    std::vector<BlockRun> runs;
    int chunks = 0;
    std::size_t subListRebuilds = 0, slotRebuilds = 0, particles = 0; // what it was made for
    double heaviestShare = 0;             // the busiest thread's share of the candidates [-]
    std::vector<ContactHealth> runHealth; // per block, written by the thread that evaluated it
    std::vector<std::uint64_t> weight;    // per block: its weight (touching candidates) [-]
    std::vector<double> speed;            // per thread: weight per second on its run, a running mean
                                          // over ~16 steps [1/s] (0: not measured yet)
    std::vector<BlockRun> proposal;       // adaptSchedule's work space (no allocation per step)
    std::uint64_t moves = 0;              // times the split moved after the speeds, in all
    bool adapt = true;                    // false: the speeds are not measured (a split by weight
                                          // alone, or by `speed` if set; tests)
};

/// How stage 4 (cross-block sums, walls, kicks: world.cpp, finishParticles) shares the particles
/// among threads: in contiguous parts in proportion to each thread's measured rate there
/// (equal parts until every thread has been timed). Its work per particle differs from the pair
/// stage's (walls, cross-block entries), so it is balanced on its own.
struct PassSchedule
{
    std::vector<double> speed; // per thread: particles per second in stage 4, a running mean over
                               // ~16 steps [1/s] (0: not measured yet)
    bool adapt = true;         // false: the speeds are not measured (equal parts, or by `speed` if
                               // set; tests)
};

struct World;

/// A distributed run's part in the step (distributed/rank_step.h): each MPI rank steps the particles it
/// owns plus ghost copies of the others' near its region, and the step calls this at two points.
/// The physics stays in the stages; this only moves particles and combines decisions.
class RankExchange
{
  public:
    virtual ~RankExchange() = default;
    /// After the kick-drift and the wall motion: the ghosts take their owners' motion, and the
    /// ranks decide together whether the contact lists are rebuilt this step (`rebuild`: this
    /// rank's own criterion). Returns that decision; when true, the particles have been exchanged
    /// (migrants with their contact history, ghosts made afresh) and step() rebuilds the lists.
    virtual bool afterDrift(World& world, bool rebuild) = 0;
    /// After the step: `health` becomes the health of all ranks' particles (the largest overlap,
    /// finite everywhere), so that every rank stops at the same step.
    virtual void combineHealth(World& world) = 0;
    /// The store's first ownedParticles() are this rank's own; the rest are ghosts.
    virtual std::size_t ownedParticles() const = 0;
    /// For an observer after the step (the energy ledger): copies of the store's velocities and
    /// angular velocities [m/s, rad/s] whose ghosts hold their owners' v(t+dt), w(t+dt) (a ghost's
    /// own are not kicked with its whole force; the world is left as it is). Collective.
    virtual void velocitiesAfterStep(const World& world, std::vector<Vec3>& velocity,
                                     std::vector<Vec3>& angularVelocity) = 0;
};

/// Sees every step (an energy ledger, energy_ledger.h): beforeForces in the step's state after
/// the kick-drift, the wall motion and the contact lists' update, just before the force stage
/// (x(t+dt), v(t+dt/2), the history of t); afterStep once the step is complete (v(t+dt)). With an
/// observer, step() takes the general path and advance() runs step() by step() (no fused kicks).
/// An observer reads the world and never changes it, so the bits do not depend on it.
class StepObserver
{
  public:
    virtual ~StepObserver() = default;
    virtual void beforeForces(const World& world, Real dt) = 0; // dt [s]
    virtual void afterStep(const World& world, Real dt) = 0;
};

/// How the step is executed, with no physics in it: which kernels and step paths run, how the
/// threads share the work, and the stage timers. It never changes a bit of the result (the
/// Determinism tests), so it is not saved in a checkpoint.
struct Execution
{
    bool batchedContactKernel = true; // four contacts at a time where the law allows (same bits as
                                      // the scalar path, which false selects; pair_kernel.h)
    // The fused step paths (world.cpp): one particle's step with its state in registers, and
    // advance()'s closing kick fused with the next step's kick-drift. Same bits either way; false
    // runs the general stages, to measure what the fusion pays (veridem_bench --no-fusion).
    bool fusedSteps = true;
    PairSchedule pairSchedule;
    PassSchedule passSchedule;
    StepProfile profile;
};

/// The physical state of a DEM run (particles, walls, materials, contacts and their history,
/// time) and, beside it, how the step is executed (`exec`).
struct World
{
    ParticleStore particles;
    std::vector<Wall> walls;
    std::vector<Material> materials;
    PairTable pairs;
    NeighborList neighbors;       // pair slots and touching candidates (the keys of pairHistory)
    WallContactList wallContacts; // particle-wall slots (the keys of wallHistory)
    // The contacts' history, updated by the force stage (dem/contact_history.h): entry a of
    // pairHistory is touching candidate a's, entry k of wallHistory wall slot k's.
    ContactHistoryStore pairHistory{true};
    ContactHistoryStore wallHistory;
    // Periodic boundaries (dem/periodic.h): the box and its periodic axes, and the pairs touching
    // through a periodic image, with their history. With no periodic axis both stay empty and the
    // step runs exactly as it would without the feature.
    PeriodicDomain domain;
    PeriodicPairs periodicPairs;
    // The frozen particles (ParticleStore::fixed) by index, and where they are held [m]; filled by
    // refreshFixedParticles(). Empty: the step runs exactly as it would without the feature.
    std::vector<std::uint32_t> fixedIndex;
    std::vector<Vec3> fixedHome;
    Vec3 gravity{0, 0, -9.81}; // [m/s^2]
    Real time = 0;             // [s]
    std::uint64_t stepCount = 0;
    StepHealth health;
    Execution exec;
    bool prepared = false;
    StepObserver* observer = nullptr; // not owned; null: none
    RankExchange* ranks = nullptr;    // not owned; null: one process holds every particle
    // Bonded particles (dem/bonds/bond_set.h): not `enabled` (the default), the step runs none of it.
    BondSet bonds;

    /// Adds a material; returns its id.
    std::uint32_t addMaterial(const Material& m);
    std::uint32_t materialId(const std::string& name) const; // throws InputError if unknown
};

/// The neighbour skin [m] prepare() gives a world that sets none (NeighborList::skin <= 0): 4 r_max
/// below 64 particles, else 0.2 r_max.
Real defaultSkin(const World& world);

/// Mixes the pair table, builds the neighbour list and computes the initial forces. Called by the
/// first step() if not called before; call again after adding particles, walls or materials.
void prepare(World& world);

/// Lists the frozen particles (World::fixedIndex, fixedHome) from ParticleStore::fixed and the
/// current positions, and tells the neighbour list whether a pair may have one (prepare(), a
/// checkpoint restore, particlesChanged()).
void refreshFixedParticles(World& world);

/// After particles were added or removed between steps (dem/particle_changes.h): the frozen
/// particles listed again, the touch reach for the materials now present, and both contact lists
/// rebuilt (their history carried by key).
void rebuildAfterParticleChange(World& world);

/// Rebuilds the pair and wall contact lists at the current positions, the history carried by key:
/// what a step does when some particle moved more than skin/2, and what follows an MPI exchange of
/// particles (distributed/rank_step.h).
void rebuildContactLists(World& world);

/// Advances the world by dt [s] with velocity Verlet (see world.cpp for the stages).
void step(World& world, Real dt);

/// Advances the world by `steps` steps of dt [s]: the same operations and bits as `steps` calls of
/// step(), but each step's closing half kick and the next step's kick-drift run as one pass over
/// the particles (one load and store of their rows instead of two; one parallel region fewer).
/// For runs that look at the world only every so many steps. Stops early after a step whose
/// health is bad: some state not finite, or world.health.maxOverlapRatio > maxOverlapRatio [-];
/// then world.health describes that step, but the particles have already had the next step's
/// first half kick and drift (the state is fit only for reporting the failure). Returns the
/// steps done.
std::uint64_t advance(World& world, Real dt, std::uint64_t steps,
                      Real maxOverlapRatio = std::numeric_limits<Real>::infinity());

/// Kinetic energy, translational + rotational [J], of the store's first `count` particles (all by
/// default; on an MPI rank, ownedParticles(): its own).
Real kineticEnergy(const World& world, std::size_t count = std::numeric_limits<std::size_t>::max());

/// The two parts of the kinetic energy, each summed over the particles in index order [J].
struct KineticEnergyParts
{
    Real translational = 0; // sum of m v^2 / 2
    Real rotational = 0;    // sum of I w^2 / 2
};
KineticEnergyParts kineticEnergyParts(const World& world);

} // namespace veridem::dem
