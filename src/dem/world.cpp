// (Above 500 lines: the general step, the one-particle step and advance() share their stages'
// helpers here, so that the three paths can be read side by side with the same operations.)
//
// The step, read top to bottom (velocity Verlet, LAMMPS/Box2D style):
//
//   kick-drift     v(t+dt/2) = v(t) + dt/2 a(t);  w likewise;  x(t+dt) = x(t) + dt v(t+dt/2),
//                  measuring each particle's displacement since the lists were built
//   walls          prescribed motion to t + dt
//   neighbours     rebuild the Verlet and wall-contact lists if some particle moved more than
//                  skin/2 (or a wall translated more than skin/2)
//   pairs          pair contact forces at x(t+dt) from the half-step velocities, summed into
//                  the particles block by block (parallel over fixed blocks of particles)
//   bonds          only in a scene with [bonds]: each intact bond's force and torque into both
//                  particles, one thread, in bond order (dem/bonds)
//   particles      one pass per particle: its contacts with earlier blocks, then its wall
//                  contacts (each in slot order: every sum has a fixed order, the same bits for
//                  any number of threads, STYLE 3.4; neighbor_list.h), then the kick
//                  v(t+dt) = v(t+dt/2) + dt/2 a(t+dt);  w likewise
//
// The dashpots and the tangential-spring increment use the half-step velocities: the spring
// increment vt dt is then exactly the relative displacement over [t, t+dt]. Output never happens
// here; the driver records the world between steps. Frozen particles (World::fixedIndex) are put
// back at rest after the kick-drift and after the kick (holdFixedParticles).
//
// Two fused paths run these stages with the same operations and bits, each kept because it pays
// (figures in docs/performance.md; Execution::fusedSteps = false turns both off to measure them): a
// world of one particle takes stepOneParticle, the ball's state kept in registers; advance() runs
// each step's closing kick and the next step's kick-drift as one pass over the particles.
#include "dem/world.h"

#include "core/error.h"
#include "core/release_free_memory.h"
#include "dem/contact_law.h"
#include "dem/forces.h"
#include "dem/integrate.h"
#include "dem/lanes.h"
#include "dem/particle_changes.h"
#include "exec/isa.h"

#include <algorithm>
#include <chrono>
#include <cstring>

namespace veridem::dem
{

std::uint32_t World::addMaterial(const Material& m)
{
    validateMaterial(m);
    for (const auto& existing : materials)
        if (existing.name == m.name)
            throw InputError("material '" + m.name + "' is defined twice");
    materials.push_back(m);
    prepared = false;
    return static_cast<std::uint32_t>(materials.size() - 1);
}

std::uint32_t World::materialId(const std::string& name) const
{
    for (std::size_t i = 0; i < materials.size(); ++i)
        if (materials[i].name == name)
            return static_cast<std::uint32_t>(i);
    std::string known;
    for (const auto& m : materials)
        known += (known.empty() ? "" : ", ") + m.name;
    throw InputError("unknown material '" + name + "' (defined: " + known + ")");
}

namespace
{

/// Below this many particles the default neighbour skin is 4 r_max instead of 0.2 r_max.
constexpr std::size_t kSmallWorld = 64;

/// Adds the time since the previous lap to one StepProfile field, when profiling is enabled.
class StageClock
{
  public:
    explicit StageClock(StepProfile& profile) : profile_(profile)
    {
        if (profile_.enabled)
            last_ = std::chrono::steady_clock::now();
    }
    void lap(double StepProfile::*stage)
    {
        if (!profile_.enabled)
            return;
        const auto now = std::chrono::steady_clock::now();
        profile_.*stage += std::chrono::duration<double>(now - last_).count();
        last_ = now;
    }

