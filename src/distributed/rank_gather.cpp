#include "distributed/rank_gather.h"

#include "distributed/bytes.h"
#include "distributed/halo.h"
#include "distributed/rank_bonds.h"
#include "distributed/rank_history.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <span>
#include <string>
#include <tuple>

namespace veridem::distributed
{

namespace
{

/// Sets each wall slot's recorded load from the entries (matched by particle, wall and place in
/// the slot group).
void setWallLoads(dem::World& world, std::span<const KeyedHistory> sources)
{
    dem::WallContactList& list = world.wallContacts;
    list.setRecordLoads(true);
    // (ids ascend in the store here, but need not be 0..N-1: a table sorted by id)
    std::vector<std::pair<std::uint32_t, std::uint32_t>> index(world.particles.size());
    for (std::size_t i = 0; i < index.size(); ++i)
        index[i] = {world.particles.id[i], static_cast<std::uint32_t>(i)};
    std::sort(index.begin(), index.end());
    using Key = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>; // particle, wall, place
    std::vector<std::pair<Key, const WallHistoryEntry*>> loads;
    for (const KeyedHistory& h : sources)
    {
        std::uint32_t place = 0;
        for (std::size_t e = 0; e < h.walls.size(); ++e)
        {
            const WallHistoryEntry& w = h.walls[e];
            place = e > 0 && h.walls[e - 1].id == w.id && h.walls[e - 1].wall == w.wall ? place + 1 : 0;
            const auto it = std::lower_bound(index.begin(), index.end(), std::pair{w.id, std::uint32_t{0}});
            if (it != index.end() && it->first == w.id)
                loads.push_back({Key{it->second, w.wall, place}, &w});
        }
    }
    std::sort(loads.begin(), loads.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0, place = 0; k < list.size(); ++k)
    {
        place = k > 0 && list.particle[k - 1] == list.particle[k] && list.wall[k - 1] == list.wall[k]
                    ? place + 1
                    : 0;
        const Key key{list.particle[k], list.wall[k], static_cast<std::uint32_t>(place)};
        const auto it = std::lower_bound(loads.begin(), loads.end(), key,
                                         [](const auto& a, const Key& b) { return a.first < b; });
        if (it != loads.end() && it->first == key)
        {
            list.loadForce[k] = it->second->loadForce;
            list.loadMoment[k] = it->second->loadMoment;
        }
    }
}

} // namespace

dem::World worldLike(const dem::World& local)
{
    dem::World w;
    w.walls = local.walls;
    w.materials = local.materials;
    w.pairs = local.pairs;
    w.domain = local.domain;
    w.time = local.time;
    w.neighbors.skin = local.neighbors.skin;
    w.neighbors.reach = local.neighbors.reach;
    return w;
}

std::optional<dem::World> gatherWorld(const dem::World& local, const RankStep& ranks, int root)
{
    const Collective& comm = ranks.comm();
    const std::size_t owned = ranks.owned();
    const dem::ParticleStore& p = local.particles;
    // One message a rank: the length of the rows [B], the rows, then the history.
    std::vector<std::byte> mine(sizeof(std::uint64_t));
    mine.reserve(owned * kMigrantBytes);
    for (std::size_t i = 0; i < owned; ++i)
        if (!p.retired(i)) // (an outlet took it: out of the outputs, as in one process)
            putParticleRow(mine, p, i, true);
    const std::uint64_t rowBytes = mine.size() - sizeof(std::uint64_t);
    std::memcpy(mine.data(), &rowBytes, sizeof rowBytes);
    KeyedHistory history;
    exportHistory(
        local, [&](std::uint32_t i) { return i < owned; }, history);
    packHistory(history, mine);

    const int size = comm.size();
    Buffers messages(static_cast<std::size_t>(size));
    if (root == kEveryRank)
        for (int b = 0; b < size; ++b)
            messages[b] = mine;
    else
        messages[root] = std::move(mine);
    messages = comm.exchange(std::move(messages));
    std::optional<dem::BondSet> bonds; // (distributed/rank_bonds.h)
    if (local.bonds.enabled)
        bonds = gatherBonds(local.bonds, p, owned, comm, root);
    if (root != kEveryRank && comm.rank() != root)
        return std::nullopt;

    dem::World whole = worldLike(local);
    whole.gravity = local.gravity;
    whole.stepCount = local.stepCount;
    whole.health = local.health;
    whole.pairHistory.keepRolling = local.pairHistory.keepRolling;
    whole.wallHistory.keepRolling = local.wallHistory.keepRolling;
    whole.pairHistory.scalarCount = local.pairHistory.scalarCount;
    whole.wallHistory.scalarCount = local.wallHistory.scalarCount;
    whole.periodicPairs.history.scalarCount = local.pairHistory.scalarCount;
    dem::ParticleStore gathered;
    std::vector<KeyedHistory> sources;
    for (int a = 0; a < size; ++a)
    {
        const std::span<const std::byte> message = messages[a];
        ByteReader r{message};
        const auto rowsOf = r.get<std::uint64_t>(); // [B]
        if (rowsOf > message.size() - r.at)
            throw SimulationError("MPI exchange: the gather's message from rank " + std::to_string(a) +
                                  " has " + std::to_string(message.size()) + " bytes, its rows " +
                                  std::to_string(rowsOf));
        addParticleRows(message.subspan(r.at, rowsOf), gathered, a, true);
        sources.push_back(unpackHistory(message.subspan(r.at + rowsOf), a));
    }
    // By id, as one process holds them (the scene's order; inserted particles after).
    std::vector<std::uint32_t> order(gathered.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return gathered.id[a] < gathered.id[b]; });
    whole.particles.reserve(gathered.size());
    for (const std::uint32_t i : order)
        whole.particles.appendRow(gathered, i);
    adoptHistory(whole, sources);
    if (bonds)
    {
        whole.bonds = std::move(*bonds);
        keepOwnedBonds(whole.bonds, whole.particles, whole.particles.size()); // (indexed in it)
    }
    dem::refreshFixedParticles(whole);
    whole.prepared = true;
    dem::rebuildContactLists(whole);
    if (local.wallContacts.recordLoads)
        setWallLoads(whole, sources);
    return whole;
}

dem::ParticleStore gatherParticlesIn(const dem::ParticleStore& local, std::size_t owned, const Vec3& lo,
                                     const Vec3& hi, const Collective& comm, int root)
{
    Buffers out(static_cast<std::size_t>(comm.size()));
    for (std::size_t i = 0; i < owned; ++i)
    {
        const Vec3& x = local.position[i];
        if (!local.retired(i) && x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z &&
            x.z <= hi.z)
            putParticleRow(out[root], local, i, true);
    }
    const Buffers in = comm.exchange(std::move(out));
    dem::ParticleStore gathered;
    if (comm.rank() != root)
        return gathered;
    for (int a = 0; a < comm.size(); ++a)
        addParticleRows(in[a], gathered, a, true);
    return gathered;
}

dem::ParticleStore broadcastParticles(const dem::ParticleStore& rows, const Collective& comm, int root)
{
    Buffers out(static_cast<std::size_t>(comm.size()));
    if (comm.rank() == root)
        for (int b = 0; b < comm.size(); ++b)
            for (std::size_t i = 0; i < rows.size(); ++i)
                putParticleRow(out[b], rows, i, true);
    const Buffers in = comm.exchange(std::move(out));
    dem::ParticleStore received;
    addParticleRows(in[root], received, root, true);
    return received;
}

} // namespace veridem::distributed
