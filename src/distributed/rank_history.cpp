#include "distributed/rank_history.h"

#include "distributed/bytes.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <variant>

namespace veridem::distributed
{

namespace
{
/// Entry a of `h`, the history of the pair of particles (i, j) (local, as the law saw them).
void exportPairOf(const dem::World& world, std::uint32_t i, std::uint32_t j,
                  const dem::ContactHistoryStore& h, std::size_t a, KeyedHistory& out)
{
    const std::uint32_t idI = world.particles.id[i];
    const std::uint32_t idJ = world.particles.id[j];
    // (i, j) local; the entry is (lo, hi) by id: the springs change sign if the orders differ.
    const Real sign = idI < idJ ? 1.0 : -1.0;
    PairHistoryEntry e;
    e.lo = std::min(idI, idJ);
    e.hi = std::max(idI, idJ);
    e.spring = sign * h.spring[a];
    if (h.keepRolling && h.rolling.size() == h.size())
        e.rolling = sign * h.rolling[a];
    e.formed = h.keepFormed && h.formed.size() == h.size() ? h.formed[a] : 1;
    out.scalarCount = h.scalarCount;
    for (unsigned s = 0; s < h.scalarCount; ++s) // (scalars do not change sign)
        e.scalars[s] = h.scalarOf(a, s);
    out.pairs.push_back(e);
}
} // namespace

void exportPair(const dem::World& world, std::size_t a, KeyedHistory& out)
{
    exportPairOf(world, world.neighbors.activeFirst[a], world.neighbors.activeSecond[a], world.pairHistory, a,
                 out);
}

void exportPeriodicPair(const dem::World& world, std::size_t k, KeyedHistory& out)
{
    const dem::PeriodicPairs& p = world.periodicPairs;
    exportPairOf(world, p.first[k], p.second[k], p.history, k, out);
}

void exportWallSlot(const dem::World& world, std::size_t k, KeyedHistory& out)
{
    const dem::WallContactList& list = world.wallContacts;
    const dem::ContactHistoryStore& h = world.wallHistory;
    WallHistoryEntry e;
    e.id = world.particles.id[list.particle[k]];
    e.wall = list.wall[k];
    e.spring = h.spring[k];
    if (h.keepRolling && h.rolling.size() == h.size())
        e.rolling = h.rolling[k];
    out.scalarCount = h.scalarCount;
    for (unsigned s = 0; s < h.scalarCount; ++s)
        e.scalars[s] = h.scalarOf(k, s);
    if (k < list.meshNormal.size())
        e.normal = list.meshNormal[k];
    e.flat = k < list.meshFlat.size() ? list.meshFlat[k] : dem::WallContactList::kNotFlat;
    if (list.recordLoads && k < list.loadForce.size())
    {
        e.loadForce = list.loadForce[k];
        e.loadMoment = list.loadMoment[k];
    }
    out.walls.push_back(e);
}

void packHistory(const KeyedHistory& h, std::vector<std::byte>& out)
{
    ByteWriter w{out};
    out.reserve(out.size() + 20 + (h.pairs.size() + h.walls.size()) * h.scalarCount * 8 +
                h.pairs.size() * kPairEntryBytes + h.walls.size() * kWallEntryBytes);
    w.put(static_cast<std::uint32_t>(h.scalarCount));
    w.put(static_cast<std::uint64_t>(h.pairs.size()));
    for (const PairHistoryEntry& e : h.pairs)
    {
        w.put(e.lo);
        w.put(e.hi);
        w.put(e.spring);
        w.put(e.rolling);
        w.put(e.formed);
        for (unsigned s = 0; s < h.scalarCount; ++s)
            w.put(e.scalars[s]);
    }
    w.put(static_cast<std::uint64_t>(h.walls.size()));
    for (const WallHistoryEntry& e : h.walls)
    {
        w.put(e.id);
        w.put(e.wall);
        w.put(e.spring);
        w.put(e.rolling);
        w.put(e.normal);
        w.put(e.flat);
        w.put(e.loadForce);
        w.put(e.loadMoment);
        for (unsigned s = 0; s < h.scalarCount; ++s)
            w.put(e.scalars[s]);
    }
}

KeyedHistory unpackHistory(std::span<const std::byte> in, int from)
{
    KeyedHistory h;
    if (in.empty())
        return h;
    ByteReader r{in};
    h.scalarCount = r.get<std::uint32_t>();
    if (h.scalarCount > dem::kHistoryScalarRoom)
        throw SimulationError("MPI exchange: contact history from rank " + std::to_string(from) + " has " +
                              std::to_string(h.scalarCount) + " history scalars per contact, at most " +
                              std::to_string(dem::kHistoryScalarRoom) + " are known");
    const auto pairs = r.get<std::uint64_t>();
    if (pairs > in.size() / kPairEntryBytes)
        throw SimulationError("MPI exchange: contact history from rank " + std::to_string(from) + " names " +
                              std::to_string(pairs) + " pairs in " + std::to_string(in.size()) + " bytes");
    h.pairs.resize(pairs);
    for (PairHistoryEntry& e : h.pairs)
    {
        e.lo = r.get<std::uint32_t>();
        e.hi = r.get<std::uint32_t>();
        e.spring = r.vec3();
        e.rolling = r.vec3();
        e.formed = r.get<std::uint8_t>();
        for (unsigned s = 0; s < h.scalarCount; ++s)
            e.scalars[s] = r.get<Real>();
    }
    const auto walls = r.get<std::uint64_t>();
    if (walls > in.size() / kWallEntryBytes)
        throw SimulationError("MPI exchange: contact history from rank " + std::to_string(from) + " names " +
                              std::to_string(walls) + " wall contacts in " + std::to_string(in.size()) +
                              " bytes");
    h.walls.resize(walls);
    for (WallHistoryEntry& e : h.walls)
    {
        e.id = r.get<std::uint32_t>();
        e.wall = r.get<std::uint32_t>();
        e.spring = r.vec3();
        e.rolling = r.vec3();
        e.normal = r.vec3();
        e.flat = r.get<std::uint32_t>();
        e.loadForce = r.vec3();
        e.loadMoment = r.vec3();
        for (unsigned s = 0; s < h.scalarCount; ++s)
            e.scalars[s] = r.get<Real>();
    }
    if (!r.done())
        throw SimulationError("MPI exchange: contact history from rank " + std::to_string(from) + " has " +
                              std::to_string(in.size() - r.at) + " bytes left over");
    return h;
}

namespace
{

constexpr std::uint32_t kAbsent = 0xffffffffu;

/// The local index of each id, through a table sorted by id.
class LocalIndex
{
  public:
    explicit LocalIndex(const dem::ParticleStore& p) : byId_(p.size())
    {
        for (std::size_t i = 0; i < p.size(); ++i)
            byId_[i] = {p.id[i], static_cast<std::uint32_t>(i)};
        std::sort(byId_.begin(), byId_.end());
    }
    std::uint32_t operator()(std::uint32_t id) const
    {
        const auto it = std::lower_bound(byId_.begin(), byId_.end(), std::pair{id, std::uint32_t{0}});
        return it != byId_.end() && it->first == id ? it->second : kAbsent;
    }