  private:
    StepProfile& profile_;
    std::chrono::steady_clock::time_point last_;
};

VERIDEM_HOT_INLINE bool contactListsNeedRebuild(World& world, const Motion& moved)
{
    return world.neighbors.checkMotion(world.particles.size(), moved.sinceBuild2, moved.sinceActiveBuild2) ||
           world.wallContacts.needsRebuild(world.walls, world.neighbors.skin);
}

Real pairTouchReach(const World& world);

} // namespace

[[gnu::noinline, gnu::cold]] void rebuildContactLists(World& world)
{
    if (removeRetiredParticles(world)) // (dem/particle_changes.h: they leave the store here)
    {
        refreshFixedParticles(world);
        world.neighbors.reach = pairTouchReach(world);
    }
    if (world.domain.any()) // positions wrapped into the box, the pairs through an image found
    {
        wrapParticles(world.domain, world.particles);
        world.periodicPairs.rebuild(world.domain, world.particles,
                                    world.neighbors.skin + world.neighbors.reach, world.neighbors.anyFixed,
                                    world.neighbors, world.pairHistory);
    }
    else if (!world.periodicPairs.empty()) // inserted particles' pairs (particle_changes.h): now slots
        world.periodicPairs.handOver(world.neighbors, world.pairHistory);
    world.neighbors.rebuild(world.particles, world.pairHistory);
    world.wallContacts.rebuild(world.particles, world.walls, world.neighbors.skin, world.wallHistory);
    // The rebuild's temporaries out of the resident set, in worlds where they weigh: malloc_trim
    // walks the whole process heap (every thread's arena, shared by verification cases run side
    // by side), and a world of a few particles rebuilds often and frees little.
    if (world.particles.size() >= kTrimAfterRebuildParticles)
        releaseFreeMemory();
}

namespace
{

/// Holds the frozen particles: back to their positions (and position rows) with zero velocity and
/// angular velocity, undoing what a kick or drift gave them (gravity, contact forces).
[[gnu::noinline]] void holdFixedParticles(World& world)
{
    ParticleStore& p = world.particles;
    for (std::size_t k = 0; k < world.fixedIndex.size(); ++k)
    {
        const std::uint32_t i = world.fixedIndex[k];
        p.position[i] = world.fixedHome[k];
        p.positionRadius[i] = p.positionRadiusRow(i);
        p.velocity[i] = Vec3{};
        p.angularVelocity[i] = Vec3{};
    }
}

/// Particles per sub-pass of stage 4: their forces, torques, velocities and wall contacts
/// (~200 B a particle) stay in L1/L2 between the three sub-passes (a whole chunk's do not).
constexpr std::size_t kFinishBlock = 512;

/// Stage 4 for the particles [begin, end), in sub-blocks of kFinishBlock while each one's data is
/// hot in cache: their cross-block pair contacts, their wall contacts (both in slot order), then
/// the final half kick v(t+dt) = v(t+dt/2) + dt/2 a(t+dt). Each particle's operations, and the
/// order of the health record, are those of one pass over the range. Returns the wall health and
/// sets `finite` to false if some state of the range is not finite. With `drift` (advance()), the
/// kick is followed by the next step's kick-drift (kickThenKickDrift), its motion from `drift`'s
/// reference folded into `motion`.
ContactHealth finishRange(World& world, Real dt, std::size_t begin, std::size_t end, bool lanes, bool& finite,
                          const NeighborList::MotionReference* drift, Motion& motion)
{
    ContactHealth health{0, 0, false, 0};
    finite = true;
    for (std::size_t s = begin; s < end; s += kFinishBlock)
    {
        const std::size_t e = std::min(s + kFinishBlock, end);
        // The wall particles' rows (cold since the pair stage) on their way while the
        // cross-block sums run: the wall pass waited on them.
        const WallContactList& wallList = world.wallContacts;
        if (wallList.start.size() == world.particles.size() + 1)
            for (std::size_t k = wallList.start[s]; k < wallList.start[e]; ++k)
            {
                const std::uint32_t i = wallList.particle[k];
                __builtin_prefetch(&world.particles.position[i]);
                __builtin_prefetch(&world.particles.velocity[i]);
                __builtin_prefetch(&world.particles.angularVelocity[i]);
            }
        addCrossBlockForces(world, s, e);
        const ContactHealth walls = computeWallForces(world, dt, s, e);
        addExternalLoads(world.particles, s, e);
        health.touching += walls.touching;
        if (walls.found && walls.maxOverlapRatio > health.maxOverlapRatio) // first of the largest
            health = {walls.maxOverlapRatio, walls.worstParticle, true, health.touching};
        finite = (drift ? kickThenKickDrift(world.particles, world.gravity, dt, *drift, s, e, lanes, motion)
                        : kick(world.particles, world.gravity, dt, s, e, lanes)) &&
                 finite;
    }
    return health;
}

/// The parts of stage 4: edge[c] .. edge[c + 1] for thread c (edge[chunks] = n), in proportion to
/// the threads' measured speeds, each edge a multiple of 64 particles (so that a jitter of the
/// speeds does not move rows between cores every step), or equal parts until all are measured.
void passEdges(PassSchedule& s, std::size_t n, int chunks, std::size_t* edge)
{
    if (s.speed.size() != static_cast<std::size_t>(chunks))
        s.speed.assign(static_cast<std::size_t>(chunks), 0.0);
    double total = 0;
    for (double v : s.speed)
        total = v > 0 && total >= 0 ? total + v : -1; // -1: some thread not measured yet
    constexpr std::size_t kGrain = 64;
    double before = 0;
    edge[0] = 0;
    for (int c = 1; c <= chunks; ++c)
    {
        if (c == chunks)
            edge[c] = n;
        else if (total > 0)
        {
            before += s.speed[static_cast<std::size_t>(c - 1)];
            const auto at = static_cast<std::size_t>(std::llround(static_cast<double>(n) * before / total /
                                                                  static_cast<double>(kGrain))) *
                            kGrain;
            edge[c] = std::clamp(at, edge[c - 1], n);
        }
        else
            edge[c] = chunkBegin(n, chunks, c);
    }
}

/// Folds each thread's stage-4 rate (its particles over its time `seconds[c]`) into the running
/// mean of its speed.
void updatePassSpeeds(PassSchedule& s, const std::size_t* edge, const double* seconds, int chunks)
{
    constexpr double kMix = 1.0 / 16; // weight of the newest step in the running mean
    for (int c = 0; c < chunks; ++c)
    {
        const std::size_t count = edge[c + 1] - edge[c];
        if (count == 0 || seconds[c] <= 0)
            continue;
        const double rate = static_cast<double>(count) / seconds[c];
        double& speed = s.speed[static_cast<std::size_t>(c)];
        speed = speed > 0 ? speed + kMix * (rate - speed) : rate;
    }
}

/// Stage 4, one pass over the particles, in chunks (one per thread); health is combined in
/// chunk order. `lanes`: the kick runs in AVX2 lanes. `driftNext` (advance()): the pass also runs
/// the next step's kick-drift and returns its motion (else zero motion).
Motion finishParticles(World& world, Real dt, bool lanes, bool driftNext)
{
    ParticleStore& p = world.particles;
    const std::size_t n = p.size();
    const int chunks = std::min(loopThreads(n), 64);
    const NeighborList::MotionReference reference = world.neighbors.motionReference(n);
    const NeighborList::MotionReference* const drift = driftNext ? &reference : nullptr;
    Motion motion;
    if (chunks == 1 && n <= kFinishBlock && !drift) // a few balls: the three calls, nothing else
    {
        addCrossBlockForces(world, 0, n);
        const ContactHealth walls = computeWallForces(world, dt, 0, n);
        addExternalLoads(p, 0, n);
        mergeWallHealth(world.health, &walls, 1);
        world.health.finite = kick(p, world.gravity, dt, 0, n, lanes);
    }
    else if (chunks == 1) // no parallel region, no chunk arrays
    {
        bool finite = true;
        const ContactHealth walls = finishRange(world, dt, 0, n, lanes, finite, drift, motion);
        mergeWallHealth(world.health, &walls, 1);
        world.health.finite = finite;
    }
    else
    {
        ContactHealth walls[64]{}; // (zeroed: GCC cannot see that chunks <= 64 entries are written)
        bool finite[64]{};
        Motion moved[64];
        // Each thread finishes a contiguous part of the particles, in proportion to its measured
        // rate (PassSchedule; any split gives the same bits).
        std::size_t edge[65];
        passEdges(world.exec.passSchedule, n, chunks, edge);
        double seconds[64] = {};
        parallelChunks(
            static_cast<std::size_t>(chunks), chunks,
            [&](int c, std::size_t, std::size_t)
            {
                const ThreadBusyTimer busy(world.exec.profile, world.exec.profile.particlePassBusy, c);
                const auto start = std::chrono::steady_clock::now();
                walls[c] = finishRange(world, dt, edge[c], edge[c + 1], lanes, finite[c], drift, moved[c]);
                seconds[c] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            });
        if (world.exec.passSchedule.adapt)
            updatePassSpeeds(world.exec.passSchedule, edge, seconds, chunks);
        mergeWallHealth(world.health, walls, chunks);
        world.health.finite = std::all_of(finite, finite + chunks, [](bool b) { return b; });
        for (int c = 0; c < chunks; ++c) // a maximum: the same for any chunking
            motion = {std::max(motion.sinceBuild2, moved[c].sinceBuild2),
                      std::max(motion.sinceActiveBuild2, moved[c].sinceActiveBuild2)};
    }
    if (!world.health.finite)
        recordFirstNonFinite(p, world.health);
    return motion;
}

/// True if the integration loops run in AVX2 lanes (integrate.cpp, the same bits as the scalar
/// loops): the lane kernels are on (Execution::batchedContactKernel), the variant in use is "avx2",
/// and there are at least four particles (one ball keeps the scalar loop).
bool integrationInLanes(const World& world)
{
    return world.particles.size() >= 4 && world.exec.batchedContactKernel && exec::isAvx2();
}

/// step() for a world of one particle (a single-ball verification run): the same stages in the
/// same order with the same operations, so the same bits, but the particle's state stays in
/// registers from the kick-drift to the kick instead of being stored by one stage and loaded by
/// the next (2.1x the steps per second of the general stages; docs/performance.md). A single
/// particle has no pair slots, so the pair stage only resets the pair health.
void stepOneParticle(World& world, Real dt)
{
    ParticleStore& p = world.particles;
    ParticleState s = particleState(p, 0);
    const Real invMass = p.invMass[0];
    const Vec3 gravity = world.gravity;
    kickDriftOne(s.position, s.velocity, s.angularVelocity, p.force[0], p.torque[0], invMass, s.invInertia,
                 gravity, dt);
    p.position[0] = s.position;
    p.velocity[0] = s.velocity;
    p.angularVelocity[0] = s.angularVelocity;
    // The motion since the full build, as kickDriftRange measures it. Not the motion since the
    // candidate sub-list was built: one particle has no pair slots, so that sub-list is empty and
    // left as it is (a rebuild, which a second particle would force, marks it stale anyway).
    Motion moved;
    if (const NeighborList::MotionReference reference = world.neighbors.motionReference(1); reference.built)
        moved.sinceBuild2 = std::max(Real{0}, lengthSquared(s.position - reference.built[0]));
    moveWalls(world.walls, dt);
    if (contactListsNeedRebuild(world, moved)) [[unlikely]]
    {
        rebuildContactLists(world);
        s.position = p.position[0]; // (wrapped into a periodic box)
    }
    world.health.maxOverlapRatio = 0; // the pair stage (computePairForces) without pair slots: it
    world.health.touchingPairs = 0;   // only resets the pair health (one particle has no pairs)

    Vec3 force{}, torque{}; // the pair sums are zero (addCrossBlockForces)
    const ContactHealth walls = wallContactsOf(world, dt, 0, s, force, torque);
    p.force[0] = force;
    p.torque[0] = torque;
    if (p.hasExternalLoads()) [[unlikely]]
    {
        addExternalLoads(p, 0, 1);
        force = p.force[0];
        torque = p.torque[0];
    }
    mergeWallHealth(world.health, &walls, 1);
    world.health.finite =
        kickOne(s.position, s.velocity, s.angularVelocity, force, torque, invMass, s.invInertia, gravity, dt);
    p.velocity[0] = s.velocity;
    p.angularVelocity[0] = s.angularVelocity;
    if (!world.health.finite)
        recordFirstNonFinite(p, world.health);
    world.time += dt;
    ++world.stepCount;
}

/// The stages of step() after the kick-drift (`moved`: the motion it measured): wall motion,
/// neighbours, pairs, particles. `driftNext` (advance()): the particle pass closes with the next
/// step's kick-drift too, whose motion it returns (else zero motion), and leaves every force and
/// torque row zero. `sumsAreZero`: the previous step did so (the pair stage need not zero them).
Motion stepAfterKickDrift(World& world, Real dt, const Motion& moved, bool lanes, bool driftNext,
                          bool sumsAreZero, StageClock& clock)
{
    moveWalls(world.walls, dt); // wall motion to t+dt
    clock.lap(&StepProfile::integration);
    bool rebuild = contactListsNeedRebuild(world, moved);
    if (world.ranks) [[unlikely]] // ghosts moved, the decision taken by all ranks, particles exchanged
        rebuild = world.ranks->afterDrift(world, rebuild);
    if (rebuild) // Verlet + wall lists, history merge
        rebuildContactLists(world);
    clock.lap(&StepProfile::neighbours);
    if (world.observer) [[unlikely]]
        world.observer->beforeForces(world, dt);
    computePairForces(world, dt, sumsAreZero); // 3. pair forces at t+dt, summed within blocks
    if (world.bonds.enabled) [[unlikely]]      //    and the bonds, in their order (dem/bonds)
        applyBonds(world.bonds, world.particles,
                   world.ranks ? world.ranks->ownedParticles() : world.particles.size(), world.time, dt);
    clock.lap(&StepProfile::pairForces);
    // 4. cross-block and wall contacts, then v(t+dt) (and, if driftNext, v(t+3dt/2), x(t+2dt))
    const Motion next = finishParticles(world, dt, lanes, driftNext);
    if (world.ranks) [[unlikely]]
        world.ranks->combineHealth(world);
    clock.lap(&StepProfile::particlePass);
    world.time += dt;
    ++world.stepCount;
    return next;
}

/// NeighborList::reach: the largest touch reach of a pair of the world's particles (R* at most
/// r_max / 2). Refuses JKR adhesion between a particle and a wall, whose contacts keep no formed
/// state (WallContactList).
Real pairTouchReach(const World& world)
{
    const ParticleStore& p = world.particles;
    std::vector<bool> present(world.materials.size(), false);
    Real maxRadius = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        present[p.material[i]] = true;
        maxRadius = std::max(maxRadius, p.radius[i]);
    }
    Real reach = 0;
    for (std::uint32_t a = 0; a < world.pairs.count(); ++a)
    {
        if (!present[a])
            continue;
        for (std::uint32_t b = 0; b < world.pairs.count(); ++b)
            if (present[b])
                reach = std::max(reach, touchReach(world.pairs(a, b), 0.5 * maxRadius));
        for (std::size_t w = 0; w < world.walls.size(); ++w)
            if (touchReach(world.pairs(a, world.walls[w].material), maxRadius) > 0)
                throw InputError(
                    "wall " +
                    (world.walls[w].name.empty() ? std::to_string(w) : "'" + world.walls[w].name + "'") +
                    " and material '" + world.materials[a].name +
                    "': JKR adhesion between a particle and a wall is not supported; give the "
                    "wall a material with surface_energy = 0 (or use \"dmt\")");
    }
    return reach;
}

} // namespace

