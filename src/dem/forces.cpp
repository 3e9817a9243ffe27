// Stage 3 of the step, the pair forces, and the force stages run serially for the initial
// evaluation. The pair stage runs over fixed blocks of particles (NeighborList::kBlockParticles),
// each thread a contiguous run of blocks (dem/exec/pair_schedule.h). Per block: the selection pass
// collects the touching candidates into batches (dem/exec/pair_selection.h), the pair kernel
// evaluates them (dem/pair_kernel.h: contact frame, law, sums), and every contact is added straight
// into its particles' force and torque, except the share of a second particle in a later block,
// which goes to the slot's deferred entry; stage 4 adds the deferred entries per particle in slot
// order (dem/exec/cross_block_sums.cpp), then the wall contacts (dem/wall_forces.cpp). No sum
// depends on the thread schedule. The health record (largest overlap) is reduced per block and
// combined in block order, so it too is independent of the thread count (STYLE 3.4).
#include "dem/forces.h"

#include "dem/exec/pair_schedule.h"
#include "dem/exec/pair_selection.h"
#include "dem/pair_kernel.h"
#include "dem/parallel.h"
#include "dem/periodic.h"
#include "exec/isa.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <optional>

namespace veridem::dem
{

namespace
{

using namespace batch; // PairBatch, Candidates, kBatch, UniformLaw (dem/exec/)

/// Folds per-chunk health into world health in chunk order (strictly greater wins: the first slot
/// with the largest ratio, as a serial loop would find); sets `touching` to the chunks' total.
void foldHealth(StepHealth& health, const ContactHealth* chunk, int chunks, std::size_t& touching)
{
    touching = 0;
    for (int c = 0; c < chunks; ++c)
    {
        touching += chunk[c].touching;
        if (chunk[c].found && chunk[c].maxOverlapRatio > health.maxOverlapRatio)
        {
            health.maxOverlapRatio = chunk[c].maxOverlapRatio;
            health.worstParticle = chunk[c].worstParticle;
        }
    }
}

/// The law of batch `b`'s contacts [0, count) if they all join the same ordered material pair (a
/// bed of one material struck by a ball of another, DEM8's impact: nearly every batch), else
/// `uniform` (the world's single law, or null: each lane's pair looked up by the kernel).
const UniformLaw* lawOfBatch(const BatchLaws& laws, const UniformLaw* uniform, const std::uint32_t* material,
                             const PairBatch& b, std::size_t count)
{
    if (laws.materials == 0)
        return uniform;
    const std::uint32_t mi = material[b.i[0]], mj = material[b.j[0]];
    for (std::size_t m = 1; m < count; ++m)
        if (material[b.i[m]] != mi || material[b.j[m]] != mj)
            return nullptr;
    return &laws.law[mi * laws.materials + mj];
}

/// Zeroes the pair sums of particles [begin, end); returns end. Out of line: it runs once a block.
[[gnu::noinline]] std::size_t zeroSums(const PairSink& sink, bool alreadyZero, std::size_t begin,
                                       std::size_t end)
{
    if (alreadyZero) // (advance()'s fused particle pass zeroed them)
        return end;
    // (memset: glibc's picks the CPU's widest stores; std::fill of the 32-byte Sums compiled to
    // eight scalar stores a particle here, -fno-tree-slp-vectorize.)
    std::memset(static_cast<void*>(sink.force + begin), 0, (end - begin) * sizeof(PaddedVec3));
    std::memset(static_cast<void*>(sink.torque + begin), 0, (end - begin) * sizeof(PaddedVec3));
    return end;
}

/// computePairForces for a world with particles and pair slots.
void pairForcesOfSlots(World& world, Real dt, bool sumsAreZero)
{
    ParticleStore& p = world.particles;
    NeighborList& list = world.neighbors;
    const std::size_t n = p.size();
    const std::size_t pairCount = list.size();
    // (The lane kernels carry no history scalars: a scene whose model declares some runs the
    // general law one contact at a time, the same law.)
    const bool allBatchable = world.exec.batchedContactKernel && world.pairHistory.scalarCount == 0;
    const std::optional<UniformLaw> single = uniformLaw(world);
    const UniformLaw* const uniform = single ? &*single : nullptr;
    const BatchLaws perBatch = batchLaws(world, uniform);
    const std::uint32_t* const material = p.material.data();

    constexpr std::size_t B = NeighborList::kBlockParticles;
    const std::size_t blocks = (n + B - 1) / B;
    const int chunks = static_cast<int>(std::min(
        {static_cast<std::size_t>(loopThreads(std::max(pairCount, n))), blocks, std::size_t{kMaxChunks}}));

    list.refreshActiveSlots(p, world.pairHistory); // the touching candidates, if the sub-list is stale
    const std::uint32_t* const active = list.activeSlots.data();
    const std::size_t activeCount = list.activeSlots.size();
    const auto activeFrom = [&](std::size_t particle) // first candidate slot of this particle on
    {
        return static_cast<std::size_t>(
            std::lower_bound(active, active + activeCount, list.firstStart[particle]) - active);
    };
    const std::vector<BlockRun>& runs = scheduleBlocks(world, blocks, chunks, activeFrom);

    if (p.positionRadius.size() != n) // (prepare() and every drift keep it; a direct caller may not)
        p.refreshPositionRadius();
    const PaddedVec3* const positionRadiusRows = p.positionRadius.data();
    const PairSink sink(world);
    const PairKernel kernel = pairKernelFor(exec::isa());
    const SelectPass select = selectPassFor(exec::isa());
    // Health per block (one thread: per run, in entry 0), folded in block order (the order of a
    // serial loop).
    ContactHealth* const health = world.exec.pairSchedule.runHealth.data();
    // One run of consecutive blocks: their candidates, selected and evaluated in batches.
    const auto pairRun = [&](const BlockRun& run) -> ContactHealth
    {
        const std::size_t firstParticle = std::min(run.first * B, n), endParticle = std::min(run.end * B, n);
        // A block's sums are zeroed just before its first candidate, not the run's all at
        // once: a block's contacts add only into its own particles' sums (the cross-block
        // shares are deferred), so the sums are still in L2 when the contacts add to them
        // (a chunk's sums, 64 B a particle, do not fit in a 512 KB L2).
        std::size_t zeroedEnd = firstParticle; // sums [firstParticle, zeroedEnd) are zero
        const auto blockEndOf = [&](std::size_t particle)
        { return std::min((particle / B + 1) * B, endParticle); };
        const std::size_t begin = activeFrom(firstParticle),
                          end = endParticle == n ? activeCount : activeFrom(endParticle);
        WorstOverlap worst{0, 0, false};
        std::size_t touchingCount = 0;
        // Array bases in locals (the byte-sized mayBeActive stores could alias the vectors).
        const std::uint32_t* const first = list.activeFirst.data();
        const std::uint32_t* const second = list.activeSecond.data();
        const Vec3* const position = p.position.data();
        const Real* const radius = p.radius.data();
        std::uint8_t* const mayBeActive = sink.mayBeActive;
        if (!allBatchable)
        {
            for (std::size_t a = begin; a < end; ++a)
            {
                const std::uint32_t i = first[a], j = second[a];
                if (i >= zeroedEnd)
                    zeroedEnd = zeroSums(sink, sumsAreZero, zeroedEnd, blockEndOf(i));
                const Real touching = radius[i] + radius[j] + list.reach;
                if (lengthSquared(position[i] - position[j]) < touching * touching)
                {
                    pairContactScalar(world, sink, dt, a, worst);
                    ++touchingCount;
                }
                else if (mayBeActive[a])
                    list.openCandidate(a, world.pairHistory);
            }
            zeroSums(sink, sumsAreZero, zeroedEnd, endParticle);
            return ContactHealth{worst.ratio, worst.particle, worst.found, touchingCount};
        }
        // One pass: each touching candidate is appended (branch-free) to a batch, which runs when
        // full (selectTouching*). The selection stops at a block's first candidate, whose sums
        // are zeroed here, and candidates found open are only recorded, then opened here
        // (openCandidate touches no candidate of the batch, and nothing in this pass reads what
        // it writes again).
        const Candidates selection{first,       second, position,  radius, positionRadiusRows,
                                   mayBeActive, end,    list.reach};
        PairBatch batch;
        std::uint32_t opened[kBatch];
        std::size_t m = 0, o = 0;
        std::size_t a = begin;
        while (a < end)
        {
            a = select(selection, a, zeroedEnd, batch, m, opened, o);
            for (std::size_t q = 0; q < o; ++q)
                list.openCandidate(opened[q], world.pairHistory);
            o = 0;
            if (m == kBatch || a == end)
            {
                if (m > 0)
                    kernel(world, sink, dt, m, worst, batch,
                           lawOfBatch(perBatch, uniform, material, batch, m));
                touchingCount += m;
                m = 0;
            }
            if (a < end && first[a] >= zeroedEnd)
                // (the batch holds earlier blocks' contacts only)
                zeroedEnd = zeroSums(sink, sumsAreZero, zeroedEnd, blockEndOf(first[a]));
        }
        zeroSums(sink, sumsAreZero, zeroedEnd, endParticle);
        return ContactHealth{worst.ratio, worst.particle, worst.found, touchingCount};
    };
    if (chunks == 1)
    {
        for (const BlockRun& run : runs)
            health[run.first] = pairRun(run);
    }
    else
    {
        // Each thread evaluates its own run's blocks, timed for adaptSchedule.
        const BlockRun* runOf[kMaxChunks] = {};
        for (const BlockRun& run : runs)
            runOf[run.chunk] = &run;
        double seconds[kMaxChunks] = {};
        parallelChunks(
            static_cast<std::size_t>(chunks), chunks,
            [&](int chunk, std::size_t, std::size_t)
            {
                const ThreadBusyTimer busy(world.exec.profile, world.exec.profile.pairBusy, chunk);
                const BlockRun* const run = runOf[chunk];
                if (!run)
                    return;
                const auto start = std::chrono::steady_clock::now();
                for (std::uint32_t b = run->first; b < run->end; ++b)
                    health[b] = pairRun(BlockRun{b, b + 1, chunk});
                seconds[chunk] =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            });
        if (world.exec.pairSchedule.adapt)
            adaptSchedule(world.exec.pairSchedule, seconds, chunks);
    }
    foldHealth(world.health, health, static_cast<int>(blocks), world.health.touchingPairs);
}

} // namespace

void computePairForces(World& world, Real dt, bool sumsAreZero)
{
    world.health.maxOverlapRatio = 0;
    world.health.touchingPairs = 0;
    // (Small, so that it inlines into the step: one ball on a turntable has no pair slots and no
    // sums to fill; addCrossBlockForces zeroes its force and torque.)
    if (world.particles.size() > 0 && world.neighbors.size() > 0)
        pairForcesOfSlots(world, dt, sumsAreZero);
    if (!world.periodicPairs.empty()) [[unlikely]] // pairs through a periodic image, after the blocks
        addPeriodicPairForces(world, dt, sumsAreZero);
}

void mergeWallHealth(StepHealth& health, const ContactHealth* chunk, int chunks)
{
    foldHealth(health, chunk, chunks, health.touchingWalls);
}

void addExternalLoads(ParticleStore& particles, std::size_t begin, std::size_t end)
{
    if (!particles.hasExternalLoads()) [[likely]]
        return;
    for (std::size_t i = begin; i < end; ++i)
    {
        particles.force[i] = particles.force[i] + particles.externalForce[i];
        particles.torque[i] = particles.torque[i] + particles.externalTorque[i];
        particles.appliedExternalForce[i] = particles.externalForce[i];
        particles.appliedExternalTorque[i] = particles.externalTorque[i];
    }
}

void syncExternalLoads(ParticleStore& particles)
{
    if (!particles.hasExternalLoads())
        return;
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        particles.force[i] =
            particles.force[i] + (particles.externalForce[i] - particles.appliedExternalForce[i]);
        particles.torque[i] =
            particles.torque[i] + (particles.externalTorque[i] - particles.appliedExternalTorque[i]);
        particles.appliedExternalForce[i] = particles.externalForce[i];
        particles.appliedExternalTorque[i] = particles.externalTorque[i];
    }
}

void computeForces(World& world, Real dt)
{
    computePairForces(world, dt);
    const std::size_t n = world.particles.size();
    addCrossBlockForces(world, 0, n);
    const ContactHealth walls = computeWallForces(world, dt, 0, n);
    addExternalLoads(world.particles, 0, n);
    mergeWallHealth(world.health, &walls, 1);
}

} // namespace veridem::dem
