#include "io/plausibility.h"

#include "core/error.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <variant>

namespace veridem::io
{

namespace
{

std::string number(double x)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
}

std::string point(const Vec3& x)
{
    return "(" + number(x.x) + ", " + number(x.y) + ", " + number(x.z) + ")";
}

/// An axis-aligned box [m], empty until a point is added.
struct Box
{
    Vec3 lo{std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::infinity(),
            std::numeric_limits<Real>::infinity()};
    Vec3 hi = -lo;
    void add(const Vec3& x, Real r = 0)
    {
        lo = {std::fmin(lo.x, x.x - r), std::fmin(lo.y, x.y - r), std::fmin(lo.z, x.z - r)};
        hi = {std::fmax(hi.x, x.x + r), std::fmax(hi.y, x.y + r), std::fmax(hi.z, x.z + r)};
    }
    bool empty() const { return !(lo.x <= hi.x); }
    Real diagonal() const { return empty() ? 0 : length(hi - lo); }
};

/// The box around a finite wall at t = 0; false for an infinite plane.
bool finiteWallBox(const dem::Wall& wall, Box& box)
{
    if (const auto* plane = std::get_if<dem::PlaneShape>(&wall.shape))
    {
        if (!std::isfinite(plane->diskRadius))
            return false;
        box.add(plane->point, plane->diskRadius);
    }
    else if (const auto* dish = std::get_if<dem::DishShape>(&wall.shape))
        box.add(dish->lowestPoint + Vec3{0, 0, dish->sphereRadius}, dish->sphereRadius);
    else if (const auto* cylinder = std::get_if<dem::CylinderShape>(&wall.shape))
    {
        box.add(cylinder->point, cylinder->radius);
        box.add(cylinder->point + cylinder->length * cylinder->axis, cylinder->radius);
    }
    else if (const auto* mesh = std::get_if<dem::MeshShape>(&wall.shape))
    {
        box.add(mesh->mesh->lower);
        box.add(mesh->mesh->upper);
    }
    return true;
}

} // namespace

