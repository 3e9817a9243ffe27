// veridem's public C++ API: a DEM scene as one object that is built, stepped, read, changed and
// checkpointed. `veridem run` drives it (src/app/run_dem.cpp) and so does the Python module
// (src/python/); docs/python.md documents both. SI units throughout: m, s, kg, N, N m, rad/s.
//
// A Simulation owns the scene's world (particles, walls, materials, contact lists), its particle
// flow (inserters, outlets), its output files and, on MPI ranks, this rank's part of the
// decomposition. How the steps are executed (threads, kernels, schedules) stays inside: nothing
// here changes a bit of the result. Outputs and checkpoints happen at the scene's own times while
// it steps, exactly as in `veridem run`, so a scene driven from here writes the same files.
#pragma once

#include "core/vec3.h"
#include "dem/contact_diagnostics.h"
#include "dem/energy_ledger.h"
#include "dem/world.h"
#include "distributed/collective.h"

#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace veridem::api
{

struct SimulationOptions
{
    std::filesystem::path outDir;       // where the scene's files go (created if missing);
                                        // empty: no files are written (checkpoints still can be)
    bool speak = true;                  // start-up notes and warnings on stderr
    bool allowUnstableTimeStep = false; // run above the stability limit (warned), else refused
    bool strict = false;                // the plausibility warnings (io/plausibility.h) are errors
    std::string restartFile;            // continue from this checkpoint (empty: start afresh)
    const distributed::Collective* ranks = nullptr; // the MPI job's ranks (mpirun); null: one process
    std::uint64_t rebalanceEvery = 10;              // exchanges of particles between cuts of the regions
};

/// Why advance() returned before its last step.
enum class StopReason
{
    Completed,   // every requested step ran
    Interrupted, // the `interrupted` callback returned true between two runs of steps
    EndOfScene,  // the scene's duration was reached
};

/// A blow-up: a state that is not finite, or an overlap above the scene's limit. Thrown by
/// advance() after the outputs written so far are flushed; the message names the step, the
/// particle (by id) and the cause.
class BlowUp : public SimulationError
{
  public:
    BlowUp(const std::string& message, bool everyRank) : SimulationError(message), allRanks(everyRank) {}
    bool allRanks; // every MPI rank stopped at this step (the first reports it)
};

/// One row of every contact touching now, each listed once: particle i (by id) and its partner
/// (another particle's id, or a wall by index into wallNames()), in the state between steps.
struct ContactTable
{
    std::vector<std::uint32_t> i;      // particle id
    std::vector<std::int64_t> j;       // partner particle id, or -1 for a wall
    std::vector<std::int32_t> wall;    // wall index, or -1 for a particle pair
    std::vector<double> overlap;       // [m]
    std::vector<Vec3> normal;          // unit, from the partner towards i
    std::vector<Vec3> point;           // contact point [m]
    std::vector<Vec3> normalForce;     // on i [N]
    std::vector<Vec3> tangentialForce; // on i [N]
    std::size_t size() const { return i.size(); }
};

/// A wall's load: the sum of its contacts' forces on it [N] and their torque about its load point
/// (which moves with the wall) [N m].
struct WallLoad
{
    Vec3 force, torque;
};

class Simulation
{
  public:
    /// Reads a scene file (docs/scene-format.md; a "dem" scene).
    static Simulation fromFile(const std::filesystem::path& sceneFile, const SimulationOptions& options);
    /// Builds a scene from a TOML table (the same keys, checks and messages as a file); `name`
    /// stands for the file in messages and resolves relative paths in it.
    static Simulation fromTable(const toml::table& scene, const std::string& name,
                                const SimulationOptions& options);
    Simulation(Simulation&&) noexcept;
    Simulation& operator=(Simulation&&) noexcept;
    ~Simulation();

    // --- time ---------------------------------------------------------------------------------
    double dt() const;              // [s]
    double time() const;            // [s]: step() * dt() exactly as the step counts it
    std::uint64_t step() const;     // steps taken since the scene's start
    std::uint64_t lastStep() const; // the scene's duration in steps
    double outputInterval() const;  // [s]

    /// Runs up to `steps` steps (not past the scene's duration), with the outputs, checkpoints
    /// and particle flow at their times, in runs of at most ~50 ms of wall time; between two
    /// runs it asks `interrupted` (if given) whether to stop. Returns the steps taken and why it
    /// stopped. Throws BlowUp on a state that is not finite or an overlap above the limit.
    /// Collective on MPI ranks.
    std::uint64_t advance(std::uint64_t steps, StopReason* reason = nullptr,
                          const std::function<bool()>& interrupted = {});

    /// The particle-steps run by advance() on this rank (its own particles) so far [-].
    double particleSteps() const;
    /// The outputs (frames of particles.csv) written so far, this run's and a restored run's.
    std::size_t outputsWritten() const;
    /// On several ranks: how often the regions were cut (0 in one process).
    std::uint64_t regionCuts() const;

    /// Writes a checkpoint (the same format as `veridem run`'s) to `path`. Collective.
    void writeCheckpoint(const std::filesystem::path& path);
    /// Writes DIR/checkpoint.bin (the scene's own checkpoint path). Collective.
    void writeCheckpoint();
    std::filesystem::path checkpointPath() const;
    /// True if checkpointPath() holds the present step's state (written by advance()'s schedule or
    /// by writeCheckpoint() at this step, nothing restored since): a run stopping here need not
    /// write it again.
    bool checkpointIsCurrent() const;
    /// Restores a checkpoint written by this scene (the same table: comments and layout aside).
    /// The outputs continue after it only if it came from this Simulation's output directory.
    void restore(const std::filesystem::path& path);
    /// Closes the output files (also done by the destructor). Collective.
    void close();

    // --- reading and changing the state between steps ------------------------------------------
    /// The world: particles (dem::ParticleStore, slot order; ids in particles.id), walls,
    /// materials. Valid until the next call that changes the set of particles. On MPI ranks, this
    /// rank's store (owned particles first, then ghosts: ownedParticles()).
    const dem::World& world() const;
    std::size_t ownedParticles() const;
    /// True if a step may change where the particle arrays live (inserters, outlets, ranks).
    bool stepsMayMoveParticles() const;

    /// Moves the particle arrays to new memory (a copy) and returns their old memory, unchanged,
    /// for whoever still reads it: the Python module's views of a store that a step, an insertion
    /// or a removal may reallocate keep it alive this way (docs/python.md, "Views"). O(N).
    std::shared_ptr<const dem::ParticleStore> detachParticleArrays();
    /// Mutable particle store for the views the Python module hands out (velocities, external
    /// loads); the set of particles is changed only through addParticle/removeParticles.
    dem::ParticleStore& particleStore();

    /// Sets particle velocities / angular velocities by slot [m/s, rad/s].
    void setVelocity(std::size_t slot, const Vec3& v);
    void setAngularVelocity(std::size_t slot, const Vec3& w);
    /// A force [N] and torque [N m] added to the particle's contact sums every step until changed
    /// (drag, fields). Not saved in checkpoints: a script sets them again after restore.
    void setExternalForce(std::size_t slot, const Vec3& force, const Vec3& torque);
    /// Mutable rows of the external loads (allocated on first use; all zero).
    std::vector<Vec3>& externalForces();
    std::vector<Vec3>& externalTorques();

    /// Adds a sphere; returns its id. material by name; radius [m]; position [m]; velocities.
    std::uint32_t addParticle(const std::string& material, double radius, const Vec3& position,
                              const Vec3& velocity = {}, const Vec3& angularVelocity = {});
    /// Removes the particles with these ids (unknown ids refused, nothing removed).
    void removeParticles(const std::vector<std::uint32_t>& ids);

    /// The index of a wall by name (InputError naming the known walls if none).
    std::size_t wallIndex(const std::string& name) const;
    std::vector<std::string> wallNames() const;
    /// A wall's translation velocity [m/s] and angular velocity [rad/s] from now on (an analytic
    /// wall turns about its symmetry axis only; a wall following a motion table or oscillating
    /// is refused). The step integrates the displacement as for any steady motion.
    void setWallVelocity(std::size_t wall, const Vec3& velocity);
    void setWallAngularVelocity(std::size_t wall, const Vec3& angularVelocity);
    Vec3 wallDisplacement(std::size_t wall) const; // since t = 0 [m]
    WallLoad wallLoad(std::size_t wall) const;

    /// Every touching contact now (evaluated as the force stage does, on a copy of the history).
    ContactTable contacts() const;
    /// Kinetic energies [J] and the energy ledger's terms (if the scene keeps one: [output]
    /// energy = true), as in thermo.csv.
    dem::KineticEnergyParts kineticEnergy() const;
    const dem::EnergyLedgerState* ledger() const;

  private:
    struct State;
    explicit Simulation(std::unique_ptr<State> state);
    std::unique_ptr<State> s_;
};

/// The hash that ties a checkpoint to its scene: of the TOML table's content, so comments and
/// layout do not count.
std::uint64_t sceneHash(const toml::table& scene);

} // namespace veridem::api
