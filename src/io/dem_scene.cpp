#include "io/dem_scene.h"

#include "core/constants.h"
#include "core/error.h"
#include "dem/spatial_sort.h"
#include "dem/walls/wall.h"
#include "io/bond_keys.h"
#include "io/domain_keys.h"
#include "io/material_keys.h"
#include "io/particle_file.h"
#include "io/particle_flow_keys.h"
#include "io/scene_limits.h"
#include "io/surface_mesh_reader.h"
#include "io/toml_reader.h"
#include "io/wall_keys.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <memory>
#include <sstream>

namespace veridem::io
{

namespace
{

/// Moves a sphere onto a wall at its resting overlap and, if asked, sets the no-slip spin.
void placeOnWall(dem::World& world, std::uint32_t i, const dem::Wall& wall, bool noSlip, const TableReader& t)
{
    auto& p = world.particles;
    const Real r = p.radius[i];
    Vec3 normal;
    if (std::holds_alternative<dem::CylinderShape>(wall.shape))
        t.fail("on_wall", "supports plane, turntable and dish walls, not a cylinder");
    if (const auto* plane = std::get_if<dem::PlaneShape>(&wall.shape))
    {
        normal = plane->normal;
        const Real distance = dot(p.position[i] - plane->point, normal);
        p.position[i] -= distance * normal; // onto the surface
    }
    else if (std::holds_alternative<dem::MeshShape>(wall.shape))
        t.fail("on_wall", "cannot place a sphere on a mesh wall (give its position)");
    else
    {
        const auto& dish = std::get<dem::DishShape>(wall.shape);
        const Vec3 centre = dish.lowestPoint + Vec3{0, 0, dish.sphereRadius};
        Vec3 out = p.position[i] - centre;
        if (!(length(out) > 0) || out.z > 0)
            t.fail("on_wall", "the sphere's position must be below the dish centre");
        out = out / length(out);
        p.position[i] = centre + dish.sphereRadius * out;
        normal = -out;
    }
    // Resting overlap under the normal part of gravity (linear: m g_n / kn; Hertz: solved).
    const dem::PairParams params =
        dem::mixMaterials(world.materials[p.material[i]], world.materials[wall.material]);
    const Real load = std::fmax(-dot(world.gravity, normal), 0.0) * p.mass[i];
    Real overlap = 0;
    if (params.normalModel == dem::NormalModel::Linear)
        overlap = load / params.kn;
    else
        overlap = std::pow(3 * load / (4 * params.effectiveModulus * std::sqrt(r)), 2.0 / 3.0);
    p.position[i] += (r - overlap) * normal;
    if (noSlip)
    {
        const Vec3 contactPoint = p.position[i] - r * normal;
        const Vec3 slip = p.velocity[i] - dem::wallSurfaceVelocity(wall, contactPoint);
        const Vec3 inPlaneSlip = slip - dot(slip, normal) * normal;
        p.angularVelocity[i] = cross(normal, inPlaneSlip) / r; // no spin about the normal
    }
}

/// A box filled with spheres on a cubic lattice (optionally jittered, deterministic seed).
struct Lattice
{
    std::uint32_t material = 0;
    Real radius = 0, spacing = 0, jitter = 0;
    Vec3 lo{}, velocity{};
    long nx = 0, ny = 0, nz = 0;
    bool fixed = false;
};

/// Reads a [[lattice]] table and counts its spheres (in floating point, checked against
/// maxSphereCount() before any conversion to an integer); allocates nothing.
Lattice readLattice(TableReader& t, const dem::World& world)
{
    Lattice l;
    l.material = world.materialId(t.requiredString("material"));
    l.radius = t.requiredNumber("radius");
    t.requirePositive("radius", l.radius, "m");
    const Vec3 lo = t.requiredVec3("min"), hi = t.requiredVec3("max");
    l.spacing = t.number("spacing", 2.2 * l.radius);
    if (!(l.spacing >= 2 * l.radius) || !std::isfinite(l.spacing))
        t.fail("spacing", "must be >= 2 radius so the spheres do not overlap");
    l.jitter = t.number("jitter", 0.0);
    if (!(l.jitter >= 0 && l.jitter <= 0.5 * (l.spacing - 2 * l.radius)))
        t.fail("jitter", "must be in [0, (spacing - 2 radius)/2] m so the spheres do not overlap");
    l.velocity = t.vec3("velocity", {});
    l.fixed = t.boolean("fixed", false);
    t.finish();
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
        t.fail("max", "must be above 'min' in x, y and z");
    auto count = [&](Real a, Real b) { return std::floor((b - a - 2 * l.radius) / l.spacing) + 1; };
    const Real nx = count(lo.x, hi.x), ny = count(lo.y, hi.y), nz = count(lo.z, hi.z);
    if (!(nx >= 1 && ny >= 1 && nz >= 1))
        t.fail("max", "the box is smaller than one sphere");
    if (!(nx * ny * nz <= maxSphereCount()))
    {
        std::ostringstream s;
        s << "with 'min', 'max' and 'spacing' would create " << std::setprecision(3) << nx * ny * nz
          << " spheres (at most " << maxSphereCount() << " in a scene)";
        t.fail("spacing", s.str());
    }
    l.lo = lo;
    l.nx = static_cast<long>(nx);
    l.ny = static_cast<long>(ny);
    l.nz = static_cast<long>(nz);
    return l;
}

double sphereCount(const Lattice& l)
{
    return double(l.nx) * double(l.ny) * double(l.nz);
}

void fillLattice(const Lattice& l, dem::World& world)
{
    std::uint64_t state = 0x9E3779B97F4A7C15ull; // splitmix64: the same lattice on every machine
    auto uniform = [&]()
    {
        state += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return double(z >> 11) * 0x1.0p-53 * 2.0 - 1.0;
    };
    const Real density = world.materials[l.material].density;
    for (long k = 0; k < l.nz; ++k)
        for (long j = 0; j < l.ny; ++j)
            for (long i = 0; i < l.nx; ++i)
            {
                Vec3 x{l.lo.x + l.radius + Real(i) * l.spacing, l.lo.y + l.radius + Real(j) * l.spacing,
                       l.lo.z + l.radius + Real(k) * l.spacing};
                x += l.jitter * Vec3{uniform(), uniform(), uniform()};
                world.particles.add(x, l.velocity, {}, l.radius, density, l.material);
                world.particles.fixed.back() = l.fixed;
            }
}

void checkInitialOverlaps(dem::World& world, Real tolerance)
{
    dem::prepare(world);
    const auto& p = world.particles;
    const auto& list = world.neighbors;
    for (std::size_t k = 0; k < list.size(); ++k)
    {
        const auto i = list.first[k], j = list.second[k];
        const Real overlap = p.radius[i] + p.radius[j] - length(p.position[i] - p.position[j]);
        if (overlap > tolerance * std::min(p.radius[i], p.radius[j]))
        {
            std::ostringstream s;
            s << "spheres " << i << " and " << j << " overlap by " << overlap << " m initially (more than "
              << tolerance << " of the smaller radius; see [simulation] initial_overlap_tolerance)";
            throw InputError(s.str());
        }
    }
    const auto& periodic = world.periodicPairs; // pairs through a periodic face
    for (std::size_t k = 0; k < periodic.size(); ++k)
    {
        const auto i = periodic.first[k], j = periodic.second[k];
        const Real overlap =
            p.radius[i] + p.radius[j] - length(p.position[i] - p.position[j] - periodic.shift[k]);
        if (overlap > tolerance * std::min(p.radius[i], p.radius[j]))
        {
            std::ostringstream s;
            s << "spheres " << i << " and " << j << " overlap by " << overlap
              << " m initially across a periodic face (more than " << tolerance
              << " of the smaller radius; see [simulation] initial_overlap_tolerance)";
            throw InputError(s.str());
        }
    }
    for (std::size_t i = 0; i < p.size(); ++i)
        for (const auto& wall : world.walls)
        {
            const dem::WallGap gap = dem::wallGap(wall, p.position[i], p.radius[i]);
            if (gap.touching && gap.overlap > tolerance * p.radius[i] + 1e-12)
            {
                std::ostringstream s;
                s << "sphere " << i << " overlaps wall '" << wall.name << "' by " << gap.overlap
                  << " m initially (more than " << tolerance << " of its radius; use on_wall to place it)";
                throw InputError(s.str());
            }
        }
}

} // namespace

DemScene readDemScene(const toml::table& root, const std::string& file)
{
    TableReader top(root, "scene", file);
    DemScene scene;
    dem::World& world = scene.world;

    auto simulation = top.table("simulation");
    if (!simulation)
        top.fail("simulation", "is missing: every scene needs a [simulation] table with dt and duration");
    simulation->choice("type", "dem", {"dem", "fdem2d"});
    refuseRenamedKeys(*simulation);
    scene.dt = simulation->requiredNumber("dt");
    simulation->requirePositive("dt", scene.dt, "s");
    scene.duration = simulation->requiredNumber("duration");
    simulation->requirePositive("duration", scene.duration, "s");
    scene.outputInterval = simulation->number("output_interval", scene.duration / 100);
    simulation->requirePositive("output_interval", scene.outputInterval, "s");
    if (auto interval = simulation->optionalNumber("checkpoint_interval"))
    {
        simulation->requirePositive("checkpoint_interval", *interval, "s");
        scene.checkpointInterval = *interval;
    }
    world.gravity = simulation->vec3("gravity", {0, 0, -kStandardGravity});
    if (auto skin = simulation->optionalNumber("skin"))
    {
        simulation->requirePositive("skin", *skin, "m");
        world.neighbors.skin = *skin;
    }
    scene.maxOverlapFraction = simulation->number("max_overlap_fraction", 0.5);
    simulation->requirePositive("max_overlap_fraction", scene.maxOverlapFraction, "");
    const Real overlapTolerance = simulation->number("initial_overlap_tolerance", 0.01);
    simulation->requireNonNegative("initial_overlap_tolerance", overlapTolerance, "");
    scene.characteristicSpeed = simulation->number("characteristic_speed", 0.0);
    simulation->requireNonNegative("characteristic_speed", scene.characteristicSpeed, "m/s");
    scene.writeVtk = simulation->boolean("vtk", true);
    const std::string vtkFormat = simulation->choice("vtk_format", "auto", {"auto", "ascii", "binary"});
    const Real flowInterval = simulation->number("flow_interval", 100 * scene.dt);
    const bool sortParticles = simulation->boolean("sort_particles", false);
    simulation->requirePositive("flow_interval", flowInterval, "s");
    simulation->finish();
    scene.measurements = readMeasurementOptions(top, scene.output);

    auto materials = top.arrayOfTables("material");
    if (materials.empty())
        top.fail("material", "is missing: define at least one [[material]]");
    for (auto& m : materials)
        world.addMaterial(readMaterial(m));
    if (scene.measurements.energy)
        for (const dem::Material& m : world.materials)
            if (m.normalModel == dem::NormalModel::Thornton)
                top.fail("material",
                         "'" + m.name +
                             "': the \"thornton\" model cannot be combined with [output] energy = "
                             "true yet (the ledger has no plastic work term)");
    scene.measurements.zones = readZones(top, world);

    auto pairs = top.arrayOfTables("pair");
    for (auto& w : top.arrayOfTables("wall"))
    {
        world.walls.push_back(readWall(w, world));
        if (std::holds_alternative<dem::CylinderShape>(world.walls.back().shape) && w.boolean("caps", false))
            for (dem::Wall& cap : cylinderCaps(world.walls.back()))
                world.walls.push_back(std::move(cap));
    }

    Real maxSpeed = 0;
    for (auto& s : top.arrayOfTables("sphere"))
    {
        const std::uint32_t material = world.materialId(s.requiredString("material"));
        const Real radius = s.requiredNumber("radius");
        s.requirePositive("radius", radius, "m");
        const Vec3 x = s.requiredVec3("position");
        const Vec3 v = s.vec3("velocity", {});
        const Vec3 w = s.vec3("angular_velocity", {});
        const std::string onWall = s.string("on_wall", "");
        const bool noSlip = s.boolean("no_slip", false);
        const bool fixed = s.boolean("fixed", false);
        s.finish();
        const std::uint32_t i =
            world.particles.add(x, v, w, radius, world.materials[material].density, material);
        world.particles.fixed.back() = fixed;
        maxSpeed = std::fmax(maxSpeed, length(v));
        if (!onWall.empty())
        {
            const dem::Wall* wall = nullptr;
            for (const auto& candidate : world.walls)
                if (candidate.name == onWall)
                    wall = &candidate;
            if (!wall)
                s.fail("on_wall", "names no [[wall]] (walls are matched by name)");
            placeOnWall(world, i, *wall, noSlip, s);
        }
        else if (noSlip)
            s.fail("no_slip", "needs on_wall = \"<wall name>\" to know which surface to roll on");
    }
    // Count before allocating: the lattices are read (not filled) first, the particle files are
    // read against the budget left; the order of the spheres stays [[sphere]], files, lattices.
    std::vector<Lattice> lattices;
    double latticeSpheres = 0;
    for (auto& l : top.arrayOfTables("lattice"))
    {
        lattices.push_back(readLattice(l, world));
        latticeSpheres += sphereCount(lattices.back());
    }
    const double planned = double(world.particles.size()) + latticeSpheres;
    checkSphereCount(planned, "the [[sphere]] and [[lattice]] tables", file);
    std::vector<GivenIds> givenIds; // (files with an id column)
    for (auto& f : top.arrayOfTables("particles"))
        readParticleFile(f, world, file, latticeSpheres, givenIds);
    for (const Lattice& l : lattices)
        fillLattice(l, world);
    numberParticles(world.particles, givenIds);
    const std::optional<TableReader> domain = readDomain(top, world, scene.measurements);
    scene.flow =
        readParticleFlow(top, world, std::max<std::uint64_t>(1, std::llround(flowInterval / scene.dt)));
    readBonds(top, world, scene.dt, !scene.flow.inserters.empty(), scene.measurements.energy); // [bonds]
    top.finish();

    if (world.particles.size() == 0 && scene.flow.inserters.empty())
        throw InputError(
            file + ": the scene has no particles ([[sphere]], [[particles]], [[lattice]] or [[insert]])");
    startParticleFlow(scene.flow, world, scene.measurements.energy, file);
    checkSphereRanges(world, scene.dt, file);
    const double expected = expectedParticles(scene.flow, world, scene.duration, file);
    scene.vtkFormat = chooseVtkFormat(vtkFormat, static_cast<std::size_t>(std::fmin(expected, 1e12)));
    scene.output.dt = scene.dt;
    scene.output.vtk = scene.writeVtk;
    scene.output.vtkFormat = scene.vtkFormat;
    if (scene.characteristicSpeed == 0)
        scene.characteristicSpeed = std::fmax(1.0, maxSpeed);
    // `sort_particles`: renumbered along a Morton curve before the run (dem/spatial_sort.h), so the
    // force loop's blocks of consecutive indices hold neighbours and most contacts stay inside a
    // block; a packing file in arbitrary order (the DEM8 beds) otherwise spends ~30 % of its time
    // on cross-block sums (bench/results/2026-12-07-cpp-2core-dem8.txt).
    if (sortParticles && world.particles.size() > 1)
    {
        // Cells of two small diameters: a cell of the largest sphere's size would hold thousands
        // of small ones in input order (a 10 mm ball among 1 mm beads).
        Real smallest = world.particles.radius[0];
        for (const Real r : world.particles.radius)
            smallest = std::fmin(smallest, r);
        dem::sortParticlesSpatially(world, 4 * smallest);
    }
    try
    {
        checkInitialOverlaps(world, overlapTolerance); // also builds the pair table
    }
    catch (const dem::PeriodicBoxError& e)
    {
        if (!domain)
            throw;
        std::ostringstream message;
        message << "is too close to 'min': " << e.what();
        domain->fail("max", message.str());
    }
    applyPairOverrides(pairs, world);
    return scene;
}

} // namespace veridem::io
