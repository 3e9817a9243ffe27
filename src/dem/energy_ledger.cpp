#include "dem/energy_ledger.h"

namespace veridem::dem
{

std::size_t bookedParticles(const World& world)
{
    return world.ranks ? world.ranks->ownedParticles() : world.particles.size();
}

LedgerPowers ledgerPowers(const World& world, const std::vector<ContactRecord>& records,
                          const std::vector<Vec3>& velocity, const std::vector<Vec3>& angularVelocity)
{
    const ParticleStore& p = world.particles;
    LedgerPowers power;
    for (const ContactRecord& c : records)
    {
        const std::uint32_t i = c.i;
        Vec3 relativeVelocity, relativeAngularVelocity;
        if (c.wall)
        {
            const Wall& wall = world.walls[c.partner];
            const Vec3 wallVelocity = wallSurfaceVelocity(wall, c.point);
            relativeVelocity =
                velocity[i] + cross(angularVelocity[i], c.point - p.position[i]) - wallVelocity;
            relativeAngularVelocity = angularVelocity[i] - wall.motion.angularVelocity;
            power.wall += dot(c.normalForce + c.tangentialForce, wallVelocity) +
                          dot(c.rollingTorque, wall.motion.angularVelocity);
        }
        else
        {
            const std::uint32_t j = c.partner;
            relativeVelocity = velocity[i] - velocity[j] -
                               cross(c.leverI * angularVelocity[i] + c.leverJ * angularVelocity[j], c.normal);
            relativeAngularVelocity = angularVelocity[i] - angularVelocity[j];
        }
        power.normalDamping -= dot(c.normalDamping, relativeVelocity);
        power.tangentialDamping -= dot(c.tangentialDamping, relativeVelocity);
        power.rolling -= dot(c.rollingDissipative, relativeAngularVelocity);
    }
    return power;
}

void EnergyLedger::start(const World& world)
{
    if (state.started)
        return;
    const std::vector<ContactRecord> records = evaluateContacts(world, 0.0);
    state = {};
    Real elastic = 0;
    for (const ContactRecord& c : records)
    {
        elastic += c.storedEnergy();
        state.tangentialSpringEnergy += c.tangentialEnergyBefore;
        state.rollingSpringEnergy += c.rollingEnergyBefore;
    }
    const LedgerPowers power =
        ledgerPowers(world, records, world.particles.velocity, world.particles.angularVelocity);
    state.started = true;
    state.elasticEnergy = elastic;
    state.initialEnergy = kineticEnergy(world, bookedParticles(world)) + elastic;
    state.wallPower = power.wall;
    state.normalDampingPower = power.normalDamping;
    state.tangentialDampingPower = power.tangentialDamping;
    state.rollingPower = power.rolling;
}

void EnergyLedger::beforeForces(const World& world, Real dt)
{
    // Gravity: m g . dx with dx = dt v(t+dt/2), the drift just done (exact: the potential).
    const ParticleStore& p = world.particles;
    Real gravityPower = 0;
    const std::size_t booked = bookedParticles(world);
    for (std::size_t i = 0; i < booked; ++i)
        gravityPower += p.mass[i] * dot(world.gravity, p.velocity[i]);
    state.gravityWork += dt * gravityPower;
    records_ = evaluateContacts(world, dt, &state.adhesion);
    // The springs' energy lost before the law's increment: of contacts that opened (their
    // history is dropped) and by the stiffness's change with the overlap.
    Real tangentialBefore = 0, rollingBefore = 0;
    for (const ContactRecord& c : records_)
    {
        state.friction += c.frictionWork;
        state.rolling += c.rollingSlipWork;
        tangentialBefore += c.tangentialEnergyBefore;
        rollingBefore += c.rollingEnergyBefore;
    }
    state.friction += state.tangentialSpringEnergy - tangentialBefore;
    state.rolling += state.rollingSpringEnergy - rollingBefore;
}

void EnergyLedger::afterStep(const World& world, Real dt)
{
    // The powers of this step's forces at v(t+dt), trapezoids with the last step's.
    const ParticleStore& p = world.particles;
    if (world.ranks) // (a ghost's own velocity is not its owner's v(t+dt))
        world.ranks->velocitiesAfterStep(world, velocity_, angularVelocity_);
    const LedgerPowers power = world.ranks ? ledgerPowers(world, records_, velocity_, angularVelocity_)
                                           : ledgerPowers(world, records_, p.velocity, p.angularVelocity);
    const Real half = 0.5 * dt;
    state.wallWork += half * (state.wallPower + power.wall);
    state.normalDamping += half * (state.normalDampingPower + power.normalDamping);
    state.tangentialDamping += half * (state.tangentialDampingPower + power.tangentialDamping);
    state.rolling += half * (state.rollingPower + power.rolling);
    state.wallPower = power.wall;
    state.normalDampingPower = power.normalDamping;
    state.tangentialDampingPower = power.tangentialDamping;
    state.rollingPower = power.rolling;
    Real elastic = 0;
    state.tangentialSpringEnergy = state.rollingSpringEnergy = 0;
    for (const ContactRecord& c : records_)
    {
        elastic += c.elasticEnergy();
        state.tangentialSpringEnergy += c.tangentialEnergy;
        state.rollingSpringEnergy += c.rollingEnergy;
    }
    state.elasticEnergy = elastic;
}

Real EnergyLedger::dissipated() const
{
    return state.normalDamping + state.tangentialDamping + state.friction + state.rolling + state.adhesion;
}

Real EnergyLedger::residual(const World& world) const
{
    return kineticEnergy(world) + state.elasticEnergy - state.gravityWork - state.wallWork + dissipated() -
           state.initialEnergy;
}

} // namespace veridem::dem