Real defaultSkin(const World& world)
{
    Real maxRadius = 0;
    for (Real r : world.particles.radius)
        maxRadius = std::max(maxRadius, r);
    // Few particles: a wide skin costs nothing (a handful of candidate pairs and walls) and
    // spares a fast ball a list rebuild every few steps (a 12 m/s ball in the dish moves
    // 0.2 r per step at dt = 5e-5 s).
    const Real perRadius = world.particles.size() < kSmallWorld ? 4.0 : 0.2;
    return perRadius * maxRadius;
}

void prepare(World& world)
{
    if (world.pairs.count() != world.materials.size())
        world.pairs.build(world.materials);
    if (world.neighbors.skin <= 0)
        world.neighbors.skin = defaultSkin(world);
    // Rolling springs are stored only if some pair uses the EPSD rolling model.
    bool rollingHistory = false;
    for (std::uint32_t a = 0; a < world.pairs.count(); ++a)
        for (std::uint32_t b = 0; b < world.pairs.count(); ++b)
            rollingHistory = rollingHistory || world.pairs(a, b).rollingModel == RollingModel::Epsd;
    world.pairHistory.keepRolling = rollingHistory;
    world.wallHistory.keepRolling = rollingHistory;
    // History scalars are stored only if some pair's normal model declares them.
    const unsigned scalars = world.pairs.historyScalars();
    world.pairHistory.scalarCount = scalars;
    world.wallHistory.scalarCount = scalars;
    world.periodicPairs.history.scalarCount = scalars;
    world.neighbors.reach = pairTouchReach(world);
    refreshFixedParticles(world);
    rebuildContactLists(world);
    world.particles.refreshPositionRadius();
    world.prepared = true;
    computeForces(world, 0.0);
}

