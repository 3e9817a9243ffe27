// api::Simulation: a DEM scene read (or restored), stepped with its outputs, checkpoints and
// particle flow at their times. On several MPI ranks each rank steps its region's particles
// (distributed/rank_step.h) and the first writes the files from the whole world gathered
// (distributed/rank_gather.h). Reading and changing the state between steps: simulation_access.cpp.
#include "api/simulation.h"

#include "api/rolling_note.h"
#include "api/simulation_state.h"
#include "api/start_notes.h"
#include "io/plausibility.h"

namespace veridem::api
{

std::uint64_t sceneHash(const toml::table& scene)
{
    std::ostringstream text;
    text << toml::toml_formatter(scene);        // (the content only: no comments, one layout)
    std::uint64_t hash = 0xcbf29ce484222325ull; // FNV-1a
    for (const char c : text.str())
    {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

Simulation::Simulation(std::unique_ptr<State> state) : s_(std::move(state)) {}
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;
Simulation::~Simulation()
{
    if (s_)
        try
        {
            s_->closeOutputs();
        }
        catch (...) // (a destructor does not throw; close() reports a failed write)
        {
        }
}

Simulation Simulation::fromFile(const std::filesystem::path& sceneFile, const SimulationOptions& options)
{
    return fromTable(io::parseFile(sceneFile.string()), sceneFile.string(), options);
}

Simulation Simulation::fromTable(const toml::table& table, const std::string& name,
                                 const SimulationOptions& options)
{
    auto s = std::make_unique<State>();
    s->name = name;
    s->options = options;
    s->severalRanks = options.ranks && options.ranks->size() > 1;
    s->root = !s->severalRanks || options.ranks->rank() == 0; // prints and writes the files
    const bool speak = s->root && options.speak;
    {
        // (every rank reads the scene; the first prints its warnings)
        const app::SilencedStream quiet(stderr, !speak);
        s->scene = io::readDemScene(table, name);
    }
    io::DemScene& scene = s->scene;
    dem::World& world = scene.world;
    io::reportPlausibility(scene, name, options.strict, speak); // (io/plausibility.h)
    checkTimeStep(scene, name, options.allowUnstableTimeStep, speak);
    if (speak)
        printRollingFrictionNote(world); // (api/rolling_note.h)
    s->hash = sceneHash(table);
    s->totalSteps = static_cast<std::uint64_t>(std::llround(scene.duration / scene.dt));
    s->outputEvery = std::max<std::uint64_t>(1, std::llround(scene.outputInterval / scene.dt));
    s->checkpointEvery = scene.checkpointInterval > 0
                             ? std::max<std::uint64_t>(1, std::llround(scene.checkpointInterval / scene.dt))
                             : 0;
    std::optional<io::CheckpointOutputs> saved;
    dem::ParticleFlow& flow = scene.flow;
    if (!options.restartFile.empty())
    {
        saved = io::readDemCheckpoint(options.restartFile, world, s->hash, s->ledgerState(), &flow);
        if (saved->fileBytes.size() != s->outputFiles())
            throw InputError("checkpoint '" + options.restartFile + "' is corrupt: it records " +
                             std::to_string(saved->fileBytes.size()) + " output files, this run has " +
                             std::to_string(s->outputFiles()));
        if (world.stepCount > s->totalSteps)
            throw InputError("checkpoint '" + options.restartFile + "' is at step " +
                             std::to_string(world.stepCount) + ", after the scene's last step " +
                             std::to_string(s->totalSteps));
        if (speak)
            std::fprintf(stderr, "veridem: restarting from '%s' at step %llu (t = %.9g s)\n",
                         options.restartFile.c_str(), static_cast<unsigned long long>(world.stepCount),
                         world.time);
    }
    else if (!s->severalRanks) // (on several ranks, each prepares its part: RankStep::distribute)
    {
        dem::prepare(world);
        if (!flow.empty())
            flow.apply(world, scene.dt); // (step 0 is a flow step)
    }
    // Several ranks: each keeps its region's particles and their ghosts (distributed/rank_step.h).
    if (s->severalRanks)
    {
        s->rankStep.emplace(*options.ranks, options.rebalanceEvery);
        s->rankStep->distribute(world);
        if (!saved && !flow.empty())
            distributed::applyFlow(flow, world, *s->rankStep, scene.dt); // (step 0 is a flow step)
        if (saved) // (the checkpoint's totals are counted once, by the first rank)
        {
            distributed::countOnFirstRank(flow.outlets, *options.ranks);
            if (!s->root)
                dem::forEachAmount(s->ledger.state, [](Real& a) { a = 0; });
        }
    }
    world.wallContacts.setRecordLoads(s->wallLoads());
    if (scene.measurements.energy)
    {
        s->ledger.start(world); // (a restored ledger keeps its state)
        world.observer = &s->ledger;
    }
    s->openOutputs(saved ? &*saved : nullptr);
    if (!saved)
        s->recordOutputs();
    return Simulation(std::move(s));
}

double Simulation::dt() const
{
    return s_->scene.dt;
}
double Simulation::time() const
{
    return s_->scene.world.time;
}
std::uint64_t Simulation::step() const
{
    return s_->scene.world.stepCount;
}
std::uint64_t Simulation::lastStep() const
{
    return s_->totalSteps;
}
double Simulation::outputInterval() const
{
    return s_->scene.outputInterval;
}
const dem::World& Simulation::world() const
{
    return s_->scene.world;
}
std::size_t Simulation::ownedParticles() const
{
    return s_->rankStep ? s_->rankStep->owned() : s_->scene.world.particles.size();
}
bool Simulation::stepsMayMoveParticles() const
{
    return !s_->scene.flow.empty() || s_->severalRanks;
}
std::filesystem::path Simulation::checkpointPath() const
{
    return s_->options.outDir / "checkpoint.bin";
}

std::uint64_t Simulation::advance(std::uint64_t steps, StopReason* reason,
                                  const std::function<bool()>& interrupted)
{
    State& st = *s_;
    dem::World& world = st.world();
    dem::ParticleFlow& flow = st.scene.flow;
    const std::uint64_t first = world.stepCount;
    const std::uint64_t end = std::min(st.totalSteps, first + std::min(steps, st.totalSteps));
    constexpr std::uint64_t kMaxChunk = 1024;
    StopReason why = end < first + steps ? StopReason::EndOfScene : StopReason::Completed;
    dem::syncExternalLoads(world.particles); // (loads changed since the last step, into its sums)
    // In runs of steps up to the next output, checkpoint or flow step (dem::advance: the bits of
    // step() calls, the kick passes fused), stopping after the first step whose state is not
    // finite or whose overlap exceeds the limit. A run is at most `chunk` steps, sized to ~10-50 ms
    // of wall time, so that `interrupted` is asked often (the bits do not depend on where the
    // runs end).
    for (std::uint64_t s = world.stepCount; s < end;)
    {
        std::uint64_t runEnd = std::min({(s / st.outputEvery + 1) * st.outputEvery, s + st.chunk, end});
        if (st.checkpointEvery)
            runEnd = std::min(runEnd, (s / st.checkpointEvery + 1) * st.checkpointEvery);
        if (!flow.empty()) // particles come and go between runs of steps
            runEnd = std::min(runEnd, (s / flow.everySteps + 1) * flow.everySteps);
        const auto runStart = std::chrono::steady_clock::now();
        const std::uint64_t done = dem::advance(world, st.scene.dt, runEnd - s, st.scene.maxOverlapFraction);
        s += done;
        // (the count changes with a flow; on several ranks, this rank's own particles)
        st.particleSteps +=
            double(done) * double(st.rankStep ? st.rankStep->owned() : world.particles.size());
        if (s < runEnd || !world.health.finite || world.health.maxOverlapRatio > st.scene.maxOverlapFraction)
            st.blowUp();
        double runSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
        // Several ranks agree on the next run's length and on a stop (each is asked at its own
        // moment): the largest of their values.
        double agreed[2] = {runSeconds, interrupted && interrupted() ? 1.0 : 0.0};
        if (st.rankStep)
            st.options.ranks->max(agreed);
        runSeconds = agreed[0];
        if (runSeconds < 0.01 && st.chunk < kMaxChunk)
            st.chunk *= 2;
        else if (runSeconds > 0.05 && st.chunk > 1)
            st.chunk /= 2;
        if (!flow.empty() && s % flow.everySteps == 0)
            st.applyFlow();
        if (s % st.outputEvery == 0 || s == st.totalSteps)
            st.recordOutputs();
        if (st.checkpointEvery && (s % st.checkpointEvery == 0 || s == st.totalSteps))
        {
            st.writeCheckpoint(checkpointPath());
            st.ownCheckpointStep = s;
        }
        if (agreed[1] != 0 && s < end)
        {
            why = StopReason::Interrupted;
            break;
        }
    }
    if (reason)
        *reason = why;
    return world.stepCount - first;
}

std::size_t Simulation::outputsWritten() const
{
    return s_->recorder ? s_->recorder->framesWritten() : 0;
}
double Simulation::particleSteps() const
{
    return s_->particleSteps;
}
std::uint64_t Simulation::regionCuts() const
{
    return s_->rankStep ? s_->rankStep->cuts() : 0;
}

void Simulation::writeCheckpoint(const std::filesystem::path& path)
{
    s_->writeCheckpoint(path);
}
void Simulation::writeCheckpoint()
{
    s_->writeCheckpoint(checkpointPath());
    s_->ownCheckpointStep = step();
}
bool Simulation::checkpointIsCurrent() const
{
    return s_->ownCheckpointStep && *s_->ownCheckpointStep == step();
}
void Simulation::close()
{
    s_->closeOutputs();
}

void Simulation::restore(const std::filesystem::path& path)
{
    State& st = *s_;
    if (st.severalRanks)
        throw InputError("restore: on several MPI ranks, restart with `veridem run --restart` instead");
    dem::World& world = st.world();
    dem::ParticleStore& p = world.particles;
    p.externalForce.clear(); // (not in checkpoints: set again after a restore)
    p.externalTorque.clear();
    st.ownCheckpointStep.reset();
    const io::CheckpointOutputs saved =
        io::readDemCheckpoint(path, world, st.hash, st.ledgerState(), &st.scene.flow);
    if (st.recorder && saved.fileBytes.size() == st.outputFiles() &&
        std::filesystem::equivalent(path.parent_path().empty() ? "." : path.parent_path(), st.options.outDir))
    {
        st.closeOutputs();
        st.closed = false;
        st.recorder.reset(); // (each file closed before it is opened again at the checkpoint's size)
        st.thermo.reset();
        st.contacts.reset();
        st.region.reset();
        st.walls.reset();
        st.outlets.reset();
        st.openOutputs(&saved);
    }
    world.wallContacts.setRecordLoads(st.wallLoads());
}

} // namespace veridem::api
