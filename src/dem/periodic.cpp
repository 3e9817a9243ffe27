#include "dem/periodic.h"

#include "core/error.h"
#include "dem/cell_grid.h"
#include "dem/neighbor_list.h"
#include "dem/pair_kernel.h"
#include "dem/world.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace veridem::dem
{

namespace
{

std::uint64_t pairKey(std::uint32_t i, std::uint32_t j)
{
    return (std::uint64_t(i) << 32) | j;
}

Real component(const Vec3& v, int axis)
{
    return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

void setComponent(Vec3& v, int axis, Real value)
{
    (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = value;
}

} // namespace

Vec3 wrapPosition(const PeriodicDomain& domain, const Vec3& x)
{
    Vec3 out = x;
    for (int a = 0; a < 3; ++a)
    {
        if (!domain.periodic[static_cast<std::size_t>(a)])
            continue;
        const Real lo = component(domain.min, a), hi = component(domain.max, a), edge = hi - lo;
        const Real value = component(x, a);
        if (value >= lo && value < hi)
            continue; // inside: unchanged, bit for bit
        Real wrapped = value - edge * std::floor((value - lo) / edge);
        if (wrapped >= hi) // (rounding of a value just below lo)
            wrapped -= edge;
        if (!(wrapped >= lo)) // (rounding, or not finite: left for the health check to report)
            wrapped = std::isfinite(value) ? lo : value;
        setComponent(out, a, wrapped);
    }
    return out;
}

void checkPeriodicBox(const PeriodicDomain& domain, Real maxRadius, Real search)
{
    const Real needed = 2 * periodicCutoff(maxRadius, search);
    for (int a = 0; a < 3; ++a)
    {
        const Real edge = component(domain.length(), a);
        if (domain.periodic[static_cast<std::size_t>(a)] && !(edge >= needed))
        {
            std::ostringstream s;
            s << "the periodic box is " << edge << " m along "
              << "xyz"[a] << ", below 2 x (2 r_max + skin + reach) = " << needed
              << " m (r_max = " << maxRadius << " m, skin + reach = " << search
              << " m), so a pair could touch through two images; enlarge the box or lower 'skin'";
            throw PeriodicBoxError(s.str());
        }
    }
}

void wrapParticles(const PeriodicDomain& domain, ParticleStore& particles)
{
    const bool rows = particles.positionRadius.size() == particles.size();
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        const Vec3 wrapped = wrapPosition(domain, particles.position[i]);
        if (wrapped == particles.position[i])
            continue;
        particles.position[i] = wrapped;
        if (rows)
            particles.positionRadius[i] = particles.positionRadiusRow(i);
    }
}

void PeriodicPairs::clear()
{
    first.clear();
    second.clear();
    shift.clear();
    mass.clear();
    history.clear();
}

void PeriodicPairs::rebuild(const PeriodicDomain& domain, const ParticleStore& particles, Real search,
                            bool anyFixed, NeighborList& neighbors, ContactHistoryStore& pairHistory)
{
    const std::size_t n = particles.size();
    Real maxRadius = 0;
    for (const Real r : particles.radius)
        maxRadius = std::max(maxRadius, r);
    checkPeriodicBox(domain, maxRadius, search);

    // A cell grid: along a periodic axis the box in `count` cells of edge >= the cut-off, along
    // the others the particles' extent (as NeighborList::rebuild), kept O(N) in cells.
    const Real cutoff = periodicCutoff(maxRadius, search);
    std::array<Real, 3> origin{}, extent{}, cellEdge{};
    std::array<std::size_t, 3> count{};
    for (int a = 0; a < 3; ++a)
    {
        const auto s = static_cast<std::size_t>(a);
        if (domain.periodic[s])
        {
            origin[s] = component(domain.min, a);
            extent[s] = component(domain.length(), a);
        }
        else
        {
            Real lo = n ? component(particles.position[0], a) : 0, hi = lo;
            for (const Vec3& x : particles.position)
            {
                lo = std::fmin(lo, component(x, a));
                hi = std::fmax(hi, component(x, a));
            }
            origin[s] = lo;
            extent[s] = std::isfinite(hi - lo) ? hi - lo : 0;
        }
    }
    Real cell = std::fmax(cutoff, 1e-12);
    const Real maxCells = Real(4 * n + 64);
    for (;;)
    {
        Real total = 1;
        for (std::size_t s = 0; s < 3; ++s)
        {
            const Real c = domain.periodic[s] ? std::fmax(1, std::floor(extent[s] / cell))
                                              : std::floor(extent[s] / cell) + 1;
            total *= c;
            count[s] = static_cast<std::size_t>(std::fmin(c, maxCells));
            cellEdge[s] = domain.periodic[s] ? extent[s] / Real(count[s]) : cell;
        }
        if (total <= maxCells)
            break;
        cell *= 1.5;
    }
    const auto coordinate = [&](const Vec3& x, std::size_t s)
    { return cellCoordinate(component(x, static_cast<int>(s)), origin[s], cellEdge[s], count[s]); };
    const std::size_t cells = count[0] * count[1] * count[2];
    std::vector<std::uint32_t> cellStart(cells + 1, 0), cellOf(n), cellParticles(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& x = particles.position[i];
        cellOf[i] = static_cast<std::uint32_t>((coordinate(x, 2) * count[1] + coordinate(x, 1)) * count[0] +
                                               coordinate(x, 0));
        ++cellStart[cellOf[i] + 1];
    }
    sortByCell(
        cellOf, 1, [](std::size_t) { return 0; },
        [&](int) -> std::vector<std::uint32_t>& { return cellStart; },
        [&](int) { return cellParticles.data(); });

    // For each i, the pairs (i, j > i) through an image: the 27 neighbouring cells, each offset
    // along an axis a (cell, shift) pair; a cell reached across a periodic face holds j's images
    // at x_j -+ L. Only the neighbours reached across some face are visited (the direct ones are
    // the neighbour list's).
    struct Found
    {
        std::uint32_t j;
        Vec3 shift;
    };
    std::vector<std::uint32_t> newFirst, newSecond;
    std::vector<Vec3> newShift;
    std::vector<Found> scratch;
    for (std::size_t i = 0; i < n; ++i)
    {
        const std::size_t c = cellOf[i];
        const std::array<std::size_t, 3> at{c % count[0], (c / count[0]) % count[1],
                                            c / (count[0] * count[1])};
        bool onFace = false;
        for (std::size_t s = 0; s < 3; ++s)
            onFace = onFace || (domain.periodic[s] && (at[s] == 0 || at[s] + 1 == count[s]));
        if (!onFace)
            continue;
        // Per axis the (cell, shift) neighbours.
        std::array<std::array<std::pair<std::size_t, Real>, 3>, 3> near{};
        std::array<int, 3> nearCount{};
        for (std::size_t s = 0; s < 3; ++s)
            for (int d = -1; d <= 1; ++d)
            {
                const long raw = static_cast<long>(at[s]) + d;
                const long cnt = static_cast<long>(count[s]);
                if (raw >= 0 && raw < cnt)
                    near[s][static_cast<std::size_t>(nearCount[s]++)] = {static_cast<std::size_t>(raw), 0.0};
                else if (domain.periodic[s])
                    near[s][static_cast<std::size_t>(nearCount[s]++)] = {
                        static_cast<std::size_t>(raw < 0 ? raw + cnt : raw - cnt),
                        raw < 0 ? -extent[s] : extent[s]};
            }
        const Vec3 xi = particles.position[i];
        const Real ri = particles.radius[i];
        scratch.clear();
        for (int z = 0; z < nearCount[2]; ++z)
            for (int y = 0; y < nearCount[1]; ++y)
                for (int x = 0; x < nearCount[0]; ++x)
                {
                    const auto &nx = near[0][static_cast<std::size_t>(x)],
                               &ny = near[1][static_cast<std::size_t>(y)],
                               &nz = near[2][static_cast<std::size_t>(z)];
                    if (nx.second == 0 && ny.second == 0 && nz.second == 0)
                        continue; // a direct neighbour: the neighbour list's
                    const Vec3 s{nx.second, ny.second, nz.second};
                    const std::size_t neighbour = (nz.first * count[1] + ny.first) * count[0] + nx.first;
                    for (std::uint32_t k = cellStart[neighbour]; k < cellStart[neighbour + 1]; ++k)
                    {
                        const std::uint32_t j = cellParticles[k];
                        if (j <= i)
                            continue;
                        const Real within = ri + particles.radius[j] + search;
                        if (lengthSquared(xi - (particles.position[j] + s)) < within * within)
                            scratch.push_back({j, s});
                    }
                }
        std::sort(scratch.begin(), scratch.end(), [](const Found& a, const Found& b) { return a.j < b.j; });
        for (const Found& f : scratch)
        {
            newFirst.push_back(static_cast<std::uint32_t>(i));
            newSecond.push_back(f.j);
            newShift.push_back(f.shift);
        }
    }

    // The history by key: from this list's old pairs, else from the neighbour list's candidates.
    ContactHistoryStore carried(true);
    carried.keepRolling = pairHistory.keepRolling;
    carried.scalarCount = pairHistory.scalarCount;
    const std::size_t pairs = newFirst.size();
    carried.spring.assign(pairs, Vec3{});
    if (carried.keepRolling)
        carried.rolling.assign(pairs, Vec3{});
    carried.formed.assign(pairs, 0);
    carried.resizeScalars(pairs);
    const bool oldRolling = history.keepRolling && history.rolling.size() == history.size();
    const bool mainRolling = pairHistory.keepRolling && pairHistory.rolling.size() == pairHistory.size();
    std::vector<std::uint8_t> continued(first.size(), 0); // old pair k is still periodic
    const std::size_t candidates = std::min(neighbors.activeFirst.size(), pairHistory.size());
    std::size_t old = 0, candidate = 0;
    for (std::size_t k = 0; k < pairs; ++k)
    {
        const std::uint64_t wanted = pairKey(newFirst[k], newSecond[k]);
        while (old < first.size() && pairKey(first[old], second[old]) < wanted)
            ++old;
        while (candidate < candidates &&
               pairKey(neighbors.activeFirst[candidate], neighbors.activeSecond[candidate]) < wanted)
            ++candidate;
        if (old < first.size() && pairKey(first[old], second[old]) == wanted)
        {
            continued[old] = 1;
            carried.spring[k] = history.spring[old];
            if (carried.keepRolling && oldRolling)
                carried.rolling[k] = history.rolling[old];
            carried.formed[k] = history.formed[old];
            carried.copyScalars(k, history, old);
        }
        else if (candidate < candidates &&
                 pairKey(neighbors.activeFirst[candidate], neighbors.activeSecond[candidate]) == wanted)
        {
            carried.spring[k] = pairHistory.spring[candidate];
            if (carried.keepRolling && mainRolling)
                carried.rolling[k] = pairHistory.rolling[candidate];
            carried.formed[k] = pairHistory.formed[candidate];
            carried.copyScalars(k, pairHistory, candidate);
        }
    }

    // The old pairs that may be in contact and are no longer periodic join the neighbour list's
    // candidates (a merge by key), which its rebuild carries to the new slots by (i, j).
    handOverFormed(continued, neighbors, pairHistory);

    first.swap(newFirst);
    second.swap(newSecond);
    shift.swap(newShift);
    history = std::move(carried);
    mass.resize(pairs);
    for (std::size_t k = 0; k < pairs; ++k)
    {
        const std::uint32_t i = first[k], j = second[k];
        const Real mi = particles.mass[i], mj = particles.mass[j];
        mass[k] = effectivePairMass(mi, mj);
        if (anyFixed && (particles.fixed[i] || particles.fixed[j]))
            mass[k] = particles.fixed[i] ? mj : mi;
    }
}

void PeriodicPairs::handOverFormed(const std::vector<std::uint8_t>& continued, NeighborList& neighbors,
                                   ContactHistoryStore& pairHistory) const
{
    const bool oldRolling = history.keepRolling && history.rolling.size() == history.size();
    const bool mainRolling = pairHistory.keepRolling && pairHistory.rolling.size() == pairHistory.size();
    const std::size_t candidates = std::min(neighbors.activeFirst.size(), pairHistory.size());
    std::vector<std::size_t> leaving;
    for (std::size_t k = 0; k < first.size(); ++k)
        if (!continued[k] && history.formed[k])
            leaving.push_back(k);
    if (leaving.empty())
        return;
    ContactHistoryStore merged(true);
    merged.keepRolling = pairHistory.keepRolling;
    merged.scalarCount = pairHistory.scalarCount;
    std::vector<std::uint32_t> mergedFirst, mergedSecond;
    std::size_t a = 0;
    const auto take =
        [&](const ContactHistoryStore& from, std::size_t e, bool rolling, std::uint32_t i, std::uint32_t j)
    {
        mergedFirst.push_back(i);
        mergedSecond.push_back(j);
        merged.spring.push_back(from.spring[e]);
        if (merged.keepRolling)
            merged.rolling.push_back(rolling ? from.rolling[e] : Vec3{});
        merged.formed.push_back(from.formed[e]);
        merged.appendScalars(&from, e);
    };
    for (const std::size_t k : leaving)
    {
        const std::uint64_t key = pairKey(first[k], second[k]);
        for (; a < candidates && pairKey(neighbors.activeFirst[a], neighbors.activeSecond[a]) < key; ++a)
            take(pairHistory, a, mainRolling, neighbors.activeFirst[a], neighbors.activeSecond[a]);
        if (a < candidates && pairKey(neighbors.activeFirst[a], neighbors.activeSecond[a]) == key)
            ++a; // (cannot happen: a pair is a slot's or this list's, never both; this list's wins)
        take(history, k, oldRolling, first[k], second[k]);
    }
    for (; a < candidates; ++a)
        take(pairHistory, a, mainRolling, neighbors.activeFirst[a], neighbors.activeSecond[a]);
    neighbors.activeFirst.swap(mergedFirst);
    neighbors.activeSecond.swap(mergedSecond);
    pairHistory = std::move(merged);
}

void PeriodicPairs::handOver(NeighborList& neighbors, ContactHistoryStore& pairHistory)
{
    handOverFormed(std::vector<std::uint8_t>(first.size(), 0), neighbors, pairHistory);
    clear();
}

void PeriodicPairs::addPairs(const ParticleStore& particles, bool anyFixed,
                             const std::vector<std::uint32_t>& newFirst,
                             const std::vector<std::uint32_t>& newSecond, const std::vector<Vec3>& newShift)
{
    struct Entry
    {
        std::uint64_t key;
        std::uint32_t from; // old pair, or size() + new pair
    };
    const std::size_t old = first.size(), added = newFirst.size();
    std::vector<Entry> order(old + added);
    for (std::size_t k = 0; k < old; ++k)
        order[k] = {pairKey(first[k], second[k]), static_cast<std::uint32_t>(k)};
    for (std::size_t k = 0; k < added; ++k)
        order[old + k] = {pairKey(newFirst[k], newSecond[k]), static_cast<std::uint32_t>(old + k)};
    std::sort(order.begin(), order.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
    PeriodicPairs merged;
    merged.history.keepRolling = history.keepRolling;
    merged.history.scalarCount = history.scalarCount;
    const bool rolling = history.keepRolling && history.rolling.size() == history.size();
    for (const Entry& e : order)
    {
        const auto i = static_cast<std::uint32_t>(e.key >> 32), j = static_cast<std::uint32_t>(e.key);
        merged.first.push_back(i);
        merged.second.push_back(j);
        if (e.from < old)
        {
            merged.shift.push_back(shift[e.from]);
            merged.mass.push_back(mass[e.from]);
            merged.history.spring.push_back(history.spring[e.from]);
            if (history.keepRolling)
                merged.history.rolling.push_back(rolling ? history.rolling[e.from] : Vec3{});
            merged.history.formed.push_back(history.formed[e.from]);
            merged.history.appendScalars(&history, e.from);
            continue;
        }
        const Real mi = particles.mass[i], mj = particles.mass[j];
        Real m = effectivePairMass(mi, mj);
        if (anyFixed && (particles.fixed[i] || particles.fixed[j]))
            m = particles.fixed[i] ? mj : mi;
        merged.shift.push_back(newShift[e.from - old]);
        merged.mass.push_back(m);
        merged.history.spring.push_back(Vec3{});
        if (history.keepRolling)
            merged.history.rolling.push_back(Vec3{});
        merged.history.formed.push_back(0);
        merged.history.appendScalars(nullptr, 0);
    }
    *this = std::move(merged);
}

void PeriodicPairs::renameParticles(const std::vector<std::uint32_t>& newIndex)
{
    struct Renamed
    {
        std::uint64_t key;
        std::uint32_t from;
        bool flipped;
    };
    std::vector<Renamed> kept;
    for (std::size_t k = 0; k < first.size(); ++k)
    {
        const std::uint32_t i = newIndex[first[k]], j = newIndex[second[k]];
        if (i == NeighborList::kGone || j == NeighborList::kGone)
            continue;
        kept.push_back({i < j ? pairKey(i, j) : pairKey(j, i), static_cast<std::uint32_t>(k), i > j});
    }
    std::sort(kept.begin(), kept.end(), [](const Renamed& a, const Renamed& b) { return a.key < b.key; });
    PeriodicPairs renamed;
    renamed.history.keepRolling = history.keepRolling;
    renamed.history.scalarCount = history.scalarCount;
    const bool rolling = history.keepRolling && history.rolling.size() == history.size();
    for (const Renamed& r : kept)
    {
        // (j, i) instead of (i, j): the separation, the relative motion and each spring change
        // sign, and j's image shift becomes i's.
        const Real sign = r.flipped ? -1.0 : 1.0;
        renamed.first.push_back(static_cast<std::uint32_t>(r.key >> 32));
        renamed.second.push_back(static_cast<std::uint32_t>(r.key));
        renamed.shift.push_back(sign * shift[r.from]);
        renamed.mass.push_back(mass[r.from]);
        renamed.history.spring.push_back(sign * history.spring[r.from]);
        if (history.keepRolling)
            renamed.history.rolling.push_back(rolling ? sign * history.rolling[r.from] : Vec3{});
        renamed.history.formed.push_back(history.formed[r.from]);
        renamed.history.appendScalars(&history, r.from); // (scalars do not change sign)
    }
    *this = std::move(renamed);
}

void addPeriodicPairForces(World& world, Real dt, bool sumsAreZero)
{
    ParticleStore& p = world.particles;
    PeriodicPairs& pairs = world.periodicPairs;
    if (!sumsAreZero && world.neighbors.size() == 0) // (the pair stage did not write the sums)
        for (std::size_t i = 0; i < p.size(); ++i)
            p.force[i] = p.torque[i] = Vec3{};
    const Real reach = world.neighbors.reach;
    Real worstRatio = 0;
    std::uint32_t worstParticle = 0;
    bool found = false;
    std::size_t touchingCount = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k)
    {
        const std::uint32_t i = pairs.first[k], j = pairs.second[k];
        const Vec3 separation = (p.position[i] - p.position[j]) - pairs.shift[k];
        const Real touching = p.radius[i] + p.radius[j] + reach;
        if (!(lengthSquared(separation) < touching * touching))
        {
            if (pairs.history.formed[k])
                pairs.history.forget(k); // the contact opened
            continue;
        }
        ContactHistory h = pairs.history.at(k);
        const PairContactResult c = pairContactAt(world, i, j, separation, pairs.mass[k], h, dt);
        pairs.history.set(k, h);
        PairSink::add(p.force[i], c.force);
        PairSink::add(p.torque[i], c.torqueI);
        PairSink::subtract(p.force[j], c.force);
        PairSink::add(p.torque[j], c.torqueJ);
        ++touchingCount;
        const Real minRadius = std::min(p.radius[i], p.radius[j]);
        if (c.overlap > worstRatio * minRadius)
        {
            worstRatio = c.overlap / minRadius;
            worstParticle = i;
            found = true;
        }
    }
    StepHealth& health = world.health;
    health.touchingPairs += touchingCount;
    if (found && worstRatio > health.maxOverlapRatio) // (after the pair stage's: its order)
    {
        health.maxOverlapRatio = worstRatio;
        health.worstParticle = worstParticle;
    }
}

} // namespace veridem::dem
