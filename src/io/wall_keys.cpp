#include "io/wall_keys.h"

#include "core/constants.h"
#include "io/surface_mesh_reader.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

namespace veridem::io
{

namespace
{

/// The rows of `key` as a MotionTable: times strictly increasing; `toVector` maps a row's values
/// after the time to a vector.
template <class ToVector>
dem::MotionTable readTable(TableReader& t, const char* key, const std::vector<std::size_t>& widths,
                           ToVector toVector)
{
    const std::vector<std::vector<Real>> rows = t.numberRows(key, widths);
    std::vector<Real> time;
    std::vector<Vec3> value;
    for (const auto& row : rows)
    {
        if (!time.empty() && !(row[0] > time.back()))
            t.fail(key, "times (the first column, s) must be strictly increasing");
        time.push_back(row[0]);
        value.push_back(toVector(row));
    }
    return rows.empty() ? dem::MotionTable{} : dem::MotionTable(std::move(time), std::move(value));
}

} // namespace

Vec3 symmetryAxis(const dem::Wall& wall)
{
    if (const auto* plane = std::get_if<dem::PlaneShape>(&wall.shape))
        return plane->normal;
    if (const auto* cylinder = std::get_if<dem::CylinderShape>(&wall.shape))
        return cylinder->axis;
    if (std::holds_alternative<dem::MeshShape>(wall.shape))
        return {};    // (none: a mesh turns about any axis through its rotation centre)
    return {0, 0, 1}; // dish
}

void readCommonWallKeys(TableReader& t, dem::Wall& wall, const Vec3& axis)
{
    dem::WallMotion& m = wall.motion;
    m.velocity = t.vec3("velocity", m.velocity); // (a plane has read it; the others read it here)
    m.velocityTable = readTable(t, "velocity_table", {4},
                                [](const std::vector<Real>& r) {
                                    return Vec3{r[1], r[2], r[3]};
                                });
    if (!m.velocityTable.empty())
    {
        if (length(m.velocity) > 0)
            t.fail("velocity_table", "cannot be combined with a constant 'velocity'");
        if (m.oscillationAngularFrequency > 0)
            t.fail("velocity_table", "cannot be combined with an oscillation");
        m.velocity = m.velocityTable.at(0);
    }
    m.angularVelocityTable = readTable(
        t, "omega_table", {2, 4},
        [&](const std::vector<Real>& r)
        {
            const bool anyAxis = length(axis) == 0; // a mesh
            if (r.size() == 2 && anyAxis)
                t.fail("omega_table", "needs [t, wx, wy, wz] rows for a mesh (it has no symmetry axis)");
            if (r.size() == 2)
                return r[1] * axis;
            const Vec3 w{r[1], r[2], r[3]};
            const Vec3 across = w - dot(w, axis) * axis;
            if (!anyAxis && length(across) > 1e-12 * length(w))
                t.fail("omega_table", "must be about the wall's symmetry axis (plane "
                                      "normal, dish z, cylinder axis): give [t, w] rows");
            return w;
        });
    if (!m.angularVelocityTable.empty())
    {
        if (length(m.angularVelocity) > 0)
            t.fail("omega_table", "cannot be combined with a constant 'omega'");
        m.angularVelocity = m.angularVelocityTable.at(0);
    }
    wall.activeFrom = t.number("active_from", -std::numeric_limits<Real>::infinity());
    wall.activeUntil = t.number("active_until", std::numeric_limits<Real>::infinity());
    if (!(wall.activeUntil > wall.activeFrom))
        t.fail("active_until", "must be after active_from (s)");
    wall.loadPoint = t.vec3("load_point", m.rotationCentre);
}

/// A triangle-mesh wall: the surface from `file` (STL, Gmsh or triangle text, relative to the scene's
/// directory) times `scale`, translating at `velocity` and turning at `omega` (a vector) about
/// `rotation_centre`. The mesh's warnings (open boundary, non-manifold edges) go to stderr.
void readMeshWall(TableReader& t, dem::Wall& wall)
{
    const std::string file = t.requiredString("file");
    const Real scale = t.number("scale", 1.0);
    t.requirePositive("scale", scale, "");
    const std::filesystem::path path = std::filesystem::path(t.file()).parent_path() / file;
    dem::MeshReport report;
    std::vector<std::size_t> lines; // (of a text mesh: each triangle's line, for its errors)
    const std::vector<Vec3> corners = readSurfaceMesh(path.string(), scale, &lines);
    dem::MeshShape mesh;
    mesh.mesh = std::make_shared<const dem::TriangleMesh>(
        dem::buildTriangleMesh(corners, path.string(), report, lines));
    for (const std::string& warning : report.warnings)
        std::fprintf(stderr, "veridem: warning: wall '%s': %s\n", wall.name.c_str(), warning.c_str());
    wall.motion.velocity = t.vec3("velocity", {});
    wall.motion.angularVelocity = t.vec3("omega", {});
    wall.motion.rotationCentre = t.vec3("rotation_centre", {});
    mesh.pivot = wall.motion.rotationCentre;
    mesh.farthestVertex = mesh.mesh->farthestVertex(mesh.pivot);
    wall.shape = std::move(mesh);
}

bool readCylinder(TableReader& t, dem::Wall& wall)
{
    dem::CylinderShape c;
    c.point = t.requiredVec3("point");
    const Vec3 axis = t.requiredVec3("axis");
    if (!(length(axis) > 0))
        t.fail("axis", "must be a non-zero vector");
    c.axis = axis / length(axis);
    c.radius = t.requiredNumber("radius");
    t.requirePositive("radius", c.radius, "m");
    c.length = t.requiredNumber("length");
    t.requirePositive("length", c.length, "m");
    c.inside = t.choice("side", "inside", {"inside", "outside"}) == "inside";
    wall.shape = c;
    wall.motion.velocity = t.vec3("velocity", {});
    wall.motion.angularVelocity = t.number("omega", 0.0) * c.axis;
    wall.motion.rotationCentre = c.point;
    return t.boolean("caps", false);
}

std::vector<dem::Wall> cylinderCaps(const dem::Wall& cylinder)
{
    const auto& c = std::get<dem::CylinderShape>(cylinder.shape);
    // Inside (a drum) the caps face inwards; outside (a post) they face away from it.
    const Real facing = c.inside ? 1.0 : -1.0;
    std::vector<dem::Wall> caps(2, cylinder);
    caps[0].name = cylinder.name + "/cap0";
    caps[0].shape = dem::PlaneShape{c.point, facing * c.axis, c.radius};
    caps[1].name = cylinder.name + "/cap1";
    caps[1].shape = dem::PlaneShape{c.point + c.length * c.axis, -facing * c.axis, c.radius};
    return caps;
}

dem::Wall readWall(TableReader& t, const dem::World& world)
{
    dem::Wall wall;
    wall.name = t.requiredString("name");
    if (wall.name.empty() || wall.name.find_first_of(",\"\n\r") != std::string::npos)
        t.fail("name", "must be a non-empty name without commas, quotes or line breaks (it is a column of "
                       "walls.csv and contacts_NNNNNN.csv)");
    const std::string type = t.choice("type", "plane", {"plane", "turntable", "dish", "cylinder", "mesh"});
    wall.material = world.materialId(t.requiredString("material"));
    if (type == "plane")
    {
        dem::PlaneShape plane;
        plane.point = t.vec3("point", {});
        const Vec3 normal = t.requiredVec3("normal");
        if (!(length(normal) > 0))
            t.fail("normal", "must be a non-zero vector");
        plane.normal = normal / length(normal);
        wall.shape = plane;
        wall.motion.velocity = t.vec3("velocity", {});
        wall.motion.oscillationAmplitude = t.vec3("oscillation_amplitude", {});
        wall.motion.oscillationAngularFrequency = t.number("oscillation_omega", 0.0);
        if (wall.motion.oscillationAngularFrequency < 0)
            t.fail("oscillation_omega", "must be >= 0 rad/s");
        if (wall.motion.oscillationAngularFrequency > 0 && length(wall.motion.velocity) > 0)
            t.fail("oscillation_omega", "an oscillating plane cannot also have a steady velocity");
        const Real omega = t.number("omega", 0.0);
        wall.motion.angularVelocity = omega * plane.normal;
        wall.motion.rotationCentre = plane.point;
    }
    else if (type == "turntable")
    {
        dem::PlaneShape disk;
        disk.point = t.vec3("centre", {});
        disk.diskRadius = t.requiredNumber("radius");
        t.requirePositive("radius", disk.diskRadius, "m");
        const Real tilt = t.number("tilt_degrees", 0.0);
        const Real downhill = t.number("downhill_degrees", 0.0);
        if (!(std::fabs(tilt) < 90))
            t.fail("tilt_degrees", "must be in (-90, 90) degrees");
        disk.normal = dem::tiltedNormal(degToRad(tilt), degToRad(downhill));
        wall.shape = disk;
        wall.motion.angularVelocity = t.number("omega", 0.0) * disk.normal;
        wall.motion.rotationCentre = disk.point;
    }
    else if (type == "cylinder")
        static_cast<void>(readCylinder(t, wall)); // (caps: readDemScene adds them)
    else if (type == "mesh")
    {
        readMeshWall(t, wall);
    }
    else
    {
        dem::DishShape dish;
        dish.lowestPoint = t.vec3("lowest_point", {});
        dish.sphereRadius = t.requiredNumber("sphere_radius");
        t.requirePositive("sphere_radius", dish.sphereRadius, "m");
        wall.shape = dish;
        wall.motion.angularVelocity = {0, 0, t.number("omega", 0.0)};
        wall.motion.rotationCentre = dish.lowestPoint;
    }
    readCommonWallKeys(t, wall, symmetryAxis(wall));
    t.finish();
    return wall;
}

} // namespace veridem::io
