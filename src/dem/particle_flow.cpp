#include "dem/particle_flow.h"

#include "dem/particle_changes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace veridem::dem
{

namespace
{

/// Two unit vectors completing the unit `axis` to an orthonormal basis.
void perpendiculars(const Vec3& axis, Vec3& u, Vec3& w)
{
    const Vec3 helper = std::fabs(axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    u = cross(axis, helper);
    u = u / length(u);
    w = cross(axis, u);
}

} // namespace

bool FlowRegion::contains(const Vec3& x) const
{
    switch (kind)
    {
    case Kind::Box:
        return x.x >= min.x && x.x <= max.x && x.y >= min.y && x.y <= max.y && x.z >= min.z && x.z <= max.z;
    case Kind::Cylinder:
    {
        const Vec3 d = x - point;
        const Real along = dot(d, axis);
        return along >= 0 && along <= length && lengthSquared(d - along * axis) <= radius * radius;
    }
    case Kind::HalfSpace:
        return dot(x - point, normal) > 0;
    }
    return false;
}

bool FlowRegion::sample(Random& random, Real r, Vec3& x) const
{
    if (kind == Kind::Box)
    {
        if (!(max.x - min.x >= 2 * r && max.y - min.y >= 2 * r && max.z - min.z >= 2 * r))
            return false;
        const Real a = random.uniform(min.x + r, max.x - r), b = random.uniform(min.y + r, max.y - r),
                   c = random.uniform(min.z + r, max.z - r);
        x = {a, b, c};
        return true;
    }
    if (kind == Kind::Cylinder)
    {
        if (!(radius >= r && length >= 2 * r))
            return false;
        const Real along = random.uniform(r, length - r);
        Real s, t; // uniform in the unit disk, by rejection from the square (no trigonometry)
        do
        {
            s = 2 * random.uniform() - 1;
            t = 2 * random.uniform() - 1;
        } while (s * s + t * t > 1);
        Vec3 u, w;
        perpendiculars(axis, u, w);
        x = point + along * axis + (radius - r) * (s * u + t * w);
        return true;
    }
    return false;
}

void FlowRegion::bounds(Vec3& lo, Vec3& hi) const
{
    if (kind == Kind::Box)
    {
        lo = min;
        hi = max;
        return;
    }
    // Cylinder: the end disks' boxes (a disk of unit normal a spans r sqrt(1 - a_k^2) along k).
    const Vec3 end = point + length * axis;
    const Vec3 e{radius * std::sqrt(std::fmax(0.0, 1 - axis.x * axis.x)),
                 radius * std::sqrt(std::fmax(0.0, 1 - axis.y * axis.y)),
                 radius * std::sqrt(std::fmax(0.0, 1 - axis.z * axis.z))};
    lo = Vec3{std::fmin(point.x, end.x), std::fmin(point.y, end.y), std::fmin(point.z, end.z)} - e;
    hi = Vec3{std::fmax(point.x, end.x), std::fmax(point.y, end.y), std::fmax(point.z, end.z)} + e;
}

Real RadiusDistribution::sample(Random& random) const
{
    switch (kind)
    {
    case Kind::Fixed:
        return value;
    case Kind::Uniform:
        return random.uniform(min, max);
    case Kind::Normal:
        for (;;) // rejection: the truncated normal exactly (the reader checks min <= mean <= max)
        {
            const Real r = mean + std * random.normal();
            if (r >= min && r <= max)
                return r;
        }
    case Kind::LogNormal:
        for (;;)
        {
            const Real r = std::exp(mu + sigma * random.normal());
            if (r >= min && r <= max)
                return r;
        }
    case Kind::Table:
    {
        const Real u = random.uniform();
        std::size_t k = 0;
        while (k + 1 < radii.size() && u >= cumulative[k])
            ++k;
        return radii[k];
    }
    }
    return value;
}

Real RadiusDistribution::largest() const
{
    switch (kind)
    {
    case Kind::Fixed:
        return value;
    case Kind::Table:
        return *std::max_element(radii.begin(), radii.end());
    default:
        return max;
    }
}

Real ParticleFlow::largestRadius() const
{
    Real r = 0;
    for (const Inserter& in : inserters)
        r = std::max(r, in.radius.largest());
    return r;
}

namespace
{

/// True while the inserter is behind its schedule at time t [s].
bool behind(const Inserter& in, Real t, Real dt)
{
    if (t < in.from - 0.5 * dt)
        return false;
    const Real elapsed = std::max(Real(0), std::min(t, in.until) - in.from);
    switch (in.mode)
    {
    case Inserter::Mode::Count:
    {
        const Real window = in.until - in.from;
        const Real due =
            window > 0 ? std::floor(in.count * std::min(Real(1), elapsed / window + 1e-12)) : in.count;
        return Real(in.inserted) < due;
    }
    case Inserter::Mode::Rate:
        return Real(in.inserted) < std::floor(in.rate * elapsed + 1e-9);
    case Inserter::Mode::MassRate:
        return in.insertedMass < in.rate * elapsed;
    }
    return false;
}

/// True if a sphere (x, r) [m] overlaps no particle, nor a particle's image in a periodic box
/// (`index` holds every particle near x and its images).
bool freeOfParticles(const World& world, const ParticleIndex& index, const Vec3& x, Real r)
{
    const ParticleStore& p = world.particles;
    bool free = true;
    forEachImageShift(world.domain, x, r + index.largestRadius() + 0.5 * world.neighbors.skin,
                      [&](const Vec3& s)
                      {
                          const Vec3 q = x + s;
                          index.forEachNear(q,
                                            [&](std::uint32_t j)
                                            {
                                                const Real reach = r + p.radius[j];
                                                free = free &&
                                                       !(lengthSquared(q - p.position[j]) < reach * reach);
                                            });
                      });
    return free;
}

/// Inserts the particles `in` owes at time t, each appended to `index`; returns how many.
std::size_t insert(World& world, Inserter& in, ParticleIndex& index, std::uint32_t& nextId, Real t, Real dt)
{
    if (!behind(in, t, dt))
        return 0;
    ParticleStore& p = world.particles;
    std::size_t added = 0;
    while (behind(in, t, dt))
    {
        const Real r = in.radius.sample(in.random);
        std::size_t m = 0;
        const Real u = in.random.uniform();
        while (m + 1 < in.materials.size() && u >= in.materialCumulative[m])
            ++m;
        const std::uint32_t material = in.materials[m];
        const Real s = in.velocitySpread;
        Vec3 v = in.velocity;
        if (s > 0)
        {
            const Real a = in.random.uniform(-s, s), b = in.random.uniform(-s, s),
                       c = in.random.uniform(-s, s);
            v += Vec3{a, b, c};
        }
        bool placed = false;
        Vec3 x;
        for (int attempt = 0; attempt < ParticleFlow::kAttempts && !placed; ++attempt)
        {
            if (!in.region.sample(in.random, r, x))
                break;
            x = wrapPosition(world.domain, x); // (a region across a periodic face)
            placed = freeOfParticles(world, index, x, r);
            for (std::size_t w = 0; placed && w < world.walls.size(); ++w)
                placed = !wallGap(world.walls[w], x, r).touching;
        }
        if (!placed)
        {
            if (!in.warnedFull)
                std::fprintf(stderr,
                             "veridem: warning: [[insert]] '%s' is full at t = %.6g s (%llu inserted): no "
                             "free place found for a sphere of radius %.4g m; it tries again at the next "
                             "insertion time\n",
                             in.name.c_str(), t, static_cast<unsigned long long>(in.inserted), r);
            in.warnedFull = true;
            break;
        }
        p.add(x, v, {}, r, world.materials[material].density, material);
        p.id.back() = nextId++;
        index.append(static_cast<std::uint32_t>(p.size() - 1), x);
        ++in.inserted;
        in.insertedMass += p.mass.back();
        ++added;
    }
    return added;
}

} // namespace

std::vector<std::uint32_t> ParticleFlow::takeAtOutlets(const World& world, std::size_t count)
{
    std::vector<std::uint32_t> doomed;
    if (outlets.empty())
        return doomed;
    const ParticleStore& p = world.particles;
    for (std::size_t i = 0; i < count; ++i)
    {
        if (p.fixed[i] || p.retired(i))
            continue;
        for (Outlet& o : outlets)
            if (o.region.contains(p.position[i]))
            {
                ++o.count;
                o.mass += p.mass[i];
                doomed.push_back(static_cast<std::uint32_t>(i));
                break;
            }
    }
    return doomed;
}

bool ParticleFlow::insertionDue(Real t, Real dt) const
{
    bool due = false;
    for (const Inserter& in : inserters)
        due = due || behind(in, t, dt);
    return due;
}

void ParticleFlow::insertNew(World& world, Real dt)
{
    // The grid of the particles for the overlap test and the new pairs (particle_index.h), kept
    // from the last event while the contact lists were not rebuilt.
    const ParticleStore& p = world.particles;
    const Real newRadius = largestRadius(), extra = insertedPairSearch(world.neighbors);
    if (!index.validFor(world.neighbors, p.size(), newRadius, extra))
    {
        Vec3 lo, hi;
        insertionBounds(world.domain, lo, hi);
        index.build(p, world.neighbors, newRadius, extra, lo, hi);
    }
    for (Inserter& in : inserters)
        insert(world, in, index, nextId, world.time, dt);
}

void ParticleFlow::insertionBounds(const PeriodicDomain& box, Vec3& lo, Vec3& hi) const
{
    lo = {1, 1, 1}, hi = {0, 0, 0}; // (empty)
    for (const Inserter& in : inserters)
    {
        Vec3 a, b;
        in.region.bounds(a, b);
        const bool first = lo.x > hi.x;
        lo = first ? a : Vec3{std::fmin(lo.x, a.x), std::fmin(lo.y, a.y), std::fmin(lo.z, a.z)};
        hi = first ? b : Vec3{std::fmax(hi.x, b.x), std::fmax(hi.y, b.y), std::fmax(hi.z, b.z)};
    }
    // Along a periodic axis the whole box: a new particle near one face meets the particles
    // near the other through their images.
    const auto widen = [](Real& a, Real& b, Real boxMin, Real boxMax)
    {
        a = std::fmin(a, boxMin);
        b = std::fmax(b, boxMax);
    };
    if (box.periodic[0])
        widen(lo.x, hi.x, box.min.x, box.max.x);
    if (box.periodic[1])
        widen(lo.y, hi.y, box.min.y, box.max.y);
    if (box.periodic[2])
        widen(lo.z, hi.z, box.min.z, box.max.z);
}

bool ParticleFlow::apply(World& world, Real dt)
{
    bool removed = false;
    if (std::vector<std::uint32_t> doomed = takeAtOutlets(world, world.particles.size()); !doomed.empty())
    {
        if (retiresWithoutRebuild(world))
            retireParticles(world, doomed); // (out of the store at the next rebuild)
        else
        {
            removeParticles(world, std::move(doomed));
            rebuildAfterParticleChange(world);
        }
        removed = true;
    }
    if (!insertionDue(world.time, dt))
        return removed;
    const std::size_t before = world.particles.size();
    insertNew(world, dt);
    if (world.particles.size() == before)
        return removed;
    if (insertsWithoutRebuild(world, before, index.largestRadius()))
        addInsertedParticles(world, before, index);
    else
        rebuildAfterParticleChange(world);
    return true;
}

} // namespace veridem::dem
