// Particles in and out of a run: inserters (`[[insert]]`) that add particles in a region at a
// count or a rate over a time window, and outlets (`[[outlet]]`) that remove the particles whose
// centre enters a region (docs/scene-format.md). Both act between steps, at every
// `ParticleFlow::everySteps`-th step (the driver stops its runs of steps there), never inside
// step(): a scene without them runs exactly the step it runs without this file.
//
// Insertion draws every random number from the inserter's own generator (dem/random.h), serially,
// so the particles are the same for any thread count. A new particle overlaps no particle and no
// wall: the candidate position is tested against the particles near it on a grid kept from one
// event to the next (ParticleIndex, rebuilt only after the contact lists were) and against every
// wall; after `kAttempts` failed positions the region is full: the inserter says so once
// (stderr) and tries again at the next event. The new particles join the contact lists without a
// rebuild where the scene allows it (dem/particle_changes.h, addInsertedParticles), so an event
// that only inserts costs its own particles. An outlet retires the particles whose centre it holds
// (dem/particle_changes.h, retireParticles): out of the physics at once, out of the store at the
// next rebuild of the contact lists, so an event that removes costs its own particles too; the
// outlets test every particle's centre: O(N), cheap beside a step.
#pragma once

#include "dem/particle_index.h"
#include "dem/random.h"
#include "dem/world.h"

#include <cstdint>
#include <string>
#include <vector>

namespace veridem::dem
{

/// Where particles are inserted or removed.
struct FlowRegion
{
    enum class Kind
    {
        Box,      // min, max
        Cylinder, // point (centre of one end), axis (unit, towards the other end), radius, length
        HalfSpace // the side of the plane through point that `normal` (unit) points to (outlets)
    };
    Kind kind = Kind::Box;
    Vec3 min, max;         // [m]
    Vec3 point;            // [m]
    Vec3 axis{0, 0, 1};    // unit (cylinder)
    Vec3 normal{0, 0, -1}; // unit (half space)
    Real radius = 0;       // [m]
    Real length = 0;       // [m]

    /// True if the point x [m] is inside (an outlet removes a particle whose centre is).
    bool contains(const Vec3& x) const;
    /// A centre [m] drawn uniformly among those where a sphere of radius r [m] lies wholly inside
    /// (box or cylinder); false if no such centre exists.
    bool sample(Random& random, Real r, Vec3& x) const;
    /// The bounding box [m] of a box or cylinder region.
    void bounds(Vec3& lo, Vec3& hi) const;
};

/// The radius distribution of an inserter [m].
struct RadiusDistribution
{
    enum class Kind
    {
        Fixed,     // value
        Uniform,   // on [min, max]
        Normal,    // mean, std, truncated to [min, max]
        LogNormal, // exp(mu + sigma N(0,1)), truncated to [min, max] (default: not truncated)
        Table      // radii with number probabilities (cumulative)
    };
    Kind kind = Kind::Fixed;
    Real value = 0, min = 0, max = 0, mean = 0, std = 0, mu = 0, sigma = 0; // [m] (mu: of ln(r/1 m))
    std::vector<Real> radii;                                                // [m] (table)
    std::vector<Real> cumulative; // ascending number probabilities, last 1 (table)

    Real sample(Random& random) const;
    Real largest() const; // the largest radius it can draw [m]
};

struct Inserter
{
    std::string name;
    FlowRegion region;
    enum class Mode
    {
        Count,   // `count` particles spread evenly over [from, until] (all at `from` if equal)
        Rate,    // `rate` particles per second over [from, until]
        MassRate // `rate` kilograms per second over [from, until]
    };
    Mode mode = Mode::Count;
    Real count = 0; // [-] (Count)
    Real rate = 0;  // [1/s] or [kg/s]
    Real from = 0;  // [s]
    Real until = 0; // [s]
    RadiusDistribution radius;
    std::vector<std::uint32_t> materials; // material ids
    std::vector<Real> materialCumulative; // ascending number fractions, last 1
    Vec3 velocity;                        // [m/s]
    Real velocitySpread = 0;              // each component + U(-s, s) [m/s]
    std::uint64_t seed = 1;

    // State (checkpointed).
    Random random;
    std::uint64_t inserted = 0; // particles inserted so far
    Real insertedMass = 0;      // [kg]
    bool warnedFull = false;
};

struct Outlet
{
    std::string name;
    FlowRegion region;
    // State (checkpointed): removed so far.
    std::uint64_t count = 0;
    Real mass = 0; // [kg]
};

struct ParticleFlow
{
    static constexpr int kAttempts = 200; // positions tried per particle before the region is full

    std::vector<Inserter> inserters;
    std::vector<Outlet> outlets;
    std::uint64_t everySteps = 1; // act at steps that are multiples of this
    std::uint32_t nextId = 0;     // the id of the next inserted particle (checkpointed)
    // The particles on a grid for insertion, kept between events (not checkpointed: rebuilt when
    // missing, with the same results).
    ParticleIndex index;

    bool empty() const { return inserters.empty() && outlets.empty(); }
    /// The largest radius an inserter can draw [m] (0 if none).
    Real largestRadius() const;
    /// Outlets, then inserters, at world.time (dt [s]: a time within half a step of a window's
    /// start counts as in it). The particles an outlet takes are retired (retireParticles) where
    /// retiresWithoutRebuild allows, else removed with a rebuild of the contact lists
    /// (rebuildAfterParticleChange); particles inserted join the lists without a rebuild
    /// (addInsertedParticles) where insertsWithoutRebuild allows, else with one. Returns true if
    /// the particles changed. Retired particles stay in the store until the next rebuild:
    /// compactRetiredParticles before reading the particles by slot.
    bool apply(World& world, Real dt);

    // The parts of apply(), for a run on several MPI ranks (distributed/rank_flow.h):
    /// The first `count` particles whose centre an outlet holds (frozen and retired ones
    /// excepted), counted into the outlets' totals; the caller retires or removes them.
    std::vector<std::uint32_t> takeAtOutlets(const World& world, std::size_t count);
    /// True if some inserter has particles due at time t [s] (dt [s]: the step).
    bool insertionDue(Real t, Real dt) const;
    /// Appends the particles the inserters have due at world.time to the store (none overlapping
    /// a particle or a wall), without joining them to the contact lists.
    void insertNew(World& world, Real dt);
    /// The box [m] a new particle can be placed in (every inserter's region; along a periodic axis
    /// the domain's extent).
    void insertionBounds(const PeriodicDomain& box, Vec3& lo, Vec3& hi) const;
};

} // namespace veridem::dem
