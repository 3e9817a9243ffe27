#include "dem/particle_index.h"

#include "dem/cell_grid.h"

#include <algorithm>
#include <cmath>

namespace veridem::dem
{

bool ParticleIndex::validFor(const NeighborList& list, std::size_t particleCount, Real newRadius,
                             Real extra) const
{
    return listBuild_ == list.rebuildCount() && next_.size() == particleCount && newRadius <= radius_ &&
           extra <= extra_;
}

void ParticleIndex::coordinates(const Vec3& x, std::size_t* c) const
{
    // (Beyond the grid or not finite: its nearest cell along that axis, cell_grid.h.)
    c[0] = cellCoordinate(x.x, origin_.x, cell_, n_[0]);
    c[1] = cellCoordinate(x.y, origin_.y, cell_, n_[1]);
    c[2] = cellCoordinate(x.z, origin_.z, cell_, n_[2]);
}

void ParticleIndex::build(const ParticleStore& particles, const NeighborList& list, Real newRadius,
                          Real extra, const Vec3& coverLo, const Vec3& coverHi)
{
    ++builds_;
    const std::size_t n = particles.size();
    const bool built = list.builtFor(n);
    const Vec3* const reference = built ? list.motionReference(n).built : particles.position.data();
    radius_ = newRadius;
    for (const Real r : particles.radius)
        radius_ = std::fmax(radius_, r);
    extra_ = extra;
    cell_ = std::fmax(2 * radius_ + extra + 0.5 * list.skin, 1e-12);
    // The grid's box: the cover box widened by a cell on each side (every query point lies in the
    // cover box, so only particles there can be found), or without one the particles' box.
    const bool cover = coverLo.x <= coverHi.x && coverLo.y <= coverHi.y && coverLo.z <= coverHi.z;
    Vec3 lo = n ? reference[0] : Vec3{}, hi = lo;
    if (!cover)
        for (std::size_t i = 0; i < n; ++i)
        {
            const Vec3& x = reference[i];
            lo = Vec3{std::fmin(lo.x, x.x), std::fmin(lo.y, x.y), std::fmin(lo.z, x.z)};
            hi = Vec3{std::fmax(hi.x, x.x), std::fmax(hi.y, x.y), std::fmax(hi.z, x.z)};
        }
    // At most 4 cells a particle plus 2^16, and 2^22 in all (a far stray particle must not make
    // billions of empty cells); counts in floating point, so a non-finite box gives one cell.
    const Real maxCells = std::fmin(4.0 * Real(n) + 65536, Real(1 << 22));
    for (;;)
    {
        if (cover)
        {
            lo = coverLo - Vec3{cell_, cell_, cell_};
            hi = coverHi + Vec3{cell_, cell_, cell_};
        }
        const Real extent[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
        const bool finite = std::isfinite(extent[0]) && std::isfinite(extent[1]) && std::isfinite(extent[2]);
        for (int k = 0; k < 3; ++k)
            n_[k] =
                finite ? static_cast<std::size_t>(std::fmin(std::floor(extent[k] / cell_) + 1, maxCells)) : 1;
        if (Real(n_[0]) * Real(n_[1]) * Real(n_[2]) <= maxCells)
            break;
        cell_ *= 1.5;
    }
    origin_ = lo;
    head_.assign(n_[0] * n_[1] * n_[2], kEnd);
    next_.assign(n, kEnd);
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& x = reference[i];
        if (cover &&
            !(x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z))
            continue; // (too far from every query to be found)
        std::size_t c[3];
        coordinates(x, c);
        std::uint32_t& head = head_[(c[2] * n_[1] + c[1]) * n_[0] + c[0]];
        next_[i] = head;
        head = static_cast<std::uint32_t>(i);
    }
    listBuild_ = built ? list.rebuildCount() : ~std::size_t{0};
}

void ParticleIndex::append(std::uint32_t i, const Vec3& x)
{
    std::size_t c[3];
    coordinates(x, c);
    std::uint32_t& head = head_[(c[2] * n_[1] + c[1]) * n_[0] + c[0]];
    next_.push_back(head);
    head = i;
}

} // namespace veridem::dem
