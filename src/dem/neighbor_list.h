// Neighbour list with contact history (Verlet list on a cell grid).
//
// Design. Candidate pairs (i < j) whose gap is below `skin` are found by binning particles into
// cubic cells of edge >= 2 r_max + skin and testing the 27 surrounding cells: O(N). The list is
// kept sorted by (i, j) and rebuilt only when some particle has moved more than skin/2 since the
// last build, so between rebuilds no pair can come into contact unseen. Each pair slot carries its
// contact history (tangential spring; rolling spring only when a rolling model keeps one); on a
// rebuild the new sorted list is merged with the old one by key, so history survives rebuilds and
// pairs that separated are dropped (Jolt's read-old/write-new contact cache; LAMMPS
// FixNeighHistory). History is also zeroed the moment a contact opens (in the force loop), so a
// re-formed contact starts fresh.
//
// Per-step outputs (STYLE 3.4). The force loop writes each slot's force and the torques on its two
// particles into the slot's own entries (no races, any thread count); the gather then sums, for
// each particle, the slots where it is the second particle (`secondSlots`, ascending slot order)
// and then its own slots as first particle (contiguous, `firstStart`). Since the list is sorted by
// (i, j), that is exactly ascending slot order: the same order, and so the same bits, as a serial
// scatter loop over the slots, for any number of threads.
#pragma once

#include "core/vec3.h"
#include "dem/contact_law.h"
#include "dem/particles.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

class NeighborList
{
  public:
    Real skin = 0;                   // extra search distance beyond touching [m]
    bool keepRollingHistory = false; // store a rolling spring per slot (EPSD rolling model in use)

    std::vector<std::uint32_t> first;   // i of each pair (sorted, i < j)
    std::vector<std::uint32_t> second;  // j of each pair
    std::vector<Vec3> tangentialSpring; // history per pair slot [m]
    std::vector<Vec3> rollingSpring;    // history per pair slot [N m] (empty unless keepRollingHistory)

    // Per-slot effective mass m* = m_i m_j / (m_i + m_j) [kg], set on a rebuild (the contact law's
    // expression, so the same bits), for the four-lane path.
    std::vector<Real> effectiveMass;

    // Per-step outputs, one entry per slot (zero for slots not in contact).
    std::vector<Vec3> force; // on the first particle [N] (the second gets -force)
    // The torques are assembled by the gather: on the first particle  rolling - leverFirst (n x Ft),
    // on the second  -rolling - leverSecond (n x Ft)  (lever arms l_i, l_j: forces.cpp). Storing
    // the three parts costs 40 bytes per slot instead of 48 for two torques.
    std::vector<Vec3> tangentialTorque; // n x Ft [N m]
    std::vector<Real> leverFirst;       // l_i [m]
    std::vector<Real> leverSecond;      // l_j [m]
    std::vector<Vec3> rollingTorque;    // on the first particle [N m] (empty unless keepRollingTorque)
    bool keepRollingTorque = false;     // some pair has a rolling-resistance model

    // Force-loop bookkeeping: whether the slot's outputs/history may be non-zero (cleared when the
    // slot is found open, so an open slot is written once, not every step), and room for each
    // chunk's list of touching slots.
    std::vector<std::uint8_t> mayBeActive;
    std::vector<std::uint32_t> touchingScratch;

    // Gather adjacency (CSR), rebuilt with the list.
    std::vector<std::uint32_t> firstStart; // slots [firstStart[p], firstStart[p+1]) have first == p
    std::vector<std::uint32_t>
        secondStart; // secondSlots[secondStart[p] .. secondStart[p+1]) have second == p
    std::vector<std::uint32_t> secondSlots; // ascending within each particle

    /// True if some particle moved more than skin/2 since the last build (or never built).
    bool needsRebuild(const ParticleStore& particles) const;
    /// Rebuilds the pair list, carrying history over by (i, j).
    void rebuild(const ParticleStore& particles);

    /// History of slot k as the contact law takes it.
    ContactHistory history(std::size_t k) const
    {
        return {tangentialSpring[k], keepRollingHistory ? rollingSpring[k] : Vec3{}};
    }
    void setHistory(std::size_t k, const ContactHistory& h)
    {
        tangentialSpring[k] = h.tangentialSpring;
        if (keepRollingHistory)
            rollingSpring[k] = h.rollingSpring;
    }

    std::size_t size() const { return first.size(); }
    std::size_t rebuildCount() const { return rebuilds_; }
    /// Bytes held by the list's arrays (capacity), for memory accounting.
    std::size_t memoryBytes() const;

  private:
    std::vector<Vec3> positionAtBuild_;
    std::size_t rebuilds_ = 0;
};

} // namespace veridem::dem
