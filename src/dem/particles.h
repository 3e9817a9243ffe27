// Per-particle state, one contiguous array per property (structure of arrays).
// Hot data (position, velocity, angular velocity, force, torque) is separate from per-particle
// constants (radius, inverse mass, inverse inertia, material).
#pragma once

#include "core/constants.h"
#include "core/vec3.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// A Vec3 padded to 32 bytes (x, y, z, pad), so that one four-lane instruction adds a contact's
/// force or torque into a particle's sum (forces.cpp). Reads and writes as a Vec3; pad stays 0.
struct alignas(32) PaddedVec3 : Vec3
{
    Real pad = 0;

    constexpr PaddedVec3() = default;
    constexpr PaddedVec3(const Vec3& v) : Vec3(v) {}
    constexpr PaddedVec3& operator=(const Vec3& v)
    {
        Vec3::operator=(v);
        return *this;
    }
};
static_assert(sizeof(PaddedVec3) == 32);

struct ParticleStore
{
    std::vector<Vec3> position;        // x [m]
    std::vector<Vec3> velocity;        // v [m/s]
    std::vector<Vec3> angularVelocity; // w [rad/s]
    // Contact force [N] (gravity excluded) and torque [N m] of the current step. The pair stage
    // adds each contact into them directly (padded rows), so they hold partial sums while a step
    // runs and the step's totals between steps.
    std::vector<PaddedVec3> force;
    std::vector<PaddedVec3> torque;
    std::vector<Real> radius;     // [m]
    std::vector<Real> mass;       // [kg]
    std::vector<Real> invMass;    // [1/kg]
    std::vector<Real> invInertia; // 1/I with I = (2/5) m r^2 (solid sphere) [1/(kg m^2)]
    std::vector<std::uint32_t> material;
    // Stable id of each particle (output key): a particle keeps it when others are removed or
    // inserted and when the store is renumbered (spatial_sort.h). The scene's particles are
    // numbered from 0 in input order; inserted ones continue (dem/particle_flow.h).
    std::vector<std::uint32_t> id;
    // 1 for a frozen particle (`fixed = true`): it keeps its position with zero velocity and
    // angular velocity, and is a partner of infinite mass in its pair contacts (world.h).
    std::vector<std::uint8_t> fixed;
    // Position [m] and radius [m] of each particle in one padded row (x, y, z, r): a copy that
    // prepare() fills and every drift (integrate.h) rewrites with the new positions, so that the
    // pair stage's distance test loads a particle with one 32-byte load.
    std::vector<PaddedVec3> positionRadius;
    // Optional loads added to each particle's contact sums every step: a force [N] and a torque
    // [N m] set by a driver between steps (drag, fields; api::Simulation). Empty (the default):
    // none, and the step runs exactly as without them. When present, they follow the rows through
    // copyRow, appendRow, truncate and add like every array (each 0 for a new particle).
    std::vector<Vec3> externalForce;
    std::vector<Vec3> externalTorque;
    // The external loads that the force and torque rows hold now (added at the last force
    // evaluation), so that loads changed between steps can be brought into the rows before the
    // next half kick (syncExternalLoads, forces.h).
    std::vector<Vec3> appliedExternalForce;
    std::vector<Vec3> appliedExternalTorque;
    bool hasExternalLoads() const { return !externalForce.empty(); }
    /// Sizes the external loads to the particles (zero) if they are not kept yet.
    void keepExternalLoads()
    {
        externalForce.resize(size());
        externalTorque.resize(size());
        appliedExternalForce.resize(size());
        appliedExternalTorque.resize(size());
    }

    /// Refills positionRadius from position and radius (prepare(); after changing either outside
    /// a step).
    void refreshPositionRadius()
    {
        positionRadius.resize(position.size());
        for (std::size_t i = 0; i < position.size(); ++i)
            positionRadius[i] = positionRadiusRow(i);
    }
    PaddedVec3 positionRadiusRow(std::size_t i) const
    {
        PaddedVec3 row(position[i]);
        row.pad = radius[i];
        return row;
    }

    std::size_t size() const { return position.size(); }

    /// True if particle i is retired: taken out of the physics by an outlet, waiting to leave the
    /// store at the next rebuild of the contact lists (dem/particle_changes.h). A retired particle
    /// has radius 0; every other particle's radius is > 0 (the scene reader refuses others).
    bool retired(std::size_t i) const { return radius[i] == 0; }
    /// The particles that are not retired: those the outputs list. O(N).
    std::size_t liveCount() const
    {
        std::size_t n = 0;
        for (const Real r : radius)
            n += r != 0;
        return n;
    }

