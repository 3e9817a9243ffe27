// Neighbour list (Verlet list on a cell grid), whose touching candidates key the pair contacts'
// history (ContactHistoryStore).
//
// Design. Candidate pairs (i < j) whose gap is below `skin` are found on cell grids, one per
// size class of the radii (dem/pair_search.h: one grid of cells of edge 2 r_max + skin and the 27
// cells around each particle when the radii are within a factor 2): O(N). The list is
// kept sorted by (i, j) and rebuilt only when some particle has moved more than skin/2 since the
// last build, so between rebuilds no pair can come into contact unseen.
//
// History. The contact history is a store of its own (ContactHistoryStore, World::pairHistory),
// with one entry per touching candidate of the sub-list below: a slot outside it cannot be
// touching, so its history is zero and is not stored (24-48 B x ~4.9 slots a particle saved).
// When the sub-list is rebuilt, the list re-keys the store: each new candidate takes the history
// of the old candidate with the same slot, or, after a rebuild of the slots, with the same (i, j):
// both lists are sorted, so this is a merge by key. History is also zeroed the moment a contact
// opens (in the force loop), so a re-formed contact starts fresh.
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
#include "dem/contact_history.h"
#include "dem/contact_law.h"
#include "dem/particles.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// The effective mass of a pair, m* = m_i m_j / (m_i + m_j) [kg] (masses [kg]), as the candidates
/// and the periodic pairs keep it.
inline Real effectivePairMass(Real massI, Real massJ)
{
    return massI * massJ / (massI + massJ);
}

class NeighborList
{
  public:
    Real skin = 0; // extra search distance beyond touching [m]
    // The touch criterion's reach [m]: the largest separation r_i + r_j - |x_i - x_j| at which a
    // contact of some pair's model can still act (a JKR contact holds to |delta_c|, cohesion.h; 0
    // for every other model). Pairs within r_i + r_j + reach are passed to the contact law, which
    // decides whether they are formed, and the lists search that much farther.
    Real reach = 0;
    // Some particle is frozen (ParticleStore::fixed; set by refreshFixedParticles): a candidate
    // with one takes the other's mass as m* (the frozen one's mass is infinite in its contacts).
    bool anyFixed = false;
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
    // Per candidate a (slot activeSlots[a]), what the force loop reads, in sequence instead of
    // scattered over all slots: first[] and second[] (the key of its history entry a);
    // m* = m_i m_j / (m_i + m_j) [kg] (the contact law's expression, so the same bits); the slot's
    // deferredIndex.
    std::vector<std::uint32_t> activeFirst, activeSecond;
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
    /// Rebuilds the candidate sub-list if stale, at the current positions, and re-keys `history`
    /// (its entries are the candidates') so that each continuing contact keeps its history; a
    /// candidate left out that was in contact just opened, so its history is dropped and its
    /// deferred entry zeroed.
    void refreshActiveSlots(const ParticleStore& particles, ContactHistoryStore& history);
    /// Rebuilds the pair slots; the history reaches the next sub-list by (i, j) (with no slots
    /// at all, `history` is emptied).
    void rebuild(const ParticleStore& particles, ContactHistoryStore& history);

    /// Renames the particles after some were removed between steps (dem/particle_changes.h):
    /// particle p is now newIndex[p], or gone if kGone. The candidates keep their history under
    /// the new (i, j) (a pair whose order flips has its springs negated); the next rebuild(),
    /// which must follow, carries it by key.
    static constexpr std::uint32_t kGone = 0xffffffffu;
    void renameParticles(const std::vector<std::uint32_t>& newIndex, ContactHistoryStore& history);
    /// Replaces the candidates by `first`[a] < `second`[a], sorted by (i, j) and without repeats,
    /// with their history `history` (entry a for candidate a), for particles renumbered between
    /// steps (renameParticles; an MPI rank's particles after an exchange, distributed/rank_history.h). The
    /// rebuild() that must follow carries the history by key.
    void adoptCandidates(std::vector<std::uint32_t> first, std::vector<std::uint32_t> second,
                         ContactHistoryStore& history, ContactHistoryStore&& adopted);

    /// Takes in the particles [from, particles.size()) appended between steps without a rebuild
    /// (dem/particle_changes.h, addInsertedParticles): they have no slots, and their motion is
    /// measured from their current positions (the reference of the rebuild criterion). Their pairs
    /// are the caller's (PeriodicPairs, evaluated after the pair stage) until the next rebuild.
    /// O(particles appended).
    void appendParticles(const ParticleStore& particles, std::size_t from);
    /// Particle i was parked at x [m] between steps (a retired particle, dem/particle_changes.h):
    /// its motion is measured from there, so that it never triggers a rebuild. O(1).
    void parkParticle(std::uint32_t i, const Vec3& x)
    {
        if (i < positionAtBuild_.size())
            positionAtBuild_[i] = x;
        if (i < positionAtActiveBuild_.size())
            positionAtActiveBuild_[i] = x;
    }
    /// True if the list was built (or appended to) for `particleCount` particles.
    bool builtFor(std::size_t particleCount) const
    {
        return positionAtBuild_.size() == particleCount && firstStart.size() == particleCount + 1;
    }

    /// The candidate of slot k (its entry in the history store), or kNotCandidate if it is not
    /// one (then it is open). A look-up by (i, j), for tests and output, not the force loop.
    static constexpr std::size_t kNotCandidate = ~std::size_t{0};
    std::size_t candidateOfSlot(std::size_t k) const;

    /// Candidate a is found open: its history is forgotten, its deferred entry (if any) zeroed.
    void openCandidate(std::size_t a, ContactHistoryStore& history)
    {
        history.forget(a);
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
    /// candidates that are left out while they may be in contact (history.formed).
    void selectCandidates(const ParticleStore& particles, const ContactHistoryStore& history);
    /// Drops every candidate and its history (the slots are gone).
    void forgetCandidates(ContactHistoryStore& history);

    static constexpr std::uint32_t kNoSource = ContactHistoryStore::kNoSource;
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
