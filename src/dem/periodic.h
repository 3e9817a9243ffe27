// Periodic boundaries per axis: the domain box, the wrap of positions, and the pairs that touch
// across a periodic face (their minimum image). The same list also holds, with shift 0, the pairs
// of particles inserted between steps until the next rebuild of the contact lists takes them into
// the neighbour list (dem/particle_changes.h, addInsertedParticles): a list of pairs evaluated
// after the pair stage through the same law, with history carried by (i, j).
//
// Design (docs/architecture.md, "Periodic boundaries"). Positions are wrapped into the box only
// when the contact lists are rebuilt (World's rebuildContactLists), so between rebuilds a particle
// may stand up to skin/2 outside the box and every pair's image is fixed. The box is at least
// twice the search cut-off (2 r_max + skin + reach) along each periodic axis, so a pair (i, j) has
// at most one image within reach: a pair is either a slot of the neighbour list (direct, no shift)
// or a pair of this list (one image, shift s: particle j's image is at x_j + s), never both, and
// the (i, j) key of the contact history stays valid. The neighbour list, its lane kernel and its
// block sums are untouched; this list's pairs are evaluated after the pair stage, one at a time
// through the same frame and law (pairContactAt, dem/pair_kernel.h), in list order, and added into
// both particles' sums, so a particle's sum has a fixed order (its in-block contacts, its periodic
// ones, its cross-block ones, its walls): the same bits on any thread count.
//
// History across the wrap. A pair whose image changes at a rebuild (a particle wrapped) keeps its
// history by key: a pair entering this list takes its entry from this list's old pairs or from the
// neighbour list's candidates; a pair leaving it hands its entry to the neighbour list's candidates,
// which carry it to the new slots by (i, j) as any rebuild does (dem/contact_history.h). The
// separation x_i - x_j - s is continuous across a wrap, so the springs need no change.
#pragma once

#include "core/error.h"
#include "core/vec3.h"
#include "dem/contact_history.h"
#include "dem/particles.h"

#include <array>
#include <cstdint>
#include <vector>

namespace veridem::dem
{

class NeighborList;
struct World;

/// The domain box and which of its axes are periodic. With no periodic axis the box is unused.
struct PeriodicDomain
{
    Vec3 min{}, max{};                                 // corners of the box [m]
    std::array<bool, 3> periodic{false, false, false}; // x, y, z

    bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
    /// Edge lengths max - min [m].
    Vec3 length() const { return max - min; }
};

/// x wrapped into [min, max) along each periodic axis (the other components unchanged) [m].
Vec3 wrapPosition(const PeriodicDomain& domain, const Vec3& x);

/// Calls f(s) for s = 0 and for every image shift s (a sum of +-box edges along periodic axes)
/// under which x + s comes within d [m] of the box: with every particle within d of the box,
/// the particles near x through an image are among those near x + s (their image x_j - s is near
/// x). At most 27 calls, in a fixed order.
template <class F> void forEachImageShift(const PeriodicDomain& domain, const Vec3& x, Real d, F&& f)
{
    const Vec3 lo = domain.min, hi = domain.max, edge = domain.length();
    const Real xs[3] = {x.x, x.y, x.z}, los[3] = {lo.x, lo.y, lo.z}, his[3] = {hi.x, hi.y, hi.z},
               edges[3] = {edge.x, edge.y, edge.z};
    Real options[3][3];
    int count[3];
    for (int a = 0; a < 3; ++a)
    {
        count[a] = 0;
        options[a][count[a]++] = 0;
        if (domain.periodic[a] && xs[a] - los[a] < d) // near the low face: its image past the high one
            options[a][count[a]++] = edges[a];
        if (domain.periodic[a] && his[a] - xs[a] < d)
            options[a][count[a]++] = -edges[a];
    }
    for (int i = 0; i < count[0]; ++i)
        for (int j = 0; j < count[1]; ++j)
            for (int k = 0; k < count[2]; ++k)
                f(Vec3{options[0][i], options[1][j], options[2][k]});
}

/// The largest pair search distance the box must hold twice along a periodic axis [m]:
/// 2 r_max + search (search = skin + reach beyond r_i + r_j).
inline Real periodicCutoff(Real maxRadius, Real search)
{
    return 2 * maxRadius + search;
}

/// A periodic box too short for the contact search (the scene reader names its [domain] line).
class PeriodicBoxError : public InputError
{
  public:
    using InputError::InputError;
};

/// Throws PeriodicBoxError if a periodic axis of the box is shorter than 2 x periodicCutoff (a pair could
/// then touch through two images, or a particle its own image).
void checkPeriodicBox(const PeriodicDomain& domain, Real maxRadius, Real search);

/// Pairs (i < j, sorted by (i, j)) within r_i + r_j + search of each other through one periodic
/// image, with their shifts and contact history.
class PeriodicPairs
{
  public:
    std::vector<std::uint32_t> first, second;
    std::vector<Vec3> shift; // particle j's image is at x_j + shift [m] (multiples of the box edges)
    std::vector<Real> mass;  // m* [kg] (a frozen particle's partner's mass, as NeighborList's)
    ContactHistoryStore history{true}; // one entry per pair

