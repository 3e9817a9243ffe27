#include "distributed/rank_step.h"

#include "core/error.h"
#include "dem/forces.h"
#include "dem/particle_changes.h"
#include "distributed/rank_bonds.h"
#include "distributed/rank_history.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <span>
#include <string>

namespace veridem::distributed
{

namespace
{

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point from, Clock::time_point to)
{
    return std::chrono::duration<double>(to - from).count();
}

constexpr Real kLeast = std::numeric_limits<Real>::min(); // (a halo of no particles: > 0)

/// Wraps the particles into the domain box along its periodic axes (a no-op without them) before
/// the regions are cut or the particles exchanged: forEachPartNear's images assume it
/// (distributed/bisection.h). One process wraps at the same point, the rebuild of the contact lists that
/// follows (dem::rebuildContactLists), so the positions are the same.
void wrapIntoBox(dem::World& world)
{
    if (world.domain.any())
        dem::wrapParticles(world.domain, world.particles);
}

/// Each particle's cost for the cut: 1 plus its touching candidates (the pair stage's work).
std::vector<std::uint32_t> contactWeights(const dem::World& world, std::size_t count)
{
    std::vector<std::uint32_t> weight(count, 1);
    const dem::NeighborList& list = world.neighbors;
    for (std::size_t a = 0; a < list.activeFirst.size(); ++a)
        for (const std::uint32_t i : {list.activeFirst[a], list.activeSecond[a]})
            if (i < count)
                ++weight[i];
    return weight;
}

} // namespace

RankStep::RankStep(const Collective& comm, std::uint64_t rebalanceEvery)
    : comm_(comm), rebalanceEvery_(rebalanceEvery)
{
    if (rebalanceEvery < 1)
        throw InputError("MPI: the regions must be cut again every 1 or more exchanges");
}

void RankStep::distribute(dem::World& world)
{
    if (world.prepared) // (a restored world: the particles its outlets retired leave first)
        dem::removeRetiredParticles(world);
    // (a restored world's bonds: those of removed particles dropped, the totals on the first rank)
    startBondCounts(world.bonds, world.particles, comm_.rank() == 0);
    wrapIntoBox(world);
    dem::ParticleStore& p = world.particles;
    const std::size_t n = p.size();
    // What prepare() sets from all the particles, set here for all ranks alike.
    if (world.neighbors.skin <= 0)
        world.neighbors.skin = dem::defaultSkin(world);
    Real largest = 0;
    for (const Real r : p.radius)
        largest = std::max(largest, r);

    // Every rank holds every particle: each takes one slice of them to the cut (the same regions
    // however they are sliced: bisect's sums are exact).
    const auto ranks = static_cast<std::size_t>(comm_.size()), me = static_cast<std::size_t>(comm_.rank());
    const std::size_t lo = n * me / ranks, hi = n * (me + 1) / ranks;
    const std::vector<std::uint32_t> weight = contactWeights(world, n);
    decomposition_ = bisect(std::span(p.position).subspan(lo, hi - lo),
                            std::span(weight).subspan(lo, hi - lo), comm_.size(), comm_, world.domain);
    ++cuts_;

    if (!world.prepared) // a fresh start: prepare this rank's part only (no contacts yet to carry)
    {
        // (bonds: their halo from the start, rank_bonds.h; none are formed yet)
        const Real bonds = bondHalo(world.bonds, largest, world.neighbors.skin);
        halo_ = splitWholeStore(p, decomposition_, std::max({largest + world.neighbors.skin, bonds, kLeast}),
                                comm_.rank());
        dem::prepare(world);
        // The touch reach (JKR adhesion) from the materials and radii of all ranks' particles: the
        // largest. A halo that must hold it too: the ghosts made again, the lists and the initial
        // forces with them.
        double reach = world.neighbors.reach;
        comm_.max(std::span(&reach, 1));
        haloWidth_ = std::max({largest + world.neighbors.skin + reach, bonds, kLeast});
        world.ranks = this;
        if (reach > 0)
        {
            world.neighbors.reach = reach;
            exchange(world);
            dem::rebuildContactLists(world);
            dem::computeForces(world, 0.0);
        }
        return;
    }
    // A restored (or prepared) world: its contact history, keyed by id, goes with the particles.
    haloWidth_ = std::max({largest + world.neighbors.skin + world.neighbors.reach,
                           bondHalo(world.bonds, largest, world.neighbors.skin), kLeast});
    KeyedHistory all;
    exportHistory(
        world, [](std::uint32_t) { return true; }, all);
    halo_ = splitWholeStore(p, decomposition_, haloWidth_, comm_.rank());
    adoptHistory(world, std::span(&all, 1));
    if (world.bonds.enabled)
        keepOwnedBonds(world.bonds, p, halo_.owned);
    dem::refreshFixedParticles(world);
    world.ranks = this;
    dem::rebuildContactLists(world);
}

