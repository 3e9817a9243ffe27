// (Above 500 lines: the writer and the reader of each record sit in one file, so that the order
// written and the order read can be compared line by line; a split would separate the two.)
#include "io/dem_checkpoint.h"

#include "io/bond_checkpoint.h"

#include <string>

namespace veridem::dem
{

/// The private state of the contact lists, with their contacts' history stores, for the checkpoint
/// (friend of NeighborList and WallContactList). The record order here is the file's. A store's
/// history scalars (acHS, wcHS, pbHS) are recorded only in scenes whose normal models declare some
/// (ContactHistoryStore::scalarCount, set by the reader from the scene's pair table before it
/// reads): so the files of every other scene are those of version 6 before the scalars existed,
/// and they are read as before.
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
        if (h.scalarCount > 0)
            out.array("acHS", h.scalars);
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
        if (h.scalarCount > 0)
            in.array("acHS", h.scalars);
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
        if (h.scalarCount > 0)
            out.array("wcHS", h.scalars);
        out.array("wcSt", w.start);
        out.array("wcDB", w.wallDisplacementAtBuild_);
        out.array("wcMN", w.meshNormal);
        out.array("wcTB", w.wallTurnAtBuild_);
        out.array("wcMF", w.meshFlat);
    }

    static void read(io::CheckpointReader& in, WallContactList& w, ContactHistoryStore& h,
                     std::size_t particles, const std::vector<Wall>& wallList)
    {
        const std::size_t walls = wallList.size();
        h.keepRolling = in.value<std::uint8_t>("wcRh") != 0;
        in.array("wcPa", w.particle);
        in.array("wcWa", w.wall);
        in.array("wcTS", h.spring);
        in.array("wcRS", h.rolling);
        if (h.scalarCount > 0)
            in.array("wcHS", h.scalars);
        in.array("wcSt", w.start);
        in.array("wcDB", w.wallDisplacementAtBuild_);
        in.array("wcMN", w.meshNormal);
        in.array("wcTB", w.wallTurnAtBuild_);
        in.array("wcMF", w.meshFlat);
        // The mesh candidates' triangle lists are not saved: those of the scene's own first build
        // do not belong to these slots, so the step falls back to the mesh grid (the same
        // contacts) until the next rebuild makes them again. A flat slot needs only its plane's
        // triangle (meshFlat, saved).
        w.meshTriangleStart.clear();
        w.meshTriangles.clear();
        const std::size_t slots = w.particle.size();
        bool ok = w.wall.size() == slots && h.spring.size() == slots &&
                  h.scalars.size() == slots * h.scalarCount &&
                  h.rolling.size() == (h.keepRolling ? slots : h.rolling.size()) &&
                  (h.rolling.empty() || h.rolling.size() == slots) && w.start.size() == particles + 1 &&
                  w.wallDisplacementAtBuild_.size() <= walls &&
                  (w.meshNormal.empty() || w.meshNormal.size() == slots) &&
                  (w.wallTurnAtBuild_.empty() || w.wallTurnAtBuild_.size() == walls) &&
                  w.meshFlat.size() == w.meshNormal.size();
        ok = ok && below(w.particle, particles) && below(w.wall, walls) && offsets(w.start, slots);
        for (std::size_t k = 0; ok && k < w.meshFlat.size(); ++k) // (a flat slot's triangle is its mesh's)
            if (w.meshFlat[k] != WallContactList::kNotFlat)
            {
                const auto* mesh = std::get_if<MeshShape>(&wallList[w.wall[k]].shape);
                ok = mesh && w.meshFlat[k] < mesh->mesh->triangles.size();
            }
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
                          candidates = n.activeFirst.size();
        // Between a rebuild of the slots and the next force stage (particles inserted or removed
        // between steps: world.h, rebuildAfterParticleChange) the candidates keep only their keys
        // and history; the rest of their record is made by the next sub-list rebuild.
        const bool pending = n.slotsRebuilt_ && n.activeStale_ && n.activeSlots.empty() &&
                             n.activeMass.empty() && n.activeDeferred.empty();
        bool ok = n.second.size() == slots && n.deferredIndex.size() == slots &&
                  n.firstStart.size() == particles + 1 && n.incomingStart.size() == particles + 1 &&
                  n.incomingEntry.size() == entries && n.activeSecond.size() == candidates &&
                  h.spring.size() == candidates && (h.rolling.empty() || h.rolling.size() == candidates) &&
                  h.scalars.size() == candidates * h.scalarCount &&
                  (!h.keepRolling || h.rolling.size() == candidates) && h.formed.size() == candidates &&
                  (pending || (n.activeSlots.size() == candidates && n.activeMass.size() == candidates &&
                               n.activeDeferred.size() == candidates)) &&
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

/// The inserters' and outlets' state as arrays (the file's order).
struct FlowRecords
{
    std::vector<std::uint64_t> random, inserted, removed;
    std::vector<Real> insertedMass, removedMass;
    std::vector<std::uint8_t> warned;
};

FlowRecords flowRecords(const dem::ParticleFlow* flow)
{
    FlowRecords r;
    if (!flow)
        return r;
    for (const dem::Inserter& in : flow->inserters)
    {
        r.random.insert(r.random.end(), in.random.state.begin(), in.random.state.end());
        r.inserted.push_back(in.inserted);
        r.insertedMass.push_back(in.insertedMass);
        r.warned.push_back(in.warnedFull);
    }
    for (const dem::Outlet& o : flow->outlets)
    {
        r.removed.push_back(o.count);
        r.removedMass.push_back(o.mass);
    }
    return r;
}

/// The pairs through a periodic image (dem/periodic.h) and their history; empty without periodic
/// axes.
void writePeriodicPairs(CheckpointWriter& out, const dem::PeriodicPairs& pairs)
{
    out.array("pbFi", pairs.first);
    out.array("pbSe", pairs.second);
    out.array("pbSh", pairs.shift);
    out.array("pbMa", pairs.mass);
    out.array("pbSp", pairs.history.spring);
    out.array("pbRo", pairs.history.rolling);
    out.array("pbMB", pairs.history.formed);
    if (pairs.history.scalarCount > 0)
        out.array("pbHS", pairs.history.scalars);
}

void readPeriodicPairs(CheckpointReader& in, dem::PeriodicPairs& pairs, bool keepRolling,
                       std::size_t particles)
{
    in.array("pbFi", pairs.first);
    const std::size_t count = pairs.first.size();
    readSized(in, "pbSe", pairs.second, count);
    readSized(in, "pbSh", pairs.shift, count);
    readSized(in, "pbMa", pairs.mass, count);
    readSized(in, "pbSp", pairs.history.spring, count);
    readSized(in, "pbRo", pairs.history.rolling, keepRolling ? count : 0);
    readSized(in, "pbMB", pairs.history.formed, count);
    if (pairs.history.scalarCount > 0)
        readSized(in, "pbHS", pairs.history.scalars, count * pairs.history.scalarCount);
    pairs.history.keepRolling = keepRolling;
    for (std::size_t k = 0; k < count; ++k)
        if (pairs.first[k] >= pairs.second[k] || pairs.second[k] >= particles)
            in.fail("is corrupt: a periodic pair names particles " + std::to_string(pairs.first[k]) +
                    " and " + std::to_string(pairs.second[k]));
}

} // namespace

