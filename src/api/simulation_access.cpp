// api::Simulation between steps: the particles' velocities and external loads, particles added
// and removed by id, the walls' motion and loads, the contacts and energies.
#include "api/simulation.h"
#include "api/simulation_state.h"

namespace veridem::api
{

namespace
{
void checkSlot(const dem::World& world, std::size_t slot, const char* what)
{
    if (slot >= world.particles.size())
        throw InputError(std::string(what) + ": particle slot " + std::to_string(slot) +
                         " is out of range (" + std::to_string(world.particles.size()) + " particles)");
}
void checkFinite(const Vec3& v, const char* what)
{
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw InputError(std::string(what) + ": every component must be finite");
}
} // namespace

std::shared_ptr<const dem::ParticleStore> Simulation::detachParticleArrays()
{
    dem::ParticleStore& p = s_->world().particles;
    auto old = std::make_shared<dem::ParticleStore>(std::move(p));
    p = *old;
    return old;
}

dem::ParticleStore& Simulation::particleStore()
{
    return s_->world().particles;
}

void Simulation::setVelocity(std::size_t slot, const Vec3& v)
{
    checkSlot(world(), slot, "velocity");
    checkFinite(v, "velocity");
    s_->world().particles.velocity[slot] = v;
}

void Simulation::setAngularVelocity(std::size_t slot, const Vec3& w)
{
    checkSlot(world(), slot, "angular velocity");
    checkFinite(w, "angular velocity");
    s_->world().particles.angularVelocity[slot] = w;
}

std::vector<Vec3>& Simulation::externalForces()
{
    s_->world().particles.keepExternalLoads();
    return s_->world().particles.externalForce;
}

std::vector<Vec3>& Simulation::externalTorques()
{
    s_->world().particles.keepExternalLoads();
    return s_->world().particles.externalTorque;
}

void Simulation::setExternalForce(std::size_t slot, const Vec3& force, const Vec3& torque)
{
    checkSlot(world(), slot, "external force");
    checkFinite(force, "external force");
    checkFinite(torque, "external torque");
    externalForces()[slot] = force;
    externalTorques()[slot] = torque;
}

std::uint32_t Simulation::addParticle(const std::string& material, double radius, const Vec3& position,
                                      const Vec3& velocity, const Vec3& angularVelocity)
{
    State& st = *s_;
    if (st.severalRanks)
        throw InputError("add_particle: not on several MPI ranks (use an [[insert]] in the scene)");
    dem::World& world = st.world();
    std::uint32_t m = 0;
    while (m < world.materials.size() && world.materials[m].name != material)
        ++m;
    if (m == world.materials.size())
    {
        std::string known;
        for (const dem::Material& k : world.materials)
            known += (known.empty() ? "'" : ", '") + k.name + "'";
        throw InputError("add_particle: unknown material '" + material + "' (the scene has " + known + ")");
    }
    if (!(radius > 0) || !std::isfinite(radius))
        throw InputError("add_particle: radius must be a finite number > 0 m (got " + std::to_string(radius) +
                         ")");
    checkFinite(position, "add_particle: position");
    checkFinite(velocity, "add_particle: velocity");
    checkFinite(angularVelocity, "add_particle: angular velocity");
    dem::ParticleStore& p = world.particles;
    const std::uint32_t slot =
        p.add(position, velocity, angularVelocity, radius, world.materials[m].density, m);
    std::uint32_t id = st.scene.flow.nextId; // (ids are never reused: above every id so far)
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        id = std::max(id, p.id[i] + 1);
    p.id[slot] = id;
    st.scene.flow.nextId = id + 1;
    // The lists take it in; its force sums start at zero, as an inserted particle's do
    // (dem/particle_flow.h).
    dem::rebuildAfterParticleChange(world);
    return id;
}

void Simulation::removeParticles(const std::vector<std::uint32_t>& ids)
{
    State& st = *s_;
    if (st.severalRanks)
        throw InputError("remove_particles: not on several MPI ranks (use an [[outlet]] in the scene)");
    dem::World& world = st.world();
    dem::ParticleStore& p = world.particles;
    std::vector<std::uint32_t> slots;
    for (const std::uint32_t id : ids)
    {
        std::size_t i = 0;
        while (i < p.size() && (p.id[i] != id || p.retired(i)))
            ++i;
        if (i == p.size())
            throw InputError("remove_particles: no particle has id " + std::to_string(id));
        if (std::find(slots.begin(), slots.end(), std::uint32_t(i)) != slots.end())
            throw InputError("remove_particles: id " + std::to_string(id) + " is listed twice");
        slots.push_back(static_cast<std::uint32_t>(i));
    }
    dem::removeParticles(world, slots);
    dem::rebuildAfterParticleChange(world);
}

std::size_t Simulation::wallIndex(const std::string& name) const
{
    const std::vector<dem::Wall>& walls = world().walls;
    for (std::size_t w = 0; w < walls.size(); ++w)
        if (walls[w].name == name)
            return w;
    std::string known;
    for (const dem::Wall& w : walls)
        known += (known.empty() ? "'" : ", '") + w.name + "'";
    throw InputError("no wall is named '" + name +
                     "' (the scene's walls: " + (known.empty() ? "none" : known) + ")");
}

std::vector<std::string> Simulation::wallNames() const
{
    std::vector<std::string> names;
    for (const dem::Wall& w : world().walls)
        names.push_back(w.name);
    return names;
}

namespace
{
dem::Wall& steadyWall(dem::World& world, std::size_t w, const char* what)
{
    if (w >= world.walls.size())
        throw InputError(std::string(what) + ": wall index " + std::to_string(w) + " is out of range");
    dem::Wall& wall = world.walls[w];
    if (!wall.motion.velocityTable.empty() || !wall.motion.angularVelocityTable.empty() ||
        wall.motion.oscillationAngularFrequency > 0)
        throw InputError(std::string(what) + ": wall '" + wall.name +
                         "' follows a motion table or oscillates; its motion is the scene's");
    return wall;
}
} // namespace

void Simulation::setWallVelocity(std::size_t w, const Vec3& velocity)
{
    checkFinite(velocity, "wall velocity");
    steadyWall(s_->world(), w, "wall velocity").motion.velocity = velocity;
}

void Simulation::setWallAngularVelocity(std::size_t w, const Vec3& angularVelocity)
{
    checkFinite(angularVelocity, "wall angular velocity");
    dem::Wall& wall = steadyWall(s_->world(), w, "wall angular velocity");
    const Vec3 axis = std::visit(
        [](const auto& shape) -> Vec3
        {
            using Shape = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<Shape, dem::PlaneShape>)
                return shape.normal;
            else if constexpr (std::is_same_v<Shape, dem::CylinderShape>)
                return shape.axis;
            else if constexpr (std::is_same_v<Shape, dem::DishShape>)
                return Vec3{0, 0, 1};
            else
                return Vec3{}; // a mesh turns about any axis
        },
        wall.shape);
    if (lengthSquared(axis) > 0 && length(cross(angularVelocity, axis)) > 1e-12 * length(angularVelocity))
        throw InputError("wall angular velocity: wall '" + wall.name +
                         "' turns only about its symmetry axis (its geometry would change)");
    wall.motion.angularVelocity = angularVelocity;
}

