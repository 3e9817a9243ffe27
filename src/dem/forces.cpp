// Contact lever arms ("contact radius convention", docs/models.md):
//  * sphere-wall: the lever arm is the undeformed radius r. The contact-point velocity
//    v + w x (-r n) and the torque (-r n) x Ft use the same arm, so the discrete dynamics are
//    exactly those of a rigid ball of radius r rolling on the wall (v = r w when rolling), which
//    is what the analytical solutions assume (2/7 Omega orbit, 5/7 v0 bowling ball).
//  * sphere-sphere: the contact point divides the centre distance d in the ratio of the radii,
//    l_i = r_i d / (r_i + r_j), so l_i + l_j = d and the tangential force conserves the total
//    angular momentum exactly (with r_i alone it would be violated by delta n x Ft).
#include "dem/forces.h"

#include "dem/contact_law.h"

#include <algorithm>
#include <cmath>

namespace veridem::dem
{

namespace
{

void computePairForces(World& world, Real dt)
{
    ParticleStore& p = world.particles;
    NeighborList& list = world.neighbors;
    StepHealth& health = world.health;
    const std::size_t pairCount = list.size();
    for (std::size_t k = 0; k < pairCount; ++k)
    {
        const std::uint32_t i = list.first[k], j = list.second[k];
        const Vec3 separation = p.position[i] - p.position[j];
        const Real ri = p.radius[i], rj = p.radius[j];
        const Real touching = ri + rj;
        const Real distance2 = lengthSquared(separation);
        if (distance2 >= touching * touching)
        {
            list.history[k] = ContactHistory{}; // the contact opened: forget it
            continue;
        }
        const Real distance = std::sqrt(distance2);
        ContactInput in;
        in.normal = distance > 0 ? separation / distance : Vec3{0, 0, 1};
        in.overlap = touching - distance;
        const Real leverI = ri * distance / touching, leverJ = rj * distance / touching;
        in.relativeVelocity = p.velocity[i] - p.velocity[j] -
                              cross(leverI * p.angularVelocity[i] + leverJ * p.angularVelocity[j], in.normal);
        in.relativeAngularVelocity = p.angularVelocity[i] - p.angularVelocity[j];
        in.effectiveMass = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
        in.effectiveRadius = ri * rj / touching;
        in.spinInertia = 1.0 / (p.invInertia[i] + p.invInertia[j]);
        in.rollingInertia = 1.0 / (1.0 / (1.0 / p.invInertia[i] + p.mass[i] * ri * ri) +
                                   1.0 / (1.0 / p.invInertia[j] + p.mass[j] * rj * rj));

        const PairParams& params = world.pairs(p.material[i], p.material[j]);
        const ContactOutput out = evaluateContact(params, in, list.history[k], dt);

        const Vec3 tangentialTorque = cross(in.normal, out.tangentialForce); // n x Ft
        p.force[i] += out.force;
        p.force[j] -= out.force;
        p.torque[i] += out.rollingTorque - leverI * tangentialTorque;
        p.torque[j] += -out.rollingTorque - leverJ * tangentialTorque;

        const Real ratio = in.overlap / std::min(ri, rj);
        if (ratio > health.maxOverlapRatio)
        {
            health.maxOverlapRatio = ratio;
            health.worstParticle = i;
        }
    }
}

void computeWallForces(World& world, Real dt)
{
    ParticleStore& p = world.particles;
    const std::size_t wallCount = world.walls.size();
    if (wallCount == 0)
        return;
    StepHealth& health = world.health;
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        for (std::size_t w = 0; w < wallCount; ++w)
        {
            const Wall& wall = world.walls[w];
            ContactHistory& history = world.wallContacts.history[i * wallCount + w];
            const Real r = p.radius[i];
            const WallGap gap = wallGap(wall, p.position[i], r);
            if (!gap.touching)
            {
                history = ContactHistory{};
                continue;
            }
            ContactInput in;
            in.normal = gap.normal;
            in.overlap = gap.overlap;
            const Vec3 arm = -r * gap.normal; // centre to contact point
            // The particle's velocities are those of the half step t+dt/2, so the wall's surface
            // velocity is taken at the contact point of the half step too (x - v dt/2). Using
            // x(t+dt) would add a spurious slip Omega |v| dt/2 on a rotating wall, and a ball
            // orbiting on a turntable would lose speed at a rate of order Omega v dt.
            const Vec3 midStepContactPoint = p.position[i] - (0.5 * dt) * p.velocity[i] + arm;
            in.relativeVelocity = p.velocity[i] + cross(p.angularVelocity[i], arm) -
                                  wallSurfaceVelocity(wall, midStepContactPoint, -0.5 * dt);
            in.relativeAngularVelocity = p.angularVelocity[i] - wall.motion.angularVelocity;
            in.effectiveMass = p.mass[i];
            in.effectiveRadius = gap.effectiveRadius;
            in.spinInertia = 1.0 / p.invInertia[i];
            in.rollingInertia = in.spinInertia + p.mass[i] * r * r;

            const PairParams& params = world.pairs(p.material[i], wall.material);
            const ContactOutput out = evaluateContact(params, in, history, dt);
            p.force[i] += out.force;
            p.torque[i] += out.rollingTorque + cross(arm, out.tangentialForce);

            const Real ratio = in.overlap / r;
            if (ratio > health.maxOverlapRatio)
            {
                health.maxOverlapRatio = ratio;
                health.worstParticle = static_cast<std::uint32_t>(i);
            }
        }
    }
}

} // namespace

void computeForces(World& world, Real dt)
{
    std::fill(world.particles.force.begin(), world.particles.force.end(), Vec3{});
    std::fill(world.particles.torque.begin(), world.particles.torque.end(), Vec3{});
    world.health.maxOverlapRatio = 0;
    computePairForces(world, dt);
    computeWallForces(world, dt);
}

} // namespace veridem::dem