void rebuildAfterParticleChange(World& world)
{
    removeRetiredParticles(world);
    refreshFixedParticles(world);
    world.neighbors.reach = pairTouchReach(world);
    rebuildContactLists(world);
}

void step(World& world, Real dt)
{
    if (!world.prepared)
        prepare(world);

    if (world.particles.size() == 1 && world.exec.fusedSteps && !world.exec.profile.enabled &&
        !world.observer && !world.ranks && world.fixedIndex.empty() && !world.particles.retired(0))
        return stepOneParticle(world, dt); // the stages below, the ball's state in registers

    StageClock clock(world.exec.profile);
    const bool lanes = integrationInLanes(world);
    const Motion moved = // v(t+dt/2), x(t+dt), and how far x moved since the lists were built
        kickDrift(world.particles, world.gravity, dt, world.neighbors.motionReference(world.particles.size()),
                  lanes);
    const bool anyFixed = !world.fixedIndex.empty();
    if (anyFixed) [[unlikely]] // frozen particles: back in place, at rest (after the kick too)
        holdFixedParticles(world);
    stepAfterKickDrift(world, dt, moved, lanes, false, false, clock);
    if (anyFixed) [[unlikely]]
        holdFixedParticles(world);
    if (world.observer) [[unlikely]]
        world.observer->afterStep(world, dt);
}

