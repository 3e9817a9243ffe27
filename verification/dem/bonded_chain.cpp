#include "bonded_chain.h"

#include "dem/forces.h"

#include <cmath>

namespace veridem::verify
{

World chainWorld(const BondedChain& chain)
{
    Material material; // (the spheres never touch: the contact law's values do not matter)
    material.name = "cement";
    material.density = chain.density;
    material.normalStiffness = 1e5;
    World world = worldWith(material, {0, 0, 0});
    for (int i = 0; i <= chain.bonds; ++i)
        world.particles.add({i * chain.spacing(), 0, 0}, {}, {}, chain.radius, chain.density, 0);
    world.particles.fixed[0] = 1;
    world.particles.keepExternalLoads();
    world.bonds.enabled = true;
    world.bonds.params = chain.law;
    world.bonds.gapTolerance = 2 * chain.gap;
    world.bonds.materialSelected = {1};
    dem::createBonds(world.bonds, world.particles);
    dem::prepare(world);
    return world;
}

Real relaxChain(World& world, Real dt, Real rate, std::uint64_t steps)
{
    dem::ParticleStore& p = world.particles;
    const std::size_t tip = p.size() - 1;
    const Real scale = std::exp(-rate * dt);
    Real angle = 0;
    dem::syncExternalLoads(p); // (the loads set since prepare(), into the rows the first kick reads)
    for (std::uint64_t s = 0; s < steps; ++s)
    {
        // The drift's w(t + dt/2) = w(t) + dt/2 T / I (the step's first half kick).
        angle += dt * (p.angularVelocity[tip].x + 0.5 * dt * p.invInertia[tip] * p.torque[tip].x);
        dem::step(world, dt);
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            p.velocity[i] = scale * p.velocity[i];
            p.angularVelocity[i] = scale * p.angularVelocity[i];
        }
    }
    return angle;
}

} // namespace veridem::verify