std::vector<std::string> plausibilityWarnings(const DemScene& scene, const std::string& file)
{
    std::vector<std::string> warnings;
    const auto warn = [&](const std::string& what) { warnings.push_back(file + ": " + what); };
    const dem::World& world = scene.world;
    const dem::ParticleStore& p = world.particles;

    // Materials.
    for (const dem::Material& m : world.materials)
    {
        if (m.density < kSmallestDensity)
            warn("[[material]] '" + m.name + "': density = " + number(m.density) + " kg/m^3 is below " +
                 number(kSmallestDensity) + " kg/m^3: densities are in kg/m^3 (2.5 g/cm^3 is 2500)");
        if (dem::isHertzian(m.normalModel) && m.youngsModulus < kSmallestModulus)
            warn("[[material]] '" + m.name + "': youngs_modulus = " + number(m.youngsModulus) +
                 " Pa is below " + number(kSmallestModulus) + " Pa: moduli are in pascals (5 MPa is 5e6)");
    }

    // Radii: the scene's spheres and what the inserters can draw.
    Box cloud;
    Real largest = 0;
    std::size_t large = 0, small = 0, firstLarge = 0, firstSmall = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Real r = p.radius[i];
        cloud.add(p.position[i], r);
        largest = std::fmax(largest, r);
        if (r > kLargestRadius && large++ == 0)
            firstLarge = i;
        if (r < kSmallestRadius && small++ == 0)
            firstSmall = i;
    }
    if (large)
        warn(std::to_string(large) + " sphere(s) with a radius above " + number(kLargestRadius) +
             " m, e.g. sphere " + std::to_string(p.id[firstLarge]) +
             " (radius = " + number(p.radius[firstLarge]) +
             " m): implausible for a granular scene; radii are in metres (1 mm is 0.001)");
    if (small)
        warn(std::to_string(small) + " sphere(s) with a radius below " + number(kSmallestRadius) +
             " m, e.g. sphere " + std::to_string(p.id[firstSmall]) +
             " (radius = " + number(p.radius[firstSmall]) + " m): radii are in metres (1 mm is 0.001)");
    for (const dem::Inserter& in : scene.flow.inserters)
    {
        const Real r = in.radius.largest();
        largest = std::fmax(largest, r);
        Vec3 lo, hi;
        in.region.bounds(lo, hi);
        cloud.add(lo);
        cloud.add(hi);
        if (r > kLargestRadius)
            warn("[[insert]] '" + in.name + "': radius up to " + number(r) +
                 " m: implausible for a granular scene; radii are in metres (1 mm is 0.001)");
        const dem::PeriodicDomain& d = world.domain;
        for (int a = 0; a < 3; ++a)
        {
            const auto axis = static_cast<std::size_t>(a);
            const Real l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
            const Real dl[3] = {d.min.x, d.min.y, d.min.z}, dh[3] = {d.max.x, d.max.y, d.max.z};
            if (d.periodic[axis] && (l[a] < dl[a] || h[a] > dh[a]))
            {
                warn("[[insert]] '" + in.name + "': its region " + point(lo) + " to " + point(hi) +
                     " m reaches outside the periodic box along " + "xyz"[a] + " ([domain] min " +
                     number(dl[a]) + " to max " + number(dh[a]) +
                     " m): its particles are wrapped into the box");
                break;
            }
        }
    }

    // Walls: meshes against the rest of the scene; spheres behind a plane or outside every wall.
    Box finite;
    bool infinitePlane = false;
    for (const dem::Wall& wall : world.walls)
        infinitePlane |= !finiteWallBox(wall, finite);
    for (const dem::Wall& wall : world.walls)
    {
        const auto* mesh = std::get_if<dem::MeshShape>(&wall.shape);
        if (!mesh)
            continue;
        Box others = cloud;
        if (largest > 0)
            others.add((cloud.lo + cloud.hi) * 0.5, 5 * largest); // at least 10 largest radii
        for (const dem::Wall& other : world.walls)
            if (&other != &wall && !std::holds_alternative<dem::MeshShape>(other.shape))
                finiteWallBox(other, others);
        const Real extent = mesh->mesh->size, reference = others.diagonal();
        if (reference > 0 && (extent > kScaleRatio * reference || extent * kScaleRatio < reference))
            warn("[[wall]] '" + wall.name + "': the mesh spans " + number(extent) + " m, " +
                 number(extent / reference) + " times the rest of the scene (" + number(reference) +
                 " m): is the file in millimetres? `scale = 0.001` converts it");
    }
    for (const dem::Wall& wall : world.walls)
    {
        const auto* plane = std::get_if<dem::PlaneShape>(&wall.shape);
        if (!plane || std::isfinite(plane->diskRadius))
            continue;
        std::size_t behind = 0, first = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
            if (dot(p.position[i] - plane->point, plane->normal) < -p.radius[i] && behind++ == 0)
                first = i;
        if (behind)
            warn(std::to_string(behind) + " sphere(s) lie wholly behind the plane [[wall]] '" + wall.name +
                 "', e.g. sphere " + std::to_string(p.id[first]) + " at " + point(p.position[first]) +
                 " m, " + number(-dot(p.position[first] - plane->point, plane->normal)) +
                 " m on its solid side: a plane is one-sided, they never touch it ('normal' points to the "
                 "particles' side)");
    }
    if (!world.walls.empty() && !infinitePlane && !finite.empty())
    {
        // Far outside: farther from the box around the walls than its diagonal (spheres falling
        // into an open container from above are near it).
        const Real margin = finite.diagonal();
        std::size_t outside = 0, first = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const Vec3& x = p.position[i];
            const Real reach = p.radius[i] + margin;
            if ((x.x + reach < finite.lo.x || x.x - reach > finite.hi.x || x.y + reach < finite.lo.y ||
                 x.y - reach > finite.hi.y || x.z + reach < finite.lo.z || x.z - reach > finite.hi.z) &&
                outside++ == 0)
                first = i;
        }
        if (outside)
            warn(std::to_string(outside) + " sphere(s) lie far outside every wall (the walls span " +
                 point(finite.lo) + " to " + point(finite.hi) + " m), e.g. sphere " +
                 std::to_string(p.id[first]) + " at " + point(p.position[first]) +
                 " m: check its units and the walls' positions");
    }
    return warnings;
}

void reportPlausibility(const DemScene& scene, const std::string& file, bool strict, bool speak)
{
    const std::vector<std::string> warnings = plausibilityWarnings(scene, file);
    if (strict && !warnings.empty())
        throw InputError(
            warnings.front() + " (an error with --strict" +
            (warnings.size() > 1 ? ", and " + std::to_string(warnings.size() - 1) + " more" : "") + ")");
    if (speak)
        for (const std::string& w : warnings)
            std::fprintf(stderr, "veridem: warning: %s\n", w.c_str());
}

} // namespace veridem::io