std::uint64_t advance(World& world, Real dt, std::uint64_t steps, Real maxOverlapRatio)
{
    if (!world.prepared)
        prepare(world);
    const auto failed = [&]
    { return !world.health.finite || world.health.maxOverlapRatio > maxOverlapRatio; };
    if (world.particles.size() <= 1 || world.observer || !world.exec.fusedSteps ||
        !world.fixedIndex.empty()) // (one ball has its own step, with nothing to fuse; an observer
                                   // sees every step's end; frozen particles are held after each)
    {
        for (std::uint64_t s = 0; s < steps; ++s)
        {
            step(world, dt);
            if (failed())
                return s + 1;
        }
        return steps;
    }
    StageClock clock(world.exec.profile);
    const bool lanes = integrationInLanes(world);
    Motion moved = kickDrift(world.particles, world.gravity, dt,
                             world.neighbors.motionReference(world.particles.size()), lanes);
    for (std::uint64_t s = 0; s < steps; ++s)
    {
        // Every step but the last closes with the next one's kick-drift (its motion returned).
        moved = stepAfterKickDrift(world, dt, moved, lanes, s + 1 < steps, s > 0, clock);
        if (failed())
            return s + 1;
    }
    return steps;
}

namespace
{
Real translationalKineticEnergy(const ParticleStore& p, std::size_t i)
{
    return 0.5 * p.mass[i] * lengthSquared(p.velocity[i]);
}
Real rotationalKineticEnergy(const ParticleStore& p, std::size_t i)
{
    return 0.5 / p.invInertia[i] * lengthSquared(p.angularVelocity[i]);
}
} // namespace

Real kineticEnergy(const World& world, std::size_t count)
{
    const ParticleStore& p = world.particles;
    Real energy = 0;
    for (std::size_t i = 0; i < std::min(count, p.size()); ++i)
        energy += translationalKineticEnergy(p, i) + rotationalKineticEnergy(p, i);
    return energy;
}

KineticEnergyParts kineticEnergyParts(const World& world)
{
    const ParticleStore& p = world.particles;
    KineticEnergyParts parts;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        parts.translational += translationalKineticEnergy(p, i);
        parts.rotational += rotationalKineticEnergy(p, i);
    }
    return parts;
}

} // namespace veridem::dem
