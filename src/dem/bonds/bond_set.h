// The bonds of a world (parallel bonds, bond_law.h) and their pass in the step.
//
// A bond joins two particles by their stable ids (ParticleStore::id), so it survives the store's
// renumbering (outlets' compaction, spatial sort): each bond caches its partners' indices and the
// pass looks them up again (one O(N) map) when an index no longer holds its id. A partner retired
// by an outlet (radius 0) or gone from the store drops the bond (counted in `dropped`).
//
// The pass (applyBonds) runs in the step after the pair stage and before the particle pass
// (world.cpp): one thread, the bonds in their order (creation order, broken ones taken out keeping
// it), each adding its force and torque to both partners' sums. The sums' order is then fixed, so
// the bits do not depend on the thread count. A world whose BondSet is not `enabled` runs no code
// of it (one predictable branch a step).
//
// The contact law acts in parallel with an intact bond, as the linear contact beside Potyondy &
// Cundall's parallel bond: two bonded particles pressed into overlap also feel their contact; a
// bond formed across a gap adds nothing to the contact until they touch. A broken bond leaves the
// pair an ordinary contact.
//
// On several MPI ranks (distributed/rank_bonds.h) a rank's store holds its owned particles, then
// ghosts: a rank holds every bond with an owned partner, evaluates it from the ghost's exact copy
// of the other partner's motion (so two ranks holding one bond advance its state to the same bits
// and break it at the same step), and adds its loads to the owned partner only (`owned`: the
// store's first `owned` particles; all of them in one process). An event of a bond held by two
// ranks (formed, broken, dropped, overstretched) is counted by the rank owning its partner of the
// lower id, so the ranks' counts sum to one process's.
#pragma once

#include "dem/bonds/bond_law.h"
#include "dem/particles.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// One intact bond. Trivially copyable (a checkpoint record).
struct Bond
{
    std::uint32_t idA = 0, idB = 0; // partners' stable ids (ParticleStore::id)
    std::uint32_t a = 0, b = 0;     // their indices at the last pass (a cache, checked by id)
    BondState state;
};

struct BondSet
{
    bool enabled = false; // a [bonds] table was given: the step runs the pass
    BondParams params;
    Real createAt = 0;     // the bonds form at the first step ending at or after this time [s]
    Real gapTolerance = 0; // partners form a bond if |xb - xa| <= ra + rb + gap [m]
    std::vector<std::uint8_t> materialSelected; // per material id: 1 if it takes part (both partners)
    bool created = false;                       // the bonds were formed
    std::vector<Bond> bonds;                    // the intact bonds, in creation order
    std::uint64_t formed = 0;                   // bonds formed in all
    std::uint64_t broken = 0;                   // bonds broken by the strength test in all
    std::uint64_t dropped = 0;                  // bonds dropped with a partner removed
    Real maxStrain = 0;              // largest (d - d0) / d0 of an intact bond at the last pass [-]
    std::uint64_t overstretched = 0; // intact bonds with (d - d0) / d0 > kOverstretch at the last pass

    /// The strain above which an intact bond is reported as drifted apart (run summary).
    static constexpr Real kOverstretch = 0.5;
    std::vector<std::uint32_t> indexOfId; // id -> index (kNoIndex: none); rebuilt when stale
};

/// True if this rank counts the events of `bond` (its partners at store indices a, b): it owns the
/// partner of the lower id (file comment; always in one process, where owned = the store's size).
inline bool countsBond(const Bond& bond, std::size_t a, std::size_t b, std::size_t owned)
{
    return (bond.idA < bond.idB ? a : b) < owned;
}

/// Forms the bonds among the selected particles now (pairs within ra + rb + gapTolerance, neither
/// retired, one of them among the store's first `owned`), in order of the first then the second
/// partner's index; returns how many. Marks the set created. Each bond runs from the partner of
/// the lower index to the other, or, when the store holds ghosts (owned < size), of the lower id.
std::size_t createBonds(BondSet& set, const ParticleStore& particles, std::size_t owned);
inline std::size_t createBonds(BondSet& set, const ParticleStore& particles)
{
    return createBonds(set, particles, particles.size());
}

/// The step's bond pass (see the file comment): forms the bonds if due (t_end = time + dt >=
/// createAt; unloaded at that step), else advances each intact bond over dt [s], adding its loads
/// to the force and torque sums of the partners among the store's first `owned`; broken and
/// dropped bonds leave the list.
void applyBonds(BondSet& set, ParticleStore& particles, std::size_t owned, Real time, Real dt);

} // namespace veridem::dem