Vec3 Simulation::wallDisplacement(std::size_t w) const
{
    if (w >= world().walls.size())
        throw InputError("wall index " + std::to_string(w) + " is out of range");
    return world().walls[w].displacement;
}

WallLoad Simulation::wallLoad(std::size_t w) const
{
    if (w >= world().walls.size())
        throw InputError("wall index " + std::to_string(w) + " is out of range");
    const dem::Wall& wall = world().walls[w];
    const dem::WallLoad load = dem::wallLoad(world().wallContacts, static_cast<std::uint32_t>(w),
                                             wall.loadPoint + wall.displacement);
    return {load.force, load.torque};
}

ContactTable Simulation::contacts() const
{
    const dem::World& w = world();
    const std::vector<dem::ContactRecord> records = dem::evaluateContacts(w, 0.0);
    ContactTable t;
    for (const dem::ContactRecord& c : records)
    {
        t.i.push_back(w.particles.id[c.i]);
        t.j.push_back(c.wall ? -1 : std::int64_t(w.particles.id[c.partner]));
        t.wall.push_back(c.wall ? std::int32_t(c.partner) : -1);
        t.overlap.push_back(c.overlap);
        t.normal.push_back(c.normal);
        t.point.push_back(c.point);
        t.normalForce.push_back(c.normalForce);
        t.tangentialForce.push_back(c.tangentialForce);
    }
    return t;
}

dem::KineticEnergyParts Simulation::kineticEnergy() const
{
    return dem::kineticEnergyParts(world());
}

const dem::EnergyLedgerState* Simulation::ledger() const
{
    return s_->scene.measurements.energy ? &s_->ledger.state : nullptr;
}

} // namespace veridem::api
