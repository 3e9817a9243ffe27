#include "io/dem_checkpoint.h"

#include <string>

namespace veridem::dem
{

/// The private state of the contact lists, with their contacts' history stores, for the checkpoint
/// (friend of NeighborList and WallContactList). The record order here is the file's.
struct CheckpointAccess
{
    static void write(io::CheckpointWriter& out, const NeighborList& n, const ContactHistoryStore& h)
    {
        out.value("skin", n.skin);
        out.value("iskn", n.innerSkin);
        out.value("rech", n.reach);
        out.value("nbRh", std::uint8_t(h.keepRolling));
        out.array("nbFi", n.first);
        out.array("nbSe", n.second);
        out.array("nbFS", n.firstStart);
        out.array("nbDI", n.deferredIndex);
        out.array("nbDe", n.deferred);
        out.array("nbIS", n.incomingStart);
        out.array("nbIE", n.incomingEntry);
        out.array("acSl", n.activeSlots);
        out.array("acFi", n.activeFirst);
        out.array("acSe", n.activeSecond);
        out.array("acSp", h.spring);
        out.array("acRo", h.rolling);
        out.array("acMB", h.formed);
        out.array("acMa", n.activeMass);
        out.array("acDe", n.activeDeferred);
        out.value("nbSR", std::uint8_t(n.slotsRebuilt_));
        out.array("nbPB", n.positionAtBuild_);
        out.array("nbPA", n.positionAtActiveBuild_);
        out.value("nbAS", std::uint8_t(n.activeStale_));
        out.value("nbAA", n.activeAge_);
        out.value("nbAR", std::uint64_t(n.activeRebuilds_));
        out.value("nbRB", std::uint64_t(n.rebuilds_));
    }

    static void read(io::CheckpointReader& in, NeighborList& n, ContactHistoryStore& h, std::size_t particles)
    {
        in.value("skin", n.skin);
        in.value("iskn", n.innerSkin);
        in.value("rech", n.reach);
        h.keepRolling = in.value<std::uint8_t>("nbRh") != 0;
        in.array("nbFi", n.first);
        in.array("nbSe", n.second);
        in.array("nbFS", n.firstStart);
        in.array("nbDI", n.deferredIndex);
        in.array("nbDe", n.deferred);
        in.array("nbIS", n.incomingStart);
        in.array("nbIE", n.incomingEntry);
        in.array("acSl", n.activeSlots);
        in.array("acFi", n.activeFirst);
        in.array("acSe", n.activeSecond);
        in.array("acSp", h.spring);
        in.array("acRo", h.rolling);
        in.array("acMB", h.formed);
        in.array("acMa", n.activeMass);
        in.array("acDe", n.activeDeferred);
        n.slotsRebuilt_ = in.value<std::uint8_t>("nbSR") != 0;
        in.array("nbPB", n.positionAtBuild_);
        in.array("nbPA", n.positionAtActiveBuild_);
        n.activeStale_ = in.value<std::uint8_t>("nbAS") != 0;
        in.value("nbAA", n.activeAge_);
        n.activeRebuilds_ = static_cast<std::size_t>(in.value<std::uint64_t>("nbAR"));
        n.rebuilds_ = static_cast<std::size_t>(in.value<std::uint64_t>("nbRB"));
        check(in, n, h, particles);
    }

    static void write(io::CheckpointWriter& out, const WallContactList& w, const ContactHistoryStore& h)
    {
        out.value("wcRh", std::uint8_t(h.keepRolling));
        out.array("wcPa", w.particle);
        out.array("wcWa", w.wall);
        out.array("wcTS", h.spring);
        out.array("wcRS", h.rolling);
        out.array("wcSt", w.start);
        out.array("wcDB", w.wallDisplacementAtBuild_);
    }

    static void read(io::CheckpointReader& in, WallContactList& w, ContactHistoryStore& h,
                     std::size_t particles, std::size_t walls)
    {
        h.keepRolling = in.value<std::uint8_t>("wcRh") != 0;
        in.array("wcPa", w.particle);
        in.array("wcWa", w.wall);
        in.array("wcTS", h.spring);
        in.array("wcRS", h.rolling);
        in.array("wcSt", w.start);
        in.array("wcDB", w.wallDisplacementAtBuild_);
        const std::size_t slots = w.particle.size();
        bool ok = w.wall.size() == slots && h.spring.size() == slots &&
                  h.rolling.size() == (h.keepRolling ? slots : h.rolling.size()) &&
                  (h.rolling.empty() || h.rolling.size() == slots) && w.start.size() == particles + 1 &&
                  w.wallDisplacementAtBuild_.size() <= walls;
        ok = ok && below(w.particle, particles) && below(w.wall, walls) && offsets(w.start, slots);
        if (!ok)
            in.fail("is corrupt: the wall-contact list does not fit the scene");
    }