void writeDemCheckpoint(const std::filesystem::path& path, const dem::World& world, std::uint64_t sceneHash,
                        const CheckpointOutputs& outputs, const dem::EnergyLedgerState* ledger,
                        const dem::ParticleFlow* flow)
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
    out.array("pId ", p.id);
    out.array("pFix", p.fixed);
    const FlowRecords f = flowRecords(flow);
    out.value("flNx", flow ? flow->nextId : std::uint32_t(p.size()));
    out.array("flRn", f.random);
    out.array("flIc", f.inserted);
    out.array("flIm", f.insertedMass);
    out.array("flWa", f.warned);
    out.array("flOc", f.removed);
    out.array("flOm", f.removedMass);

    std::vector<Vec3> displacement, velocity, angularVelocity, rotation;
    std::vector<Real> clock, turned;
    for (const dem::Wall& w : world.walls)
    {
        displacement.push_back(w.displacement);
        velocity.push_back(w.motion.velocity);
        angularVelocity.push_back(w.motion.angularVelocity);
        clock.push_back(w.clock);
        // A mesh wall's frame (its rows of R) and accumulated angle; the identity for the others.
        const auto* mesh = std::get_if<dem::MeshShape>(&w.shape);
        const dem::MeshShape identity;
        for (const Vec3& row : (mesh ? mesh : &identity)->rotation)
            rotation.push_back(row);
        turned.push_back(mesh ? mesh->turned : 0);
    }
    out.array("wDis", displacement);
    out.array("wVel", velocity);
    out.array("wAng", angularVelocity);
    out.array("wClk", clock);
    out.array("wRot", rotation);
    out.array("wTrn", turned);

    dem::CheckpointAccess::write(out, world.neighbors, world.pairHistory);
    writePeriodicPairs(out, world.periodicPairs);
    dem::CheckpointAccess::write(out, world.wallContacts, world.wallHistory);
    if (world.bonds.enabled)
        writeBondRecords(out, world.bonds);
    out.value("enLg", std::uint8_t(ledger != nullptr));
    if (ledger)
        out.array("enSt", ledgerValues(*ledger));
    out.outputs(outputs);
    out.commit();
}