void RankStep::cut(const dem::World& world, std::span<const std::uint8_t> gone)
{
    const std::vector<std::uint32_t> weight = contactWeights(world, halo_.owned);
    std::vector<Vec3> x;
    std::vector<std::uint32_t> w;
    x.reserve(halo_.owned);
    w.reserve(halo_.owned);
    for (std::size_t i = 0; i < halo_.owned; ++i)
        if (!gone[i]) // (a retired particle, parked far away, would stretch the bounds)
        {
            x.push_back(world.particles.position[i]);
            w.push_back(weight[i]);
        }
    decomposition_ = bisect(x, w, comm_.size(), comm_, world.domain);
    ++cuts_;
}

void RankStep::admit(dem::World& world, const dem::ParticleStore& arrivals)
{
    const auto start = Clock::now();
    exchange(world, &arrivals);
    dem::rebuildContactLists(world);
    times_.exchange += seconds(start, Clock::now());
}

bool RankStep::afterDrift(dem::World& world, bool rebuild)
{
    const auto start = Clock::now();
    refreshGhosts(world.particles, halo_, comm_);
    for (const auto& sent : halo_.sent)
        refreshBytes_ += sent.size() * kMotionBytes;
    const auto refreshed = Clock::now();
    times_.refresh += seconds(start, refreshed);
    double decision = rebuild ? 1 : 0;
    comm_.max(std::span(&decision, 1));
    const auto decided = Clock::now();
    times_.decision += seconds(refreshed, decided);
    if (decision == 0)
        return false;
    exchange(world);
    times_.exchange += seconds(decided, Clock::now());
    return true;
}