  private:
    template <class V> static bool below(const V& values, std::size_t bound, bool allowInBlock = false)
    {
        for (const auto v : values)
            if (v >= bound && !(allowInBlock && v == NeighborList::kInBlock))
                return false;
        return true;
    }
    /// Ascending offsets from 0 to `total`.
    static bool offsets(const std::vector<std::uint32_t>& start, std::size_t total)
    {
        if (start.empty() || start.front() != 0 || start.back() != total)
            return false;
        for (std::size_t k = 1; k < start.size(); ++k)
            if (start[k] < start[k - 1])
                return false;
        return true;
    }

    /// Every index in range and every size consistent, so a crafted file cannot make the step read
    /// out of bounds (the checksum already catches accidental damage).
    static void check(io::CheckpointReader& in, const NeighborList& n, const ContactHistoryStore& h,
                      std::size_t particles)
    {
        const std::size_t slots = n.first.size(), entries = n.deferred.size(),
                          candidates = n.activeSlots.size();
        bool ok = n.second.size() == slots && n.deferredIndex.size() == slots &&
                  n.firstStart.size() == particles + 1 && n.incomingStart.size() == particles + 1 &&
                  n.incomingEntry.size() == entries && n.activeFirst.size() == candidates &&
                  n.activeSecond.size() == candidates && h.spring.size() == candidates &&
                  (h.rolling.empty() || h.rolling.size() == candidates) &&
                  (!h.keepRolling || h.rolling.size() == candidates) && h.formed.size() == candidates &&
                  n.activeMass.size() == candidates && n.activeDeferred.size() == candidates &&
                  (n.positionAtBuild_.empty() || n.positionAtBuild_.size() == particles) &&
                  (n.positionAtActiveBuild_.empty() || n.positionAtActiveBuild_.size() == particles);
        ok = ok && below(n.first, particles) && below(n.second, particles) &&
             below(n.deferredIndex, entries, true) && below(n.incomingEntry, entries) &&
             below(n.activeSlots, slots) && below(n.activeFirst, particles) &&
             below(n.activeSecond, particles) && below(n.activeDeferred, entries, true) &&
             offsets(n.firstStart, slots) && offsets(n.incomingStart, entries);
        if (!ok)
            in.fail("is corrupt: the neighbour list does not fit the scene");
    }
};

} // namespace veridem::dem

