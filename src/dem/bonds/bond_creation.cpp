// Forming the bonds (bond_set.h, createBonds): the selected particles binned in cells at least as
// wide as the largest bond distance, each pair within reach found once, in index order.
#include "dem/bonds/bond_set.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace veridem::dem
{

namespace
{

struct Binned
{
    std::int64_t cx, cy, cz;
    std::uint32_t index;
    bool operator<(const Binned& o) const
    {
        return std::tie(cx, cy, cz, index) < std::tie(o.cx, o.cy, o.cz, o.index);
    }
};

} // namespace

std::size_t createBonds(BondSet& set, const ParticleStore& p, std::size_t owned)
{
    set.created = true;
    const auto selected = [&](std::size_t i)
    {
        return !p.retired(i) && p.material[i] < set.materialSelected.size() &&
               set.materialSelected[p.material[i]] != 0;
    };
    Real maxRadius = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (selected(i))
            maxRadius = std::fmax(maxRadius, p.radius[i]);
    if (maxRadius == 0)
        return 0;
    const Real cell = 2 * maxRadius + set.gapTolerance;
    std::vector<Binned> bins;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (selected(i))
            bins.push_back({static_cast<std::int64_t>(std::floor(p.position[i].x / cell)),
                            static_cast<std::int64_t>(std::floor(p.position[i].y / cell)),
                            static_cast<std::int64_t>(std::floor(p.position[i].z / cell)),
                            static_cast<std::uint32_t>(i)});
    std::sort(bins.begin(), bins.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> found;
    for (const Binned& s : bins)
        for (std::int64_t dz = -1; dz <= 1; ++dz)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dx = -1; dx <= 1; ++dx)
                {
                    const Binned lo{s.cx + dx, s.cy + dy, s.cz + dz, 0};
                    for (auto it = std::lower_bound(bins.begin(), bins.end(), lo);
                         it != bins.end() && it->cx == lo.cx && it->cy == lo.cy && it->cz == lo.cz; ++it)
                    {
                        const std::uint32_t i = s.index, j = it->index;
                        if (j <= i || (i >= owned && j >= owned)) // (a pair of ghosts: not ours)
                            continue;
                        const Real reach = p.radius[i] + p.radius[j] + set.gapTolerance;
                        if (lengthSquared(p.position[j] - p.position[i]) <= reach * reach)
                            found.emplace_back(i, j);
                    }
                }
    std::sort(found.begin(), found.end());
    // (with ghosts, on MPI ranks, two ranks form one bond: each from its lower-id partner, so that
    // both hold it the same way round and advance it to the same bits)
    const bool byId = owned < p.size();
    for (auto [i, j] : found)
    {
        if (byId && p.id[j] < p.id[i])
            std::swap(i, j);
        set.bonds.push_back({p.id[i], p.id[j], i, j, formBond(p.position[i], p.position[j])});
        set.formed += countsBond(set.bonds.back(), i, j, owned);
    }
    return found.size();
}

} // namespace veridem::dem
