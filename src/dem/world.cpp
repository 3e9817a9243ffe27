// The step, read top to bottom (velocity Verlet, LAMMPS/Box2D style):
//
//   kick-drift     v(t+dt/2) = v(t) + dt/2 a(t);  w likewise;  x(t+dt) = x(t) + dt v(t+dt/2)
//   walls          prescribed motion to t + dt
//   neighbours     rebuild the Verlet list if some particle moved more than skin/2
//   forces         contact forces at x(t+dt) from the half-step velocities (pairs, then walls)
//   kick           v(t+dt) = v(t+dt/2) + dt/2 a(t+dt);  w likewise
//
// The dashpots and the tangential-spring increment use the half-step velocities: the spring
// increment vt dt is then exactly the relative displacement over [t, t+dt]. Output never happens
// here; the driver records the world between steps.
#include "dem/world.h"

#include "core/error.h"
#include "dem/forces.h"
#include "dem/integrate.h"

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

void prepare(World& world)
{
    if (world.pairs.count() != world.materials.size())
        world.pairs.build(world.materials);
    if (world.neighbors.skin <= 0)
    {
        Real maxRadius = 0;
        for (Real r : world.particles.radius)
            maxRadius = std::max(maxRadius, r);
        world.neighbors.skin = 0.2 * maxRadius;
    }
    world.neighbors.rebuild(world.particles);
    world.wallContacts.history.resize(world.particles.size() * world.walls.size());
    world.prepared = true;
    computeForces(world, 0.0);
}

void step(World& world, Real dt)
{
    if (!world.prepared)
        prepare(world);

    kickDrift(world.particles, world.gravity, dt);     // v(t+dt/2), x(t+dt)
    moveWalls(world.walls, dt);                        // wall motion to t+dt
    if (world.neighbors.needsRebuild(world.particles)) // Verlet list + history merge
        world.neighbors.rebuild(world.particles);
    computeForces(world, dt);                               // contact forces at t+dt
    kick(world.particles, world.gravity, dt, world.health); // v(t+dt)

    world.time += dt;
    ++world.stepCount;
}

Real kineticEnergy(const World& world)
{
    const ParticleStore& p = world.particles;
    Real energy = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        energy += 0.5 * p.mass[i] * lengthSquared(p.velocity[i]) +
                  0.5 / p.invInertia[i] * lengthSquared(p.angularVelocity[i]);
    return energy;
}

} // namespace veridem::dem