    /// Adds a solid sphere; returns its index. radius [m], density [kg/m^3].
    std::uint32_t add(Vec3 x, Vec3 v, Vec3 w, Real r, Real density, std::uint32_t materialId)
    {
        const Real m = density * (4.0 / 3.0) * kPi * r * r * r;
        position.push_back(x);
        velocity.push_back(v);
        angularVelocity.push_back(w);
        force.push_back({});
        torque.push_back({});
        radius.push_back(r);
        mass.push_back(m);
        invMass.push_back(1.0 / m);
        invInertia.push_back(1.0 / (0.4 * m * r * r));
        material.push_back(materialId);
        id.push_back(static_cast<std::uint32_t>(id.size()));
        fixed.push_back(0);
        positionRadius.push_back(positionRadiusRow(position.size() - 1));
        if (hasExternalLoads())
            keepExternalLoads(); // (zero for the new row)
        return static_cast<std::uint32_t>(position.size() - 1);
    }

    /// Calls f(&ParticleStore::array) for every per-particle array, in a fixed order: the one list
    /// of the arrays that reserve, copyRow, appendRow and truncate (and a new array) go through.
    template <class F> static void forEachArray(F&& f)
    {
        f(&ParticleStore::position);
        f(&ParticleStore::velocity);
        f(&ParticleStore::angularVelocity);
        f(&ParticleStore::force);
        f(&ParticleStore::torque);
        f(&ParticleStore::radius);
        f(&ParticleStore::mass);
        f(&ParticleStore::invMass);
        f(&ParticleStore::invInertia);
        f(&ParticleStore::material);
        f(&ParticleStore::id);
        f(&ParticleStore::fixed);
        f(&ParticleStore::positionRadius);
    }

    void reserve(std::size_t n)
    {
        forEachArray([&](auto array) { (this->*array).reserve(n); });
    }

    /// Calls f(&ParticleStore::array) for the optional arrays that are kept (the external loads).
    template <class F> void forEachOptionalArray(F&& f) const
    {
        if (hasExternalLoads())
        {
            f(&ParticleStore::externalForce);
            f(&ParticleStore::externalTorque);
            f(&ParticleStore::appliedExternalForce);
            f(&ParticleStore::appliedExternalTorque);
        }
    }

    /// Copies particle `from`'s row (every array, its force and torque rows included) over
    /// particle `to`'s.
    void copyRow(std::size_t from, std::size_t to)
    {
        forEachArray([&](auto array) { (this->*array)[to] = (this->*array)[from]; });
        forEachOptionalArray([&](auto array) { (this->*array)[to] = (this->*array)[from]; });
    }

    /// Appends particle i of `other` (every array: its row as it is there).
    void appendRow(const ParticleStore& other, std::size_t i)
    {
        forEachArray([&](auto array) { (this->*array).push_back((other.*array)[i]); });
        if (other.hasExternalLoads() || hasExternalLoads())
            keepExternalLoads(); // (sized to the rows, this one included, zero where new)
        if (other.hasExternalLoads())
            forEachOptionalArray([&](auto array) { (this->*array).back() = (other.*array)[i]; });
    }

    /// Keeps the first n particles (n <= size()).
    void truncate(std::size_t n)
    {
        forEachArray([&](auto array) { (this->*array).resize(n); });
        forEachOptionalArray([&](auto array) { (this->*array).resize(n); });
    }

    /// Removes particle i by moving the last particle into its place; the caller re-keys the
    /// contact lists (dem/particle_changes.h).
    void swapRemove(std::size_t i)
    {
        if (i != size() - 1)
            copyRow(size() - 1, i);
        truncate(size() - 1);
    }
};

/// One particle as the contact code reads it: copied from the store (particleState) or held in a
/// caller's registers between the stages of a step (the one-particle step, world.cpp).
struct ParticleState
{
    Vec3 position;        // [m]
    Vec3 velocity;        // [m/s]
    Vec3 angularVelocity; // [rad/s]
    Real radius;          // [m]
    Real mass;            // [kg]
    Real invInertia;      // [1/(kg m^2)]
    std::uint32_t material;
};

inline ParticleState particleState(const ParticleStore& p, std::size_t i)
{
    return {p.position[i], p.velocity[i],   p.angularVelocity[i], p.radius[i],
            p.mass[i],     p.invInertia[i], p.material[i]};
}

} // namespace veridem::dem
