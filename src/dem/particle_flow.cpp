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

/// The particles near one inserter's region on a uniform grid of cells, each at least as wide as
/// the largest sum of two radii (existing or new), so a sphere can only overlap spheres of its own and the 26
/// surrounding cells. Inserted spheres are added as they come.
class InsertionGrid
{
  public:
    InsertionGrid(const World& world, const FlowRegion& region, Real newRadius)
    {
        const ParticleStore& p = world.particles;
        Real largest = 0;
        for (const Real r : p.radius)
            largest = std::max(largest, r);
        region.bounds(lo_, hi_);
        const Real margin = largest + newRadius;
        lo_ = lo_ - Vec3{margin, margin, margin};
        hi_ = hi_ + Vec3{margin, margin, margin};
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const Vec3& x = p.position[i];
            if (x.x >= lo_.x && x.x <= hi_.x && x.y >= lo_.y && x.y <= hi_.y && x.z >= lo_.z && x.z <= hi_.z)
            {
                position_.push_back(x);
                radius_.push_back(p.radius[i]);
            }
        }
        cell_ = std::max(2 * std::max(largest, newRadius), 1e-12); // (new spheres are added too)
        const Real cellsWanted = 4.0 * Real(position_.size()) + 4096;
        while (count(hi_.x - lo_.x) * count(hi_.y - lo_.y) * count(hi_.z - lo_.z) > cellsWanted)
            cell_ *= 1.5;
        n_[0] = static_cast<std::size_t>(count(hi_.x - lo_.x));
        n_[1] = static_cast<std::size_t>(count(hi_.y - lo_.y));
        n_[2] = static_cast<std::size_t>(count(hi_.z - lo_.z));
        cells_.resize(n_[0] * n_[1] * n_[2]);
        for (std::size_t k = 0; k < position_.size(); ++k)
            cells_[cellOf(position_[k])].push_back(static_cast<std::uint32_t>(k));
    }

    /// True if a sphere (x, r) [m] overlaps none of the grid's spheres.
    bool free(const Vec3& x, Real r) const
    {
        std::size_t c[3];
        coordinates(x, c);
        for (std::size_t z = c[2] ? c[2] - 1 : 0; z <= std::min(c[2] + 1, n_[2] - 1); ++z)
            for (std::size_t y = c[1] ? c[1] - 1 : 0; y <= std::min(c[1] + 1, n_[1] - 1); ++y)
                for (std::size_t xi = c[0] ? c[0] - 1 : 0; xi <= std::min(c[0] + 1, n_[0] - 1); ++xi)
                    for (const std::uint32_t k : cells_[(z * n_[1] + y) * n_[0] + xi])
                    {
                        const Real reach = r + radius_[k];
                        if (lengthSquared(x - position_[k]) < reach * reach)
                            return false;
                    }
        return true;
    }
    void add(const Vec3& x, Real r)
    {
        position_.push_back(x);
        radius_.push_back(r);
        cells_[cellOf(x)].push_back(static_cast<std::uint32_t>(position_.size() - 1));
    }

  private:
    Real count(Real extent) const { return std::floor(extent / cell_) + 1; }
    void coordinates(const Vec3& x, std::size_t* c) const
    {
        const Real v[3] = {x.x - lo_.x, x.y - lo_.y, x.z - lo_.z};
        for (int k = 0; k < 3; ++k)
        {
            const Real q = v[k] / cell_;
            c[k] = q >= 0 && q < Real(n_[k]) ? static_cast<std::size_t>(q) : q >= Real(n_[k]) ? n_[k] - 1 : 0;
        }
    }
    std::size_t cellOf(const Vec3& x) const
    {
        std::size_t c[3];
        coordinates(x, c);
        return (c[2] * n_[1] + c[1]) * n_[0] + c[0];
    }

    Vec3 lo_, hi_;
    Real cell_ = 0;
    std::size_t n_[3] = {1, 1, 1};
    std::vector<Vec3> position_;
    std::vector<Real> radius_;
    std::vector<std::vector<std::uint32_t>> cells_;
};

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

/// Inserts the particles `in` owes at time t; returns how many.
std::size_t insert(World& world, Inserter& in, std::uint32_t& nextId, Real t, Real dt)
{
    if (!behind(in, t, dt))
        return 0;
    ParticleStore& p = world.particles;
    InsertionGrid grid(world, in.region, in.radius.largest());
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
            placed = grid.free(x, r);
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
        grid.add(x, r);
        ++in.inserted;
        in.insertedMass += p.mass.back();
        ++added;
    }
    return added;
}

} // namespace

bool ParticleFlow::apply(World& world, Real dt)
{
    const Real t = world.time;
    bool changed = false;
    if (!outlets.empty())
    {
        std::vector<std::uint32_t> doomed;
        const ParticleStore& p = world.particles;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            if (p.fixed[i])
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
        if (!doomed.empty())
        {
            removeParticles(world, std::move(doomed));
            changed = true;
        }
    }
    for (Inserter& in : inserters)
        changed = insert(world, in, nextId, t, dt) > 0 || changed;
    if (changed)
        rebuildAfterParticleChange(world);
    return changed;
}

} // namespace veridem::dem
