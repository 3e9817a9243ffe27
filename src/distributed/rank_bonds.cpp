#include "distributed/rank_bonds.h"

#include "core/error.h"
#include "distributed/bytes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace veridem::distributed
{

namespace
{

constexpr std::uint32_t kAbsent = 0xffffffffu;

/// The store's indices by particle id (ids need not be 0..N-1 nor in order).
class IdIndex
{
  public:
    explicit IdIndex(const dem::ParticleStore& p, std::size_t count)
    {
        table_.reserve(count);
        for (std::size_t i = 0; i < count; ++i)
            table_.emplace_back(p.id[i], static_cast<std::uint32_t>(i));
        std::sort(table_.begin(), table_.end());
    }
    std::uint32_t operator()(std::uint32_t id) const
    {
        const auto it = std::lower_bound(table_.begin(), table_.end(), std::pair{id, std::uint32_t{0}});
        return it != table_.end() && it->first == id ? it->second : kAbsent;
    }

  private:
    std::vector<std::pair<std::uint32_t, std::uint32_t>> table_;
};

void putBonds(std::vector<std::byte>& out, std::span<const dem::Bond> bonds)
{
    ByteWriter w{out};
    w.put(static_cast<std::uint64_t>(bonds.size()));
    const std::size_t at = out.size();
    out.resize(at + bonds.size() * kBondBytes);
    if (!bonds.empty())
        std::memcpy(out.data() + at, bonds.data(), bonds.size() * kBondBytes);
}

std::vector<dem::Bond> getBonds(ByteReader& r, int from)
{
    const auto count = r.get<std::uint64_t>();
    if (count > (r.in.size() - r.at) / kBondBytes)
        throw SimulationError("MPI exchange: rank " + std::to_string(from) + " sent " +
                              std::to_string(count) + " bonds in a message of " +
                              std::to_string(r.in.size()) + " bytes");
    std::vector<dem::Bond> bonds(count);
    if (count > 0)
        std::memcpy(bonds.data(), r.in.data() + r.at, count * kBondBytes);
    r.at += count * kBondBytes;
    return bonds;
}

/// A bond's partners, the lower id first (a bond formed in one process may run either way).
std::pair<std::uint32_t, std::uint32_t> key(const dem::Bond& b)
{
    return {std::min(b.idA, b.idB), std::max(b.idA, b.idB)};
}

} // namespace

Real bondHalo(const dem::BondSet& set, Real largestRadius, Real skin)
{
    if (!set.enabled)
        return 0;
    const Real longest = 2 * largestRadius + set.gapTolerance; // the longest rest length [m]
    const Real stretch = std::fmin(set.params.tensileStrength / set.params.normalStiffness,
                                   dem::BondSet::kOverstretch * longest);
    return largestRadius + set.gapTolerance + skin + stretch;
}

void startBondCounts(dem::BondSet& set, const dem::ParticleStore& p, bool firstRank)
{
    if (!set.enabled)
        return;
    const IdIndex index(p, p.size());
    std::size_t kept = 0;
    std::uint64_t dropped = 0;
    for (const dem::Bond& b : set.bonds)
        if (index(b.idA) == kAbsent || index(b.idB) == kAbsent)
            ++dropped;
        else
            set.bonds[kept++] = b;
    set.bonds.resize(kept);
    set.dropped += dropped;
    if (!firstRank)
        set.formed = set.broken = set.dropped = set.overstretched = 0;
}

void keepOwnedBonds(dem::BondSet& set, const dem::ParticleStore& p, std::size_t owned)
{
    const IdIndex index(p, p.size());
    std::size_t kept = 0;
    for (dem::Bond b : set.bonds)
    {
        b.a = index(b.idA);
        b.b = index(b.idB);
        const bool ownsA = b.a < owned, ownsB = b.b < owned;
        if (!ownsA && !ownsB)
            continue;
        if (b.a == kAbsent || b.b == kAbsent)
            throw SimulationError("MPI: the bond between particles " + std::to_string(b.idA) + " and " +
                                  std::to_string(b.idB) + " reaches beyond the ranks' halo (rest length " +
                                  std::to_string(b.state.restLength) +
                                  " m): its partners drifted apart without breaking it; give [bonds] a "
                                  "tensile_strength, or run it in one process");
        set.bonds[kept++] = b;
    }
    set.bonds.resize(kept);
}

Buffers routeBonds(dem::BondSet& set, const dem::ParticleStore& p, std::span<const int> dest,
                   const Collective& comm)
{
    const auto ranks = static_cast<std::size_t>(comm.size());
    const int me = comm.rank();
    const std::size_t owned = dest.size();
    // The particles leaving the ranks (retired by an outlet), known to all.
    Buffers leaving(ranks);
    for (std::size_t i = 0; i < owned; ++i)
        if (dest[i] < 0)
            ByteWriter{leaving[0]}.put(p.id[i]);
    for (std::size_t b = 1; b < ranks; ++b)
        leaving[b] = leaving[0];
    std::vector<std::uint32_t> gone;
    for (const std::vector<std::byte>& in : comm.exchange(std::move(leaving)))
        for (ByteReader r{in}; !r.done();)
            gone.push_back(r.get<std::uint32_t>());
    std::sort(gone.begin(), gone.end());
    const auto isGone = [&](std::uint32_t id) { return std::binary_search(gone.begin(), gone.end(), id); };

    const IdIndex index(p, p.size());
    std::vector<std::vector<dem::Bond>> mail(ranks);
    std::size_t kept = 0;
    for (dem::Bond b : set.bonds)
    {
        const std::uint32_t a = index(b.idA), c = index(b.idB);
        if (isGone(b.idA) || isGone(b.idB))
        {
            set.dropped += dem::countsBond(b, a, c, owned); // (absent here: counted elsewhere)
            continue;
        }
        const int da = a < owned ? dest[a] : -1, dc = c < owned ? dest[c] : -1;
        if (da == me || dc == me)
            set.bonds[kept++] = b;
        if (da >= 0 && da != me)
            mail[static_cast<std::size_t>(da)].push_back(b);
        if (dc >= 0 && dc != me && dc != da)
            mail[static_cast<std::size_t>(dc)].push_back(b);
    }
    set.bonds.resize(kept);
    Buffers out(ranks);
    for (std::size_t r = 0; r < ranks; ++r)
        if (!mail[r].empty())
            putBonds(out[r], mail[r]);
    return out;
}

void adoptBonds(dem::BondSet& set, const dem::ParticleStore& p, std::size_t owned, const Buffers& in)
{
    std::vector<std::pair<std::uint32_t, std::uint32_t>> held;
    for (const dem::Bond& b : set.bonds)
        held.push_back(key(b));
    std::sort(held.begin(), held.end());
    const std::size_t before = set.bonds.size();
    for (std::size_t from = 0; from < in.size(); ++from)
        if (!in[from].empty())
            for (ByteReader r{in[from]}; !r.done();)
                for (const dem::Bond& b : getBonds(r, static_cast<int>(from)))
                    if (!std::binary_search(held.begin(), held.end(), key(b)))
                        set.bonds.push_back(b);
    // (two ranks sending one bond: the second copy, identical, is dropped; kept in arrival order)
    std::set<std::pair<std::uint32_t, std::uint32_t>> arrived;
    std::size_t kept = before;
    for (std::size_t k = before; k < set.bonds.size(); ++k)
        if (arrived.insert(key(set.bonds[k])).second)
            set.bonds[kept++] = set.bonds[k];
    set.bonds.resize(kept);
    keepOwnedBonds(set, p, owned);
}

std::optional<dem::BondSet> gatherBonds(const dem::BondSet& set, const dem::ParticleStore& p,
                                        std::size_t owned, const Collective& comm, int root)
{
    // One message a rank: its counts, its largest strain, then the bonds it counts.
    const IdIndex index(p, p.size());
    std::vector<dem::Bond> mine;
    for (const dem::Bond& b : set.bonds)
        if (dem::countsBond(b, index(b.idA), index(b.idB), owned))
            mine.push_back(b);
    std::vector<std::byte> message;
    ByteWriter w{message};
    for (const std::uint64_t c : {set.formed, set.broken, set.dropped, set.overstretched})
        w.put(c);
    w.put(set.maxStrain);
    putBonds(message, mine);
    const auto ranks = static_cast<std::size_t>(comm.size());
    Buffers out(ranks);
    for (std::size_t b = 0; b < ranks; ++b)
        if (root < 0 || static_cast<int>(b) == root)
            out[b] = message;
    const Buffers in = comm.exchange(std::move(out));
    if (root >= 0 && comm.rank() != root)
        return std::nullopt;

    dem::BondSet total = set;
    total.bonds.clear();
    total.formed = total.broken = total.dropped = total.overstretched = 0;
    total.maxStrain = 0;
    for (std::size_t a = 0; a < ranks; ++a)
    {
        ByteReader r{in[a]};
        total.formed += r.get<std::uint64_t>();
        total.broken += r.get<std::uint64_t>();
        total.dropped += r.get<std::uint64_t>();
        total.overstretched += r.get<std::uint64_t>();
        total.maxStrain = std::fmax(total.maxStrain, r.get<Real>());
        for (const dem::Bond& b : getBonds(r, static_cast<int>(a)))
            total.bonds.push_back(b);
    }
    std::sort(total.bonds.begin(), total.bonds.end(),
              [](const dem::Bond& x, const dem::Bond& y) { return key(x) < key(y); });
    return total;
}

} // namespace veridem::distributed