  private:
    std::vector<std::pair<std::uint32_t, std::uint32_t>> byId_;
};

void adoptPairs(dem::World& world, const LocalIndex& local, std::span<const KeyedHistory> sources)
{
    struct Kept
    {
        std::uint64_t key; // (i, j) local, i < j
        std::uint32_t source, entry;
        bool flipped;
    };
    std::vector<Kept> kept;
    for (std::uint32_t s = 0; s < sources.size(); ++s)
        for (std::uint32_t e = 0; e < sources[s].pairs.size(); ++e)
        {
            const PairHistoryEntry& p = sources[s].pairs[e];
            const std::uint32_t i = local(p.lo), j = local(p.hi);
            if (i == kAbsent || j == kAbsent)
                continue;
            kept.push_back(
                {i < j ? (std::uint64_t(i) << 32) | j : (std::uint64_t(j) << 32) | i, s, e, i > j});
        }
    std::stable_sort(kept.begin(), kept.end(), [](const Kept& a, const Kept& b) { return a.key < b.key; });
    kept.erase(
        std::unique(kept.begin(), kept.end(), [](const Kept& a, const Kept& b) { return a.key == b.key; }),
        kept.end());
    dem::ContactHistoryStore adopted(world.pairHistory.keepFormed);
    adopted.keepRolling = world.pairHistory.keepRolling;
    adopted.scalarCount = world.pairHistory.scalarCount;
    adopted.spring.resize(kept.size());
    adopted.resizeScalars(kept.size());
    if (adopted.keepRolling)
        adopted.rolling.resize(kept.size());
    if (adopted.keepFormed)
        adopted.formed.resize(kept.size());
    std::vector<std::uint32_t> first(kept.size()), second(kept.size());
    for (std::size_t a = 0; a < kept.size(); ++a)
    {
        const Kept& k = kept[a];
        const PairHistoryEntry& p = sources[k.source].pairs[k.entry];
        first[a] = static_cast<std::uint32_t>(k.key >> 32);
        second[a] = static_cast<std::uint32_t>(k.key);
        const Real sign = k.flipped ? -1.0 : 1.0; // (the entry is lo first; here hi is first)
        adopted.spring[a] = sign * p.spring;
        if (adopted.keepRolling)
            adopted.rolling[a] = sign * p.rolling;
        if (adopted.keepFormed)
            adopted.formed[a] = p.formed;
        for (unsigned s = 0; s < adopted.scalarCount; ++s) // (sources keep the world's count)
            adopted.scalars[a * adopted.scalarCount + s] = p.scalars[s];
    }
    world.neighbors.adoptCandidates(std::move(first), std::move(second), world.pairHistory,
                                    std::move(adopted));
}

void adoptWalls(dem::World& world, const LocalIndex& local, std::span<const KeyedHistory> sources)
{
    struct Kept
    {
        std::uint64_t key; // (particle, wall) local
        std::uint32_t source, entry;
    };
    std::vector<Kept> kept;
    for (std::uint32_t s = 0; s < sources.size(); ++s)
        for (std::uint32_t e = 0; e < sources[s].walls.size(); ++e)
        {
            const WallHistoryEntry& w = sources[s].walls[e];
            if (const std::uint32_t i = local(w.id); i != kAbsent)
                kept.push_back({(std::uint64_t(i) << 32) | w.wall, s, e});
        }
    // Sorted by key, each key's slots in their order; a key is kept from its first source only.
    std::stable_sort(kept.begin(), kept.end(), [](const Kept& a, const Kept& b) { return a.key < b.key; });
    std::size_t n = 0;
    for (std::size_t k = 0; k < kept.size(); ++k)
        if (n == 0 || kept[n - 1].key != kept[k].key || kept[n - 1].source == kept[k].source)
            kept[n++] = kept[k];
    kept.resize(n);
    const dem::WallContactList& list = world.wallContacts;
    const bool meshes =
        !list.meshNormal.empty() || !list.meshFlat.empty() ||
        std::any_of(world.walls.begin(), world.walls.end(),
                    [](const dem::Wall& w) { return std::holds_alternative<dem::MeshShape>(w.shape); });
    dem::ContactHistoryStore adopted(world.wallHistory.keepFormed);
    adopted.keepRolling = world.wallHistory.keepRolling;
    adopted.scalarCount = world.wallHistory.scalarCount;
    adopted.spring.resize(n);
    adopted.resizeScalars(n);
    if (adopted.keepRolling)
        adopted.rolling.resize(n);
    std::vector<std::uint32_t> particles(n), walls(n), flat(meshes ? n : 0);
    std::vector<Vec3> normals(meshes ? n : 0);
    for (std::size_t k = 0; k < n; ++k)
    {
        const WallHistoryEntry& w = sources[kept[k].source].walls[kept[k].entry];
        particles[k] = static_cast<std::uint32_t>(kept[k].key >> 32);
        walls[k] = w.wall;
        adopted.spring[k] = w.spring;
        if (adopted.keepRolling)
            adopted.rolling[k] = w.rolling;
        for (unsigned s = 0; s < adopted.scalarCount; ++s)
            adopted.scalars[k * adopted.scalarCount + s] = w.scalars[s];
        if (meshes)
        {
            normals[k] = w.normal;
            flat[k] = w.flat;
        }
    }
    world.wallContacts.adoptSlots(std::move(particles), std::move(walls), std::move(normals), std::move(flat),
                                  world.wallHistory, std::move(adopted));
}

} // namespace

void adoptHistory(dem::World& world, std::span<const KeyedHistory> sources)
{
    // (the periodic pairs name old indices: their entries come back as candidates, which
    // PeriodicPairs::rebuild takes over by key)
    world.periodicPairs.clear();
    const LocalIndex local(world.particles);
    adoptPairs(world, local, sources);
    adoptWalls(world, local, sources);
}

} // namespace veridem::distributed