    std::size_t size() const { return first.size(); }
    bool empty() const { return first.empty(); }

    /// Finds the pairs at the current (wrapped) positions on a cell grid of the box. The history
    /// follows by key (see the file comment): from this list's old pairs or `neighbors`' candidates
    /// (`pairHistory`), and the old pairs that are no longer periodic are handed to those candidates.
    /// Call before NeighborList::rebuild, which then carries them.
    void rebuild(const PeriodicDomain& domain, const ParticleStore& particles, Real search, bool anyFixed,
                 NeighborList& neighbors, ContactHistoryStore& pairHistory);

    /// Renames the particles after some were removed (NeighborList::renameParticles): a pair whose
    /// order flips has its springs and shift negated; a pair with a removed particle is dropped.
    void renameParticles(const std::vector<std::uint32_t>& newIndex);

    /// Adds the pairs (newFirst[k] < newSecond[k], image shift newShift[k] [m], 0 for a direct
    /// pair, fresh history) of particles inserted between steps without a rebuild
    /// (dem/particle_changes.h, addInsertedParticles), none of them already listed; the list
    /// stays sorted by (i, j). m* as NeighborList's (`anyFixed`: some particle is frozen).
    /// O((pairs listed + added) log).
    void addPairs(const ParticleStore& particles, bool anyFixed, const std::vector<std::uint32_t>& newFirst,
                  const std::vector<std::uint32_t>& newSecond, const std::vector<Vec3>& newShift);
    /// Without periodic axes, at a rebuild of the contact lists: every pair that may be in contact
    /// joins `neighbors`' candidates with its history (as rebuild() hands over the pairs that stop
    /// being periodic), and the list is emptied. Call before NeighborList::rebuild.
    void handOver(NeighborList& neighbors, ContactHistoryStore& pairHistory);

    void clear();

  private:
    /// The pairs k not `continued` that may be in contact (history.formed) merged, by key, into
    /// `neighbors`' candidates and `pairHistory`.
    void handOverFormed(const std::vector<std::uint8_t>& continued, NeighborList& neighbors,
                        ContactHistoryStore& pairHistory) const;
};

/// Wraps every particle's position (and its position row) into the box along the periodic axes.
void wrapParticles(const PeriodicDomain& domain, ParticleStore& particles);

/// The periodic pairs' forces and torques added into both particles' sums, in list order, after the
/// pair stage (dem/forces.cpp, computePairForces); the health record folded after the pair stage's.
/// `sumsAreZero`: as computePairForces'.
void addPeriodicPairForces(World& world, Real dt, bool sumsAreZero);

} // namespace veridem::dem