namespace veridem::io
{

namespace
{

template <class T>
void readSized(CheckpointReader& in, const char (&tag)[5], std::vector<T>& values, std::size_t n)
{
    in.array(tag, values);
    if (values.size() != n)
        in.fail("has " + std::to_string(values.size()) + " elements in record '" + tag + "', the scene " +
                std::to_string(n) + " (was a particle file changed?)");
}

/// The energy ledger's state as one array (the file's order) and back.
std::vector<Real> ledgerValues(const dem::EnergyLedgerState& s)
{
    return {s.started ? 1.0 : 0.0,
            s.initialEnergy,
            s.elasticEnergy,
            s.gravityWork,
            s.wallWork,
            s.normalDamping,
            s.tangentialDamping,
            s.friction,
            s.rolling,
            s.wallPower,
            s.normalDampingPower,
            s.tangentialDampingPower,
            s.rollingPower,
            s.tangentialSpringEnergy,
            s.rollingSpringEnergy,
            s.adhesion};
}
void setLedgerValues(dem::EnergyLedgerState& s, const std::vector<Real>& v)
{
    s.started = v[0] != 0;
    s.initialEnergy = v[1];
    s.elasticEnergy = v[2];
    s.gravityWork = v[3];
    s.wallWork = v[4];
    s.normalDamping = v[5];
    s.tangentialDamping = v[6];
    s.friction = v[7];
    s.rolling = v[8];
    s.wallPower = v[9];
    s.normalDampingPower = v[10];
    s.tangentialDampingPower = v[11];
    s.rollingPower = v[12];
    s.tangentialSpringEnergy = v[13];
    s.rollingSpringEnergy = v[14];
    s.adhesion = v[15];
}

} // namespace

void writeDemCheckpoint(const std::filesystem::path& path, const dem::World& world, std::uint64_t sceneHash,
                        const CheckpointOutputs& outputs, const dem::EnergyLedgerState* ledger)
{
    CheckpointWriter out(path, CheckpointEngine::Dem3d, sceneHash);
    out.value("time", world.time);
    out.value("step", world.stepCount);
    const dem::StepHealth& h = world.health;
    out.value("hMax", h.maxOverlapRatio);
    out.value("hWor", h.worstParticle);
    out.value("hPai", std::uint64_t(h.touchingPairs));
    out.value("hWal", std::uint64_t(h.touchingWalls));
    out.value("hFin", std::uint8_t(h.finite));
    out.value("hNon", h.firstNonFinite);

    const dem::ParticleStore& p = world.particles;
    out.array("pPos", p.position);
    out.array("pVel", p.velocity);
    out.array("pAng", p.angularVelocity);
    out.array("pFor", p.force);
    out.array("pTor", p.torque);
    out.array("pRad", p.radius);
    out.array("pMas", p.mass);
    out.array("pIMa", p.invMass);
    out.array("pIIn", p.invInertia);
    out.array("pMat", p.material);

    std::vector<Vec3> displacement, velocity, angularVelocity;
    std::vector<Real> clock;
    for (const dem::Wall& w : world.walls)
    {
        displacement.push_back(w.displacement);
        velocity.push_back(w.motion.velocity);
        angularVelocity.push_back(w.motion.angularVelocity);
        clock.push_back(w.clock);
    }
    out.array("wDis", displacement);
    out.array("wVel", velocity);
    out.array("wAng", angularVelocity);
    out.array("wClk", clock);

    dem::CheckpointAccess::write(out, world.neighbors, world.pairHistory);
    dem::CheckpointAccess::write(out, world.wallContacts, world.wallHistory);
    out.value("enLg", std::uint8_t(ledger != nullptr));
    if (ledger)
        out.array("enSt", ledgerValues(*ledger));
    out.outputs(outputs);
    out.commit();
}

CheckpointOutputs readDemCheckpoint(const std::filesystem::path& path, dem::World& world,
                                    std::uint64_t sceneHash, dem::EnergyLedgerState* ledger)
{
    CheckpointReader in(path, CheckpointEngine::Dem3d, sceneHash);
    in.value("time", world.time);
    in.value("step", world.stepCount);
    dem::StepHealth& h = world.health;
    in.value("hMax", h.maxOverlapRatio);
    in.value("hWor", h.worstParticle);
    h.touchingPairs = static_cast<std::size_t>(in.value<std::uint64_t>("hPai"));
    h.touchingWalls = static_cast<std::size_t>(in.value<std::uint64_t>("hWal"));
    h.finite = in.value<std::uint8_t>("hFin") != 0;
    in.value("hNon", h.firstNonFinite);

    dem::ParticleStore& p = world.particles;
    const std::size_t n = p.size();
    readSized(in, "pPos", p.position, n);
    readSized(in, "pVel", p.velocity, n);
    readSized(in, "pAng", p.angularVelocity, n);
    readSized(in, "pFor", p.force, n);
    readSized(in, "pTor", p.torque, n);
    readSized(in, "pRad", p.radius, n);
    readSized(in, "pMas", p.mass, n);
    readSized(in, "pIMa", p.invMass, n);
    readSized(in, "pIIn", p.invInertia, n);
    readSized(in, "pMat", p.material, n);
    for (const std::uint32_t m : p.material)
        if (m >= world.materials.size())
            in.fail("is corrupt: a particle names material " + std::to_string(m));
    p.refreshPositionRadius();

    std::vector<Vec3> displacement, velocity, angularVelocity;
    std::vector<Real> clock;
    const std::size_t walls = world.walls.size();
    readSized(in, "wDis", displacement, walls);
    readSized(in, "wVel", velocity, walls);
    readSized(in, "wAng", angularVelocity, walls);
    readSized(in, "wClk", clock, walls);
    for (std::size_t k = 0; k < walls; ++k)
    {
        dem::Wall& w = world.walls[k];
        w.displacement = displacement[k];
        w.motion.velocity = velocity[k];
        w.motion.angularVelocity = angularVelocity[k];
        w.clock = clock[k];
    }

    dem::CheckpointAccess::read(in, world.neighbors, world.pairHistory, n);
    dem::CheckpointAccess::read(in, world.wallContacts, world.wallHistory, n, walls);
    world.wallContacts.markActivity(world.walls); // (not saved: the walls' clocks give it)
    const bool hasLedger = in.value<std::uint8_t>("enLg") != 0;
    if (hasLedger != (ledger != nullptr))
        in.fail(hasLedger ? "keeps an energy ledger, the scene does not"
                          : "keeps no energy ledger, the scene does");
    if (ledger)
    {
        std::vector<Real> values;
        in.array("enSt", values);
        if (values.size() != ledgerValues(dem::EnergyLedgerState{}).size())
            in.fail("is corrupt: the energy ledger has " + std::to_string(values.size()) + " values");
        setLedgerValues(*ledger, values);
    }
    CheckpointOutputs outputs = in.outputs();
    in.finish();
    world.prepared = true;
    return outputs;
}

} // namespace veridem::io
