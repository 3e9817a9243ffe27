// Neighbour list with contact history (Verlet list on a cell grid).
//
// Design. Candidate pairs (i < j) whose gap is below `skin` are found by binning particles into
// cubic cells of edge >= 2 r_max + skin and testing the 27 surrounding cells: O(N). The list is
// kept sorted by (i, j) and rebuilt only when some particle has moved more than skin/2 since the
// last build, so between rebuilds no pair can come into contact unseen.
//
// History. Contact history (tangential spring; rolling spring only when a rolling model keeps
// one) lives only in the touching-candidate sub-list below: a slot outside it cannot be touching,
// so its history is zero and is not stored (24-48 B x ~4.9 slots a particle saved). When the
// sub-list is rebuilt, each new candidate takes the history of the old candidate with the same
// slot, or, after a rebuild of the slots, with the same (i, j): both lists are sorted, so this is a
// merge by key (Jolt's read-old/write-new contact cache; LAMMPS FixNeighHistory). History is also
// zeroed the moment a contact opens (in the force loop), so a re-formed contact starts fresh.
//
// Force sums (STYLE 3.4). Particles are grouped in fixed blocks of `kBlockParticles` consecutive
// indices, a partition that does not depend on the thread count. The force loop runs over whole
// blocks (each thread a contiguous range of them) and adds each contact's force and torques
// straight into both particles when both lie in the slot's block; a slot whose second particle lies
// in a later block ("cross-block") adds into its first particle only and leaves the second
// particle's share in the slot's `deferred` entry, which a per-particle pass adds afterwards in
// ascending slot order (`incomingStart`, `incomingEntry`). So every particle's sum has one fixed order:
// its in-block contacts in slot order, then its incoming cross-block contacts in slot order (then
// its walls): the same bits for any number of threads, with no per-slot outputs for the ~85 % of
// slots that stay inside a block.
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
    Real skin = 0; // extra search distance beyond touching [m]
    // The touch criterion's reach [m]: the largest separation r_i + r_j - |x_i - x_j| at which a
    // contact of some pair's model can still act (a JKR contact holds to |delta_c|, cohesion.h; 0
    // for every other model). Pairs within r_i + r_j + reach are passed to the contact law, which
    // decides whether they are formed, and the lists search that much farther.
    Real reach = 0;
    bool keepRollingHistory = false; // store a rolling spring per slot (EPSD rolling model in use)

    std::vector<std::uint32_t> first;  // i of each pair (sorted, i < j)
    std::vector<std::uint32_t> second; // j of each pair

    // Blocks: particles [b * kBlockParticles, (b + 1) * kBlockParticles) form block b.
    static constexpr std::uint32_t kBlockParticles = 1024;
    std::vector<std::uint32_t> firstStart; // slots [firstStart[p], firstStart[p+1]) have first == p

    // Cross-block slots. deferredIndex[k] is the slot's entry in `deferred`, or kInBlock. The
    // entries hold, after the force loop, the force [N] and torque [N m] on the slot's second
    // particle (zero while the slot is open), both padded rows in one 64-byte line, so that the
    // particle pass gathers each entry with one cache line and two 32-byte loads. They are numbered in slot
    // order, so each block's are one range that the pair loop writes in sequence, and no two threads write
    // into one cache line but at a range's ends (numbered by second particle, the writes of two
    // threads interleaved; the particle pass now gathers through incomingEntry instead).
    static constexpr std::uint32_t kInBlock = 0xffffffffu;
    std::vector<std::uint32_t> deferredIndex;
    struct alignas(64) DeferredShare
    {
        PaddedVec3 force;  // [N]
        PaddedVec3 torque; // [N m]
    };
    std::vector<DeferredShare> deferred;
    // incomingEntry[incomingStart[p] .. incomingStart[p+1]) are the entries whose second particle is
    // p, in ascending slot order.
    std::vector<std::uint32_t> incomingStart, incomingEntry;

    // Touching candidates (STYLE: a two-level Verlet list). `activeSlots` holds, in ascending
    // order, the slots whose gap was below `innerSkin` when it was built; it is rebuilt from the
    // slots when some particle has moved more than innerSkin/2 since, so a slot left out cannot be
    // touching and the force loop visits only these. A settled bed has ~2.6 candidates per particle (2.3
    // touching) instead of ~4.9 slots. innerSkin adapts, starting from skin/16: doubled (up to skin) when the
    // sub-list lived fewer than 8 steps, halved (down to skin/64) when it lived more than 128. The
    // result is the same bits as visiting every slot, since open slots contribute nothing.
    Real innerSkin = 0; // [m]
    std::vector<std::uint32_t> activeSlots;
    // Per candidate a (slot activeSlots[a]), what the force loop reads and writes, in sequence
    // instead of scattered over all slots: first[] and second[]; the contact history (tangential
    // spring [m], rolling spring [N m] only if keepRollingHistory, and whether the contact is formed
    // (so its history may be non-zero), 0 or 1 (the selection pass reads four flags as bits; for a
    // JKR pair it is the state of the touch criterion's hysteresis): cleared when it is found open,
    // so an open candidate is written once, not every step; m* = m_i m_j / (m_i + m_j) [kg] (the contact
    // law's expression, so the same bits); the slot's deferredIndex.
    std::vector<std::uint32_t> activeFirst, activeSecond;
    std::vector<Vec3> activeSpring, activeRolling;
    std::vector<std::uint8_t> activeMayBeActive;
    std::vector<Real> activeMass;
    std::vector<std::uint32_t> activeDeferred;

    /// True if some particle moved more than skin/2 since the last build (or never built).
    bool needsRebuild(const ParticleStore& particles) const;
    /// The positions the motion check compares with [m], for a pass that moves the particles to
    /// measure their largest displacement as it writes them (kickDrift, once per step): null if
    /// the list was not built for `particleCount` particles.
    struct MotionReference
    {
        const Vec3* built = nullptr;       // positions at the last full build
        const Vec3* activeBuilt = nullptr; // positions when the candidate sub-list was built
    };
    MotionReference motionReference(std::size_t particleCount) const;
    /// needsRebuild() from the largest squared displacements [m^2] since the last full build and
    /// since the sub-list was built, measured against motionReference() for `particleCount`
    /// particles by the caller; also marks the candidate sub-list stale if some particle moved
    /// more than innerSkin/2 since it was built. Called once per step.
    bool checkMotion(std::size_t particleCount, Real largestMotion2, Real largestActiveMotion2);
    /// Rebuilds the candidate sub-list if stale, at the current positions, carrying each
    /// continuing contact's history; a candidate left out that was in contact just opened, so its
    /// history is dropped and its deferred entry zeroed.
    void refreshActiveSlots(const ParticleStore& particles);
    /// Rebuilds the pair slots; the history reaches the next sub-list by (i, j).
    void rebuild(const ParticleStore& particles);

    /// History of slot k as the contact law takes it: its candidate's (with its formed flag), or
    /// zero if it is not a candidate (then it is open). A look-up by (i, j), for tests and output, not the
    /// force loop.
    ContactHistory slotHistory(std::size_t k) const;

    /// History of candidate a as the contact law takes it.
    ContactHistory candidateHistory(std::size_t a) const
    {
        return historyAt(activeSpring, activeRolling, keepRollingHistory, a);
    }
    void setCandidateHistory(std::size_t a, const ContactHistory& h)
    {
        storeHistoryAt(activeSpring, activeRolling, keepRollingHistory, a, h);
    }
    /// Candidate a is found open: its history is forgotten, its deferred entry (if any) zeroed.
    void openCandidate(std::size_t a)
    {
        storeHistoryAt(activeSpring, activeRolling, keepRollingHistory, a, ContactHistory{});
        activeMayBeActive[a] = 0;
        zeroDeferred(activeDeferred[a]);
    }

    std::size_t size() const { return first.size(); }
    std::size_t rebuildCount() const { return rebuilds_; }
    std::size_t activeRebuildCount() const { return activeRebuilds_; }
    /// Bytes held by the list's arrays (capacity), for memory accounting.
    std::size_t memoryBytes() const;

  private:
    friend struct CheckpointAccess; // io/dem_checkpoint.cpp saves and restores the private state

    void zeroDeferred(std::uint32_t entry)
    {
        if (entry != kInBlock)
        {
            deferred[entry] = DeferredShare{};
        }
    }
    /// The new sub-list's slots into activeSlots and, per candidate, the old candidate whose
    /// history it continues into source_ (kNoSource if none); zeroes the deferred entries of old
    /// candidates that are left out while they may be in contact.
    void selectCandidates(const ParticleStore& particles);
    /// Moves the candidates' history to their new places (source_), zero where there is none.
    void carryHistory(std::size_t oldCount);
    /// Drops every candidate and its history (the slots are gone).
    void forgetCandidates();

    static constexpr std::uint32_t kNoSource = 0xffffffffu;
    bool slotsRebuilt_ = false; // the slots were rebuilt since the sub-list was: carry by (i, j)
    std::vector<std::uint32_t> oldSlots_, source_; // scratch of the sub-list rebuild (grow-only)
    std::vector<std::uint8_t> within_;             // per slot, within the inner skin (scratch)
    std::vector<Vec3> positionAtBuild_;
    std::vector<Vec3> positionAtActiveBuild_;
    bool activeStale_ = true;
    std::uint64_t activeAge_ = 0; // steps since the sub-list was built
    std::size_t activeRebuilds_ = 0;
    std::size_t rebuilds_ = 0;
};

} // namespace veridem::dem