CheckpointOutputs readDemCheckpoint(const std::filesystem::path& path, dem::World& world,
                                    std::uint64_t sceneHash, dem::EnergyLedgerState* ledger,
                                    dem::ParticleFlow* flow)
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
    // The checkpoint's particle count (inserters and outlets change the scene's).
    in.array("pPos", p.position);
    const std::size_t n = p.position.size();
    if (n != world.particles.id.size() && (!flow || flow->empty()))
        in.fail("has " + std::to_string(n) + " particles, the scene " + std::to_string(p.id.size()) +
                " (was a particle file changed?)");
    readSized(in, "pVel", p.velocity, n);
    readSized(in, "pAng", p.angularVelocity, n);
    readSized(in, "pFor", p.force, n);
    readSized(in, "pTor", p.torque, n);
    readSized(in, "pRad", p.radius, n);
    readSized(in, "pMas", p.mass, n);
    readSized(in, "pIMa", p.invMass, n);
    readSized(in, "pIIn", p.invInertia, n);
    readSized(in, "pMat", p.material, n);
    readSized(in, "pId ", p.id, n);
    readSized(in, "pFix", p.fixed, n);
    const std::size_t inserters = flow ? flow->inserters.size() : 0,
                      outlets = flow ? flow->outlets.size() : 0;
    FlowRecords f;
    const auto nextId = in.value<std::uint32_t>("flNx");
    readSized(in, "flRn", f.random, 4 * inserters);
    readSized(in, "flIc", f.inserted, inserters);
    readSized(in, "flIm", f.insertedMass, inserters);
    readSized(in, "flWa", f.warned, inserters);
    readSized(in, "flOc", f.removed, outlets);
    readSized(in, "flOm", f.removedMass, outlets);
    if (flow)
    {
        flow->nextId = nextId;
        for (std::size_t k = 0; k < inserters; ++k)
        {
            dem::Inserter& i = flow->inserters[k];
            std::copy(f.random.begin() + std::ptrdiff_t(4 * k), f.random.begin() + std::ptrdiff_t(4 * k + 4),
                      i.random.state.begin());
            i.inserted = f.inserted[k];
            i.insertedMass = f.insertedMass[k];
            i.warnedFull = f.warned[k] != 0;
        }
        for (std::size_t k = 0; k < outlets; ++k)
        {
            flow->outlets[k].count = f.removed[k];
            flow->outlets[k].mass = f.removedMass[k];
        }
    }
    for (const std::uint32_t m : p.material)
        if (m >= world.materials.size())
            in.fail("is corrupt: a particle names material " + std::to_string(m));
    p.refreshPositionRadius();

    std::vector<Vec3> displacement, velocity, angularVelocity, rotation;
    std::vector<Real> clock, turned;
    const std::size_t walls = world.walls.size();
    readSized(in, "wDis", displacement, walls);
    readSized(in, "wVel", velocity, walls);
    readSized(in, "wAng", angularVelocity, walls);
    readSized(in, "wClk", clock, walls);
    readSized(in, "wRot", rotation, 3 * walls);
    readSized(in, "wTrn", turned, walls);
    for (std::size_t k = 0; k < walls; ++k)
    {
        dem::Wall& w = world.walls[k];
        w.displacement = displacement[k];
        w.motion.velocity = velocity[k];
        w.motion.angularVelocity = angularVelocity[k];
        w.clock = clock[k];
        if (auto* mesh = std::get_if<dem::MeshShape>(&w.shape))
        {
            mesh->rotation = {rotation[3 * k], rotation[3 * k + 1], rotation[3 * k + 2]};
            mesh->turned = turned[k];
        }
    }

    // The history scalars the scene's models declare (prepare() sets the same count).
    if (world.pairs.count() != world.materials.size())
        world.pairs.build(world.materials);
    const unsigned scalars = world.pairs.historyScalars();
    world.pairHistory.scalarCount = world.wallHistory.scalarCount = world.periodicPairs.history.scalarCount =
        scalars;
    dem::CheckpointAccess::read(in, world.neighbors, world.pairHistory, n);
    readPeriodicPairs(in, world.periodicPairs, world.pairHistory.keepRolling, n);
    dem::CheckpointAccess::read(in, world.wallContacts, world.wallHistory, n, world.walls);
    world.wallContacts.markActivity(world.walls); // (not saved: the walls' clocks give it)
    if (world.bonds.enabled)
        readBondRecords(in, world.bonds);
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
    dem::refreshFixedParticles(world);
    world.prepared = true;
    return outputs;
}

} // namespace veridem::io
