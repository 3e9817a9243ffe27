#include "io/domain_keys.h"

#include <cmath>
#include <sstream>

namespace veridem::io
{

namespace
{

/// Fails at `key` of `table` with the parts streamed into one message (streamed rather than
/// concatenated: GCC 12's LTO warns falsely on std::string + literal chains here).
template <class... Parts>
[[noreturn]] void failWith(const TableReader& table, std::string_view key, const Parts&... parts)
{
    std::ostringstream s;
    (s << ... << parts);
    table.fail(key, s.str());
}

} // namespace

std::optional<TableReader> readDomain(TableReader& top, dem::World& world,
                                      const MeasurementOptions& measurements)
{
    auto domain = top.table("domain");
    if (!domain)
        return std::nullopt;
    dem::PeriodicDomain d;
    d.min = domain->requiredVec3("min");
    d.max = domain->requiredVec3("max");
    const std::vector<bool> periodic = domain->booleans("periodic");
    domain->finish();
    if (!periodic.empty() && periodic.size() != 3)
        domain->fail("periodic", "must hold three booleans, one per axis x, y, z (e.g. [true, true, false])");
    for (std::size_t a = 0; a < periodic.size(); ++a)
        d.periodic[a] = periodic[a];
    const Vec3 edge = d.length();
    const Real edges[3] = {edge.x, edge.y, edge.z};
    for (int a = 0; a < 3; ++a)
        if (d.periodic[static_cast<std::size_t>(a)] && !(edges[a] > 0 && std::isfinite(edges[a])))
            failWith(*domain, "max", "must exceed 'min' along the periodic axis ", "xyz"[a], " [m]");
    if (!d.any())
        return std::nullopt; // a box without periodic axes bounds nothing (yet)

    const auto crossing = [&](const Vec3& n)
    {
        const Real c[3] = {n.x, n.y, n.z};
        for (int a = 0; a < 3; ++a)
            if (d.periodic[static_cast<std::size_t>(a)] && std::fabs(c[a]) > 1e-12)
                return a;
        return -1;
    };
    for (const dem::Wall& w : world.walls)
    {
        const auto* plane = std::get_if<dem::PlaneShape>(&w.shape);
        if (!plane)
            failWith(*domain, "periodic", "wall '", w.name,
                     "' is not a plane: only infinite planes parallel to the periodic axes may be used "
                     "with periodic boundaries");
        if (std::isfinite(plane->diskRadius))
            failWith(*domain, "periodic", "wall '", w.name,
                     "' is a finite disk: it would end at a periodic face");
        if (const int a = crossing(plane->normal); a >= 0)
            failWith(*domain, "periodic", "wall '", w.name, "' crosses the periodic axis ", "xyz"[a],
                     " (its normal must be perpendicular to every periodic axis)");
    }
    const auto& p = world.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Vec3 x = p.position[i], wrapped = dem::wrapPosition(d, x);
        if (wrapped == x)
            continue;
        const char axis = wrapped.x != x.x ? 'x' : wrapped.y != x.y ? 'y' : 'z';
        failWith(*domain, "min", "and 'max' leave sphere ", i, " at (", x.x, ", ", x.y, ", ", x.z,
                 ") m outside the box [min, max) along the periodic axis ", axis,
                 " (particles are not wrapped at the start: move it inside)");
    }
    if (measurements.energy || measurements.contacts || measurements.region)
        failWith(*domain, "periodic", "[output] '",
                 measurements.energy     ? "energy"
                 : measurements.contacts ? "contacts"
                                         : "region_min",
                 "' does not see the pairs that touch through a periodic face yet: remove it or the "
                 "periodic axes");
    world.domain = d;
    return domain;
}

} // namespace veridem::io
