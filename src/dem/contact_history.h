// Contact history, a store of its own (World::pairHistory, World::wallHistory): per contact of a
// contact list, the state the contact law carries from one step to the next (the tangential
// spring, the EPSD rolling spring, the normal model's history scalars, and whether the contact may
// be formed). The force stage reads
// and writes it; nothing else changes it during a step.
//
// Keyed by pair. A store belongs to one contact list (the touching candidates of NeighborList,
// keyed by (i, j); the slots of WallContactList, keyed by (particle, wall)), which keeps its
// contacts sorted by key: entry a is the history of the list's contact a. When the list changes
// its contacts it re-keys the store with carry(): each new contact takes the entry of the old
// contact with the same key (a merge of two sorted lists), or a fresh one. So a continuing
// contact keeps its history whatever its index, and the history depends on the pairs, not on how
// the lists are built (Jolt's read-old/write-new contact cache; LAMMPS FixNeighHistory). With
// domain decomposition the keys become global particle ids (docs/architecture.md).
#pragma once

#include "core/vec3.h"
#include "dem/contact_law.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

class ContactHistoryStore
{
  public:
    static constexpr std::uint32_t kNoSource = 0xffffffffu; // carry(): a contact with no old entry

    /// `withFormed`: keep a formed flag per entry (the pair candidates' store: their selection
    /// pass reads it).
    explicit ContactHistoryStore(bool withFormed = false) : keepFormed(withFormed) {}

    bool keepRolling = false; // a rolling spring per entry (an EPSD rolling model is in use)
    bool keepFormed = false;
    // History scalars per entry: the most a normal model in use declares (ModelEntry::
    // historyScalars, PairTable::historyScalars), 0 in scenes whose models declare none.
    unsigned scalarCount = 0;

    std::vector<Vec3> spring;  // tangential spring xi [m]
    std::vector<Vec3> rolling; // EPSD rolling spring torque [N m]; empty unless keepRolling
    // 1 while the contact may be formed, so its history may be non-zero; for a JKR pair the state
    // of the touch criterion's hysteresis. Cleared when the contact is found open, so an open
    // contact is written once, not every step. Empty unless keepFormed.
    std::vector<std::uint8_t> formed;
    // Entry a's history scalars at [a scalarCount, (a + 1) scalarCount); empty unless scalarCount.
    std::vector<Real> scalars;

    std::size_t size() const { return spring.size(); }

    /// Entry a as the contact law takes it (zero rolling spring, scalars and formed = 0 where not
    /// kept).
    ContactHistory at(std::size_t a) const
    {
        ContactHistory h{spring[a], keepRolling ? rolling[a] : Vec3{},
                         keepFormed ? Real(formed[a]) : Real(0)};
        for (unsigned s = 0; s < scalarCount; ++s)
            h.scalars[s] = scalars[a * scalarCount + s];
        return h;
    }
    /// Stores the law's history into entry a (formed as 0 or 1).
    void set(std::size_t a, const ContactHistory& h)
    {
        spring[a] = h.tangentialSpring;
        if (keepRolling)
            rolling[a] = h.rollingSpring;
        if (keepFormed)
            formed[a] = h.formed != 0;
        for (unsigned s = 0; s < scalarCount; ++s)
            scalars[a * scalarCount + s] = h.scalars[s];
    }

    // The history scalars as the rebuilds of the contact lists move entries (no-ops while
    // scalarCount is 0). The stores of one world keep the same scalarCount.
    /// Sizes the scalars for `entries` entries (new ones zero).
    void resizeScalars(std::size_t entries) { scalars.resize(entries * scalarCount, 0.0); }
    /// Entry `to` takes the scalars of entry e of `from` (zeros if `from` keeps fewer).
    void copyScalars(std::size_t to, const ContactHistoryStore& from, std::size_t e)
    {
        for (unsigned s = 0; s < scalarCount; ++s)
            scalars[to * scalarCount + s] = from.scalarOf(e, s);
    }
    /// Appends the scalars of entry e of `from` (zeros if `from` keeps fewer), or zeros (from null).
    void appendScalars(const ContactHistoryStore* from, std::size_t e)
    {
        for (unsigned s = 0; s < scalarCount; ++s)
            scalars.push_back(from ? from->scalarOf(e, s) : 0.0);
    }
    /// Scalar s of entry e, 0 if not kept.
    Real scalarOf(std::size_t e, unsigned s) const
    {
        return s < scalarCount && (e + 1) * scalarCount <= scalars.size() ? scalars[e * scalarCount + s]
                                                                          : 0.0;
    }
    /// The contact of entry a is open: its history is forgotten.
    void forget(std::size_t a) { set(a, ContactHistory{}); }

    /// Re-keys the store after its list changed its contacts: the new contact a (of `count`)
    /// takes old entry source[a], or a fresh history if source[a] == kNoSource. The sources of the
    /// contacts that have one ascend with a (both lists are sorted by key), which lets the move
    /// run in place.
    void carry(const std::uint32_t* source, std::size_t count);
    /// Drops every entry.
    void clear();

    /// Bytes held (capacity), for memory accounting.
    std::size_t memoryBytes() const;
};

} // namespace veridem::dem
