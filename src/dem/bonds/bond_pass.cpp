// The step's bond pass (bond_set.h): one thread, the bonds in their order.
#include "dem/bonds/bond_set.h"

#include <algorithm>
#include <cmath>

namespace veridem::dem
{

namespace
{

constexpr std::uint32_t kNoIndex = 0xffffffffu;

/// True if the cached indices still hold the bond's ids.
bool indicesHold(const Bond& bond, const ParticleStore& p)
{
    const std::size_t n = p.size();
    return bond.a < n && bond.b < n && p.id[bond.a] == bond.idA && p.id[bond.b] == bond.idB;
}

void mapIds(BondSet& set, const ParticleStore& p)
{
    std::uint32_t maxId = 0;
    for (const std::uint32_t id : p.id)
        maxId = std::max(maxId, id);
    set.indexOfId.assign(std::size_t{maxId} + 1, kNoIndex);
    for (std::size_t i = 0; i < p.size(); ++i)
        set.indexOfId[p.id[i]] = static_cast<std::uint32_t>(i);
}

std::uint32_t indexOf(const BondSet& set, std::uint32_t id)
{
    return id < set.indexOfId.size() ? set.indexOfId[id] : kNoIndex;
}

/// The reduced mass or inertia of a pair from the inverses (a frozen partner: infinite).
Real reduced(Real invA, bool fixedA, Real invB, bool fixedB)
{
    if (fixedA && fixedB)
        return 0; // (no relative motion to damp)
    if (fixedA)
        return 1 / invB;
    if (fixedB)
        return 1 / invA;
    return 1 / (invA + invB);
}

} // namespace

void applyBonds(BondSet& set, ParticleStore& p, std::size_t owned, Real time, Real dt)
{
    if (!set.created)
    {
        if (time + dt < set.createAt)
            return;
        createBonds(set, p, owned); // at x(t + dt): unloaded now, the increments start with the next step
        return;
    }
    bool mapped = false;
    std::size_t kept = 0;
    Real maxStrain = 0;
    std::uint64_t overstretched = 0;
    for (std::size_t k = 0; k < set.bonds.size(); ++k)
    {
        Bond bond = set.bonds[k];
        if (!indicesHold(bond, p))
        {
            if (!mapped)
            {
                mapIds(set, p);
                mapped = true;
            }
            bond.a = indexOf(set, bond.idA);
            bond.b = indexOf(set, bond.idB);
        }
        const std::uint32_t a = bond.a, b = bond.b;
        if (a == kNoIndex || b == kNoIndex || p.retired(a) || p.retired(b))
        {
            // (on several ranks a removed particle's bonds are dropped at the exchange that takes
            // it out, distributed/rank_bonds.h: here only in one process, where owned = size)
            set.dropped += a == kNoIndex || b == kNoIndex || countsBond(bond, a, b, owned);
            continue;
        }
        const BondPartners q{p.position[a],
                             p.position[b],
                             p.velocity[a],
                             p.velocity[b],
                             p.angularVelocity[a],
                             p.angularVelocity[b],
                             p.radius[a],
                             p.radius[b],
                             reduced(p.invMass[a], p.fixed[a], p.invMass[b], p.fixed[b]),
                             reduced(p.invInertia[a], p.fixed[a], p.invInertia[b], p.fixed[b])};
        const BondLoad load = bondStep(set.params, bond.state, q, dt);
        const bool counts = countsBond(bond, a, b, owned);
        if (load.broken)
        {
            set.broken += counts;
            continue;
        }
        if (a < owned) // (a ghost's sums are not read: its owner adds its own share)
        {
            p.force[a] = p.force[a] - load.forceOnB;
            p.torque[a] = p.torque[a] + load.torqueOnA;
        }
        if (b < owned)
        {
            p.force[b] = p.force[b] + load.forceOnB;
            p.torque[b] = p.torque[b] + load.torqueOnB;
        }
        const Real strain = (length(q.xb - q.xa) - bond.state.restLength) / bond.state.restLength;
        maxStrain = std::fmax(maxStrain, strain);
        overstretched += counts && strain > BondSet::kOverstretch;
        set.bonds[kept++] = bond;
    }
    set.bonds.resize(kept);
    set.maxStrain = maxStrain;
    set.overstretched = overstretched;
}

} // namespace veridem::dem
