#include "distributed/halo.h"

#include "core/error.h"
#include "distributed/bytes.h"
#include "distributed/exchange_plan.h"

#include <cstring>
#include <span>
#include <string>

namespace veridem::distributed
{

namespace
{

void checkSize(std::size_t bytes, std::size_t record, std::size_t expected, const char* what, int from)
{
    if (bytes != record * expected)
        throw SimulationError(std::string("MPI exchange: ") + what + " from rank " + std::to_string(from) +
                              ": " + std::to_string(bytes) + " bytes, expected " + std::to_string(expected) +
                              " records of " + std::to_string(record));
}

} // namespace

void putParticleRow(std::vector<std::byte>& out, const dem::ParticleStore& p, std::size_t i, bool withForce)
{
    ByteWriter w{out};
    w.put(p.id[i]);
    w.put(p.material[i]);
    w.put(p.fixed[i]);
    w.put(p.position[i]);
    w.put(p.velocity[i]);
    w.put(p.angularVelocity[i]);
    for (const Real v : {p.radius[i], p.mass[i], p.invMass[i], p.invInertia[i]})
        w.put(v);
    if (withForce)
    {
        w.put(Vec3(p.force[i]));
        w.put(Vec3(p.torque[i]));
    }
}

std::size_t addParticleRows(std::span<const std::byte> in, dem::ParticleStore& p, int from, bool withForce)
{
    const std::size_t bytes = withForce ? kMigrantBytes : kRowBytes;
    if (in.size() % bytes != 0)
        checkSize(in.size(), bytes, in.size() / bytes, "particle rows", from);
    ByteReader r{in};
    const std::size_t count = in.size() / bytes;
    for (std::size_t k = 0; k < count; ++k)
    {
        p.id.push_back(r.get<std::uint32_t>());
        p.material.push_back(r.get<std::uint32_t>());
        p.fixed.push_back(r.get<std::uint8_t>());
        p.position.push_back(r.vec3());
        p.velocity.push_back(r.vec3());
        p.angularVelocity.push_back(r.vec3());
        p.radius.push_back(r.get<Real>());
        p.mass.push_back(r.get<Real>());
        p.invMass.push_back(r.get<Real>());
        p.invInertia.push_back(r.get<Real>());
        p.force.emplace_back(withForce ? r.vec3() : Vec3{});
        p.torque.emplace_back(withForce ? r.vec3() : Vec3{});
        p.positionRadius.push_back(p.positionRadiusRow(p.size() - 1));
    }
    return count;
}

std::size_t Halo::ghosts() const
{
    std::size_t n = 0;
    for (const std::size_t c : ghostCount)
        n += c;
    return n;
}

int Halo::neighbours() const
{
    int n = 0;
    for (std::size_t b = 0; b < sent.size(); ++b)
        n += !sent[b].empty() || ghostCount[b] != 0;
    return n;
}

Halo exchangeParticles(dem::ParticleStore& p, std::size_t keep, const Decomposition& d, Real halo,
                       const Collective& comm, bool betweenSteps)
{
    const int ranks = comm.size(), me = comm.rank();
    if (d.parts() != ranks)
        throw InputError("MPI exchange: the decomposition has " + std::to_string(d.parts()) + " parts for " +
                         std::to_string(ranks) + " ranks");
    if (keep > p.size())
        throw InputError("MPI exchange: keep " + std::to_string(keep) + " of " + std::to_string(p.size()) +
                         " particles");
    p.truncate(keep); // (the old ghosts)
    Halo h;

    // Migrants: out with their rows, the others closed up in order, then the arrivals appended.
    const ExchangePlan leave = planExchange(d, me, p.position, p.radius, halo);
    Buffers out(ranks);
    std::vector<std::uint8_t> leaving(p.size(), 0);
    for (int b = 0; b < ranks; ++b)
    {
        out[b].reserve(leave.migrate[b].size() * (betweenSteps ? kMigrantBytes : kRowBytes));
        for (const std::uint32_t i : leave.migrate[b])
        {
            putParticleRow(out[b], p, i, betweenSteps);
            leaving[i] = 1;
        }
        h.bytesSent += out[b].size();
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!leaving[i])
        {
            if (kept != i)
                p.copyRow(i, kept);
            ++kept;
        }
    p.truncate(kept);
    Buffers in = comm.exchange(std::move(out));
    for (int a = 0; a < ranks; ++a)
        if (a != me)
            addParticleRows(in[a], p, a, betweenSteps);
    h.owned = p.size();

    // Ghosts: every owned particle to each rank whose region is within r_i + halo.
    const ExchangePlan near = planExchange(d, me, p.position, p.radius, halo);
    out.assign(ranks, {});
    for (int b = 0; b < ranks; ++b)
    {
        out[b].reserve(near.ghost[b].size() * kRowBytes);
        for (const std::uint32_t i : near.ghost[b])
            putParticleRow(out[b], p, i, false);
        h.bytesSent += out[b].size();
    }
    h.sent = near.ghost;
    in = comm.exchange(std::move(out));
    h.ghostFirst.assign(ranks, p.size());
    h.ghostCount.assign(ranks, 0);
    for (int a = 0; a < ranks; ++a)
    {
        h.ghostFirst[a] = p.size();
        if (a != me)
            h.ghostCount[a] = addParticleRows(in[a], p, a, false);
    }
    return h;
}

Halo splitWholeStore(dem::ParticleStore& p, const Decomposition& d, Real halo, int me)
{
    const int ranks = d.parts();
    const std::size_t n = p.size();
    std::vector<int> owner(n);
    for (std::size_t i = 0; i < n; ++i)
        owner[i] = d.owner(p.position[i]);
    // Per rank a, the particles whose ghost `me` needs (a's owned ones, in store order); per rank
    // b, the ones of `me` whose ghost b needs.
    std::vector<std::vector<std::uint32_t>> ghostsFrom(ranks), sentTo(ranks);
    std::vector<std::uint32_t> mine;
    for (std::size_t i = 0; i < n; ++i)
    {
        const auto index = static_cast<std::uint32_t>(i);
        if (owner[i] == me)
            mine.push_back(index);
        d.forEachPartNear(p.position[i], p.radius[i] + halo,
                          [&](int part)
                          {
                              if (part == owner[i])
                                  return;
                              if (part == me)
                                  ghostsFrom[owner[i]].push_back(index);
                              else if (owner[i] == me)
                                  sentTo[part].push_back(index);
                          });
    }
    Halo h;
    h.owned = mine.size();
    h.ghostFirst.assign(ranks, 0);
    h.ghostCount.assign(ranks, 0);
    std::vector<std::uint32_t> order = mine; // the new store's rows, by old index
    for (int a = 0; a < ranks; ++a)
    {
        h.ghostFirst[a] = order.size();
        h.ghostCount[a] = ghostsFrom[a].size();
        order.insert(order.end(), ghostsFrom[a].begin(), ghostsFrom[a].end());
    }
    std::vector<std::uint32_t> newIndex(n, 0xffffffffu);
    for (std::size_t k = 0; k < h.owned; ++k)
        newIndex[order[k]] = static_cast<std::uint32_t>(k);
    h.sent.resize(ranks);
    for (int b = 0; b < ranks; ++b)
        for (const std::uint32_t i : sentTo[b])
            h.sent[b].push_back(newIndex[i]);
    dem::ParticleStore kept;
    kept.reserve(order.size());
    for (const std::uint32_t i : order)
        kept.appendRow(p, i);
    p = std::move(kept);
    return h;
}

void ghostMotion(const dem::ParticleStore& p, const Halo& h, const Collective& comm, Vec3* position,
                 Vec3* velocity, Vec3* angularVelocity)
{
    const int ranks = comm.size();
    Buffers out(ranks);
    for (int b = 0; b < ranks; ++b)
    {
        out[b].reserve(h.sent[b].size() * kMotionBytes);
        ByteWriter w{out[b]};
        for (const std::uint32_t i : h.sent[b])
        {
            w.put(p.position[i]);
            w.put(p.velocity[i]);
            w.put(p.angularVelocity[i]);
        }
    }
    std::vector<std::size_t> sizes(ranks);
    for (int a = 0; a < ranks; ++a)
        sizes[a] = h.ghostCount[a] * kMotionBytes;
    const Buffers in = comm.exchangeSized(std::move(out), sizes);
    for (int a = 0; a < ranks; ++a)
    {
        if (a == comm.rank())
            continue;
        checkSize(in[a].size(), kMotionBytes, h.ghostCount[a], "ghost motion", a);
        ByteReader r{in[a]};
        for (std::size_t k = 0; k < h.ghostCount[a]; ++k)
        {
            const std::size_t g = h.ghostFirst[a] + k;
            const Vec3 x = r.vec3();
            if (position)
                position[g] = x;
            velocity[g] = r.vec3();
            angularVelocity[g] = r.vec3();
        }
    }
}

void refreshGhosts(dem::ParticleStore& p, const Halo& h, const Collective& comm)
{
    ghostMotion(p, h, comm, p.position.data(), p.velocity.data(), p.angularVelocity.data());
    for (int a = 0; a < comm.size(); ++a)
        if (a != comm.rank())
            for (std::size_t g = h.ghostFirst[a]; g < h.ghostFirst[a] + h.ghostCount[a]; ++g)
                p.positionRadius[g] = p.positionRadiusRow(g);
}

void returnGhostForces(dem::ParticleStore& p, const Halo& h, const Collective& comm)
{
    const int ranks = comm.size();
    Buffers out(ranks);
    for (int a = 0; a < ranks; ++a)
    {
        out[a].reserve(h.ghostCount[a] * kForceBytes);
        ByteWriter w{out[a]};
        for (std::size_t k = 0; k < h.ghostCount[a]; ++k)
        {
            const std::size_t g = h.ghostFirst[a] + k;
            w.put(Vec3(p.force[g]));
            w.put(Vec3(p.torque[g]));
            p.force[g] = p.torque[g] = dem::PaddedVec3{};
        }
    }
    std::vector<std::size_t> sizes(ranks);
    for (int b = 0; b < ranks; ++b)
        sizes[b] = h.sent[b].size() * kForceBytes;
    const Buffers in = comm.exchangeSized(std::move(out), sizes);
    for (int b = 0; b < ranks; ++b) // (ascending rank: one order of the sums)
    {
        if (b == comm.rank())
            continue;
        checkSize(in[b].size(), kForceBytes, h.sent[b].size(), "ghost forces", b);
        ByteReader r{in[b]};
        for (const std::uint32_t i : h.sent[b])
        {
            const Vec3 f = r.vec3(), t = r.vec3();
            p.force[i] = Vec3(p.force[i]) + f;
            p.torque[i] = Vec3(p.torque[i]) + t;
        }
    }
}

} // namespace veridem::distributed