void RankStep::exchange(dem::World& world, const dem::ParticleStore* arrivals)
{
    wrapIntoBox(world);
    dem::ParticleStore& p = world.particles;
    const std::size_t owned = halo_.owned;
    std::vector<std::uint8_t> gone(owned); // retired by an outlet: they leave the store here
    for (std::size_t i = 0; i < owned; ++i)
        gone[i] = p.retired(i);
    if (++exchanges_ % rebalanceEvery_ == 0)
        cut(world, gone);
    const int ranks = comm_.size(), me = comm_.rank();
    std::vector<int> dest(owned);
    for (std::size_t i = 0; i < owned; ++i)
        dest[i] = gone[i] ? -1 : decomposition_.owner(p.position[i]);
    // The bonds go with their partners (rank_bonds.h), before the store changes.
    Buffers bondMail;
    if (world.bonds.enabled)
        bondMail = routeBonds(world.bonds, p, dest, comm_);

    // The history this rank keeps (a contact of a particle it still owns) and the history that
    // leaves with each migrant (every contact of it), in one pass over the lists.
    std::vector<KeyedHistory> history(static_cast<std::size_t>(ranks)); // [me]: kept here
    const auto destination = [&](std::uint32_t i) { return i < owned ? dest[i] : -1; };
    // (a pair goes to each rank that owns one of its particles after the exchange)
    const auto sendPair = [&](std::uint32_t i, std::uint32_t j, auto&& put)
    {
        const int di = destination(i), dj = destination(j);
        if (di == me || dj == me)
            put(history[me]);
        if (di >= 0 && di != me)
            put(history[di]);
        if (dj >= 0 && dj != me && dj != di)
            put(history[dj]);
    };
    const dem::NeighborList& list = world.neighbors;
    for (std::size_t a = 0; a < list.activeFirst.size() && a < world.pairHistory.size(); ++a)
        if (mayBeFormed(world.pairHistory, a))
            sendPair(list.activeFirst[a], list.activeSecond[a],
                     [&](KeyedHistory& h) { exportPair(world, a, h); });
    const dem::PeriodicPairs& periodic = world.periodicPairs;
    for (std::size_t k = 0; k < periodic.size() && k < periodic.history.size(); ++k)
        if (mayBeFormed(periodic.history, k))
            sendPair(periodic.first[k], periodic.second[k],
                     [&](KeyedHistory& h) { exportPeriodicPair(world, k, h); });
    const dem::WallContactList& walls = world.wallContacts;
    for (std::size_t k = 0; k < walls.particle.size() && k < world.wallHistory.size(); ++k)
        if (const int d = destination(walls.particle[k]); d >= 0)
            exportWallSlot(world, k, history[d]);

    // The store: the owned particles that stay in it (in order), then the arrivals this rank's
    // region holds; exchangeParticles then migrates and makes the ghosts.
    p.truncate(owned);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < owned; ++i)
        if (!gone[i])
        {
            if (kept != i)
                p.copyRow(i, kept);
            ++kept;
        }
    p.truncate(kept);
    if (arrivals)
        for (std::size_t i = 0; i < arrivals->size(); ++i)
        {
            if (decomposition_.owner(arrivals->position[i]) == me)
                p.appendRow(*arrivals, i);
            // (a larger particle than any before widens the halo on every rank alike: all see
            // the same arrivals)
            haloWidth_ =
                std::max({haloWidth_, arrivals->radius[i] + world.neighbors.skin + world.neighbors.reach,
                          bondHalo(world.bonds, arrivals->radius[i], world.neighbors.skin)});
        }
    halo_ = exchangeParticles(p, p.size(), decomposition_, haloWidth_, comm_, arrivals != nullptr);
    exchangeBytes_ += halo_.bytesSent;
    Buffers out(static_cast<std::size_t>(ranks));
    for (int b = 0; b < ranks; ++b)
        if (b != me && (!history[b].pairs.empty() || !history[b].walls.empty()))
        {
            packHistory(history[b], out[b]);
            exchangeBytes_ += out[b].size();
        }
    const Buffers in = comm_.exchange(std::move(out));
    std::vector<KeyedHistory> sources; // this rank's own first, then the arrivals by rank
    sources.push_back(std::move(history[me]));
    for (int a = 0; a < ranks; ++a)
        if (a != me)
            sources.push_back(unpackHistory(in[a], a));
    adoptHistory(world, sources);
    if (world.bonds.enabled)
    {
        for (const auto& mail : bondMail)
            exchangeBytes_ += mail.size();
        adoptBonds(world.bonds, p, halo_.owned, comm_.exchange(std::move(bondMail)));
    }
    dem::refreshFixedParticles(world);
}

void RankStep::combineHealth(dem::World& world)
{
    dem::StepHealth& h = world.health;
    localRatio_ = h.maxOverlapRatio;
    localWorst_ = h.worstParticle;
    localFinite_ = h.finite;
    localFirstNonFinite_ = h.firstNonFinite;
    double v[2] = {h.maxOverlapRatio, h.finite ? 0.0 : 1.0};
    const auto start = Clock::now();
    comm_.max(v);
    times_.health += seconds(start, Clock::now());
    h.maxOverlapRatio = v[0];
    h.finite = v[1] == 0;
}

std::uint32_t RankStep::failedParticleId(const dem::World& world) const
{
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    const dem::ParticleStore& p = world.particles;
    std::uint32_t mine = kNone;
    if (!world.health.finite)
    {
        if (!localFinite_ && localFirstNonFinite_ < p.size())
            mine = p.id[localFirstNonFinite_];
    }
    else if (localRatio_ == world.health.maxOverlapRatio && localWorst_ < p.size())
        mine = p.id[localWorst_];
    double v = static_cast<double>(kNone - mine); // (the lowest id: the largest of these)
    comm_.max(std::span(&v, 1));
    return kNone - static_cast<std::uint32_t>(v);
}

void RankStep::velocitiesAfterStep(const dem::World& world, std::vector<Vec3>& velocity,
                                   std::vector<Vec3>& angularVelocity)
{
    const dem::ParticleStore& p = world.particles;
    velocity = p.velocity;
    angularVelocity = p.angularVelocity;
    ghostMotion(p, halo_, comm_, nullptr, velocity.data(), angularVelocity.data());
}

} // namespace veridem::distributed
