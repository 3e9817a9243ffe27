// Contact lever arms ("contact radius convention", docs/models.md):
//  * sphere-wall: the lever arm is the undeformed radius r. The contact-point velocity
//    v + w x (-r n) and the torque (-r n) x Ft use the same arm, so the discrete dynamics are
//    exactly those of a rigid ball of radius r rolling on the wall (v = r w when rolling), which
//    is what the analytical solutions assume (2/7 Omega orbit, 5/7 v0 bowling ball).
//  * sphere-sphere: the contact point divides the centre distance d in the ratio of the radii,
//    l_i = r_i d / (r_i + r_j), so l_i + l_j = d and the tangential force conserves the total
//    angular momentum exactly (with r_i alone it would be violated by delta n x Ft).
//
// Parallel layout (STYLE 3.4): stage 3 loops over contact slots and writes only the slot's own
// outputs and history; stage 4 loops over particles and reads the slots in a fixed order. The
// health record (largest overlap) is reduced per chunk and combined in chunk order, so it too is
// independent of the thread count.
#include "dem/forces.h"

#include "dem/contact_law.h"
#include "dem/parallel.h"

#include <algorithm>
#include <cmath>

namespace veridem::dem
{

namespace
{

constexpr int kMaxChunks = 64;

struct WorstOverlap  // trivial on purpose: per-chunk arrays of it are not cleared every step
{
    Real ratio;
    std::uint32_t particle;
    bool found;
};

/// Folds per-chunk records into health in chunk order (strictly greater wins: the first slot
/// with the largest ratio, as a serial loop would find).
void combine(StepHealth& health, const WorstOverlap* worst, int chunks)
{
    for (int c = 0; c < chunks; ++c)
        if (worst[c].found && worst[c].ratio > health.maxOverlapRatio)
        {
            health.maxOverlapRatio = worst[c].ratio;
            health.worstParticle = worst[c].particle;
        }
}

/// What the contact law reads beyond the linear normal and tangential model.
struct ExtraInputs
{
    bool effectiveRadius, spinInertia, rollingInertia;
};

ExtraInputs extraInputsFor(const PairParams& params)
{
    return {params.normalModel == NormalModel::Hertz || params.rollingModel != RollingModel::None,
            params.rollingModel == RollingModel::ConstantTorque, params.rollingModel == RollingModel::Epsd};
}

} // namespace

void computePairForces(World& world, Real dt)
{
    const ParticleStore& p = world.particles;
    NeighborList& list = world.neighbors;
    world.health.maxOverlapRatio = 0;
    const std::size_t pairCount = list.size();
    const int chunks = std::min(loopThreads(pairCount), kMaxChunks);
    WorstOverlap worst[kMaxChunks];
    parallelChunks(
        pairCount, chunks,
        [&](int chunk, std::size_t begin, std::size_t end)
        {
            WorstOverlap local{0, 0, false};
            // Pass 1: which slots touch (branch-free), and clear the slots that just opened.
            std::uint32_t* touchingSlots = list.touchingScratch.data() + begin;
            std::size_t touchingCount = 0;
            for (std::size_t k = begin; k < end; ++k)
            {
                const std::uint32_t i = list.first[k], j = list.second[k];
                const Real touching = p.radius[i] + p.radius[j];
                const bool isTouching = lengthSquared(p.position[i] - p.position[j]) < touching * touching;
                touchingSlots[touchingCount] = static_cast<std::uint32_t>(k);
                touchingCount += isTouching;
                if (!isTouching && list.mayBeActive[k])
                {
                    // The contact opened (or never closed): forget it, contribute nothing.
                    list.setHistory(k, ContactHistory{});
                    list.force[k] = Vec3{};
                    list.torqueOnFirst[k] = Vec3{};
                    list.torqueOnSecond[k] = Vec3{};
                    list.mayBeActive[k] = 0;
                }
            }
            // Pass 2: the contact law on the touching slots, in ascending slot order.
            for (std::size_t t = 0; t < touchingCount; ++t)
            {
                const std::size_t k = touchingSlots[t];
                const std::uint32_t i = list.first[k], j = list.second[k];
                list.mayBeActive[k] = 1;
                const Vec3 separation = p.position[i] - p.position[j];
                const Real ri = p.radius[i], rj = p.radius[j];
                const Real touching = ri + rj;
                const Real distance2 = lengthSquared(separation);
                const PairParams& params = world.pairs(p.material[i], p.material[j]);
                const ExtraInputs extra = extraInputsFor(params);
                const Real distance = std::sqrt(distance2);
                ContactInput in;
                in.normal = distance > 0 ? separation / distance : Vec3{0, 0, 1};
                in.overlap = touching - distance;
                const Real leverI = ri * distance / touching, leverJ = rj * distance / touching;
                in.relativeVelocity = p.velocity[i] - p.velocity[j] -
                                      cross(leverI * p.angularVelocity[i] + leverJ * p.angularVelocity[j], in.normal);
                in.relativeAngularVelocity = p.angularVelocity[i] - p.angularVelocity[j];
                in.effectiveMass = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
                if (extra.effectiveRadius)
                    in.effectiveRadius = ri * rj / touching;
                if (extra.spinInertia)
                    in.spinInertia = 1.0 / (p.invInertia[i] + p.invInertia[j]);
                if (extra.rollingInertia)
                    in.rollingInertia = 1.0 / (1.0 / (1.0 / p.invInertia[i] + p.mass[i] * ri * ri) +
                                               1.0 / (1.0 / p.invInertia[j] + p.mass[j] * rj * rj));

                ContactHistory history = list.history(k);
                const ContactOutput out = evaluateContact(params, in, history, dt);
                list.setHistory(k, history);

                const Vec3 tangentialTorque = cross(in.normal, out.tangentialForce);  // n x Ft
                list.force[k] = out.force;
                list.torqueOnFirst[k] = out.rollingTorque - leverI * tangentialTorque;
                list.torqueOnSecond[k] = -out.rollingTorque - leverJ * tangentialTorque;

                const Real ratio = in.overlap / std::min(ri, rj);
                if (ratio > local.ratio)
                    local = {ratio, i, true};
            }
            worst[chunk] = local;
        });
    combine(world.health, worst, chunks);
}

void computeWallForces(World& world, Real dt)
{
    const ParticleStore& p = world.particles;
    WallContactList& list = world.wallContacts;
    const std::size_t count = list.size();
    const int chunks = std::min(loopThreads(count), kMaxChunks);
    WorstOverlap worst[kMaxChunks];
    parallelChunks(
        count, chunks,
        [&](int chunk, std::size_t begin, std::size_t end)
        {
            WorstOverlap local{0, 0, false};
            for (std::size_t k = begin; k < end; ++k)
            {
                const std::uint32_t i = list.particle[k];
                const Wall& wall = world.walls[list.wall[k]];
                const Real r = p.radius[i];
                const WallGap gap = wallGap(wall, p.position[i], r);
                if (!gap.touching)
                {
                    list.setHistory(k, ContactHistory{});
                    list.force[k] = Vec3{};
                    list.torque[k] = Vec3{};
                    continue;
                }
                const PairParams& params = world.pairs(p.material[i], wall.material);
                ContactInput in;
                in.normal = gap.normal;
                in.overlap = gap.overlap;
                const Vec3 arm = -r * gap.normal;  // centre to contact point
                // The particle's velocities are those of the half step t+dt/2, so the wall's
                // surface velocity is taken at the contact point of the half step too
                // (x - v dt/2). Using x(t+dt) would add a spurious slip Omega |v| dt/2 on a
                // rotating wall, and a ball orbiting on a turntable would lose speed at a rate of
                // order Omega v dt.
                const Vec3 midStepContactPoint = p.position[i] - (0.5 * dt) * p.velocity[i] + arm;
                in.relativeVelocity = p.velocity[i] + cross(p.angularVelocity[i], arm) -
                                      wallSurfaceVelocity(wall, midStepContactPoint, -0.5 * dt);
                in.relativeAngularVelocity = p.angularVelocity[i] - wall.motion.angularVelocity;
                in.effectiveMass = p.mass[i];
                in.effectiveRadius = gap.effectiveRadius;
                in.spinInertia = 1.0 / p.invInertia[i];
                in.rollingInertia = in.spinInertia + p.mass[i] * r * r;

                ContactHistory history = list.history(k);
                const ContactOutput out = evaluateContact(params, in, history, dt);
                list.setHistory(k, history);
                list.force[k] = out.force;
                list.torque[k] = out.rollingTorque + cross(arm, out.tangentialForce);

                const Real ratio = in.overlap / r;
                if (ratio > local.ratio)
                    local = {ratio, i, true};
            }
            worst[chunk] = local;
        });
    combine(world.health, worst, chunks);
}

void gatherContactForces(World& world)
{
    ParticleStore& p = world.particles;
    const NeighborList& pairs = world.neighbors;
    const WallContactList& walls = world.wallContacts;
    const bool hasWalls = walls.start.size() == p.size() + 1;
    parallelFor(p.size(),
                [&](std::size_t i)
                {
                    Vec3 force{}, torque{};
                    // Slots where i is the second particle come first in slot order (their first
                    // particle is < i), then i's own slots.
                    for (std::uint32_t s = pairs.secondStart[i]; s < pairs.secondStart[i + 1]; ++s)
                    {
                        const std::uint32_t k = pairs.secondSlots[s];
                        force -= pairs.force[k];
                        torque += pairs.torqueOnSecond[k];
                    }
                    for (std::uint32_t k = pairs.firstStart[i]; k < pairs.firstStart[i + 1]; ++k)
                    {
                        force += pairs.force[k];
                        torque += pairs.torqueOnFirst[k];
                    }
                    if (hasWalls)
                        for (std::uint32_t k = walls.start[i]; k < walls.start[i + 1]; ++k)
                        {
                            force += walls.force[k];
                            torque += walls.torque[k];
                        }
                    p.force[i] = force;
                    p.torque[i] = torque;
                });
}

void computeForces(World& world, Real dt)
{
    computePairForces(world, dt);
    computeWallForces(world, dt);
    gatherContactForces(world);
}

} // namespace veridem::dem
