#include "fdem/scene.h"

#include "core/constants.h"
#include "core/error.h"
#include "fdem/body_overlap.h"
#include "fdem/gmsh_reader.h"
#include "fdem/mesher.h"
#include "io/toml_reader.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

namespace veridem::fdem
{

namespace
{

constexpr std::int64_t kMaxRectangleTriangles = 10'000'000; // 2 nx ny

std::string locate(const std::string& file, const toml::node& node)
{
    std::ostringstream s;
    s << file;
    if (node.source().begin.line)
        s << ":" << node.source().begin.line << ":" << node.source().begin.column;
    return s.str();
}

/// Reads a 2D vector key [x, y] and removes it from `table` (TableReader has 3D vectors only).
std::optional<Vec2> takeVec2(toml::table& table, std::string_view key, const std::string& where,
                             const std::string& file)
{
    toml::node* node = table.get(key);
    if (!node)
        return std::nullopt;
    const toml::array* a = node->as_array();
    std::optional<Vec2> v;
    if (a && a->size() == 2)
    {
        const auto x = (*a)[0].value<double>(), y = (*a)[1].value<double>();
        if (x && y && std::isfinite(*x) && std::isfinite(*y))
            v = Vec2{*x, *y};
    }
    if (!v)
        throw InputError(locate(file, *node) + ": " + where + ": '" + std::string(key) +
                         "' must be an array of 2 finite numbers [x, y]");
    table.erase(key);
    return v;
}

/// Reads a polygon [[x0, y0], [x1, y1], ...] and removes it from `table`.
std::optional<std::vector<Vec2>> takePolygon(toml::table& table, std::string_view key,
                                             const std::string& where, const std::string& file)
{
    toml::node* node = table.get(key);
    if (!node)
        return std::nullopt;
    std::vector<Vec2> out;
    const toml::array* a = node->as_array();
    bool ok = a != nullptr;
    if (ok)
        for (const auto& element : *a)
        {
            const toml::array* p = element.as_array();
            const auto x = p && p->size() == 2 ? (*p)[0].value<double>() : std::nullopt;
            const auto y = p && p->size() == 2 ? (*p)[1].value<double>() : std::nullopt;
            if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y))
            {
                ok = false;
                break;
            }
            out.push_back({*x, *y});
        }
    if (!ok)
        throw InputError(locate(file, *node) + ": " + where + ": '" + std::string(key) +
                         "' must be an array of [x, y] vertices");
    table.erase(key);
    return out;
}

Vec2 requirePositiveSize(io::TableReader& r, std::string_view key, std::optional<Vec2> v)
{
    if (!v)
        r.fail(key, "is required ([width, height] in m)");
    if (!(v->x > 0) || !(v->y > 0))
        r.fail(key, "must be positive [width, height] in m");
    return *v;
}

TriangleMesh readGeometry(toml::table& bodyTable, io::TableReader& body, const std::string& where,
                          const std::string& file)
{
    int kinds = 0;
    TriangleMesh mesh;
    // edge_length [m]: interior nodes for a polygon (else ear clipping) and the size of a disc's mesh.
    const std::optional<Real> edgeLength = body.optionalNumber("edge_length");
    if (edgeLength && !(*edgeLength > 0 && std::isfinite(*edgeLength)))
        body.fail("edge_length", "must be a positive length in m");
    const auto checkTriangleCount = [&](Real area)
    {
        // The refined mesh has about area / (sqrt(3)/4 h^2) triangles: refused before it is made.
        const Real estimate = area / (0.4330127018922193 * *edgeLength * *edgeLength);
        if (estimate > static_cast<Real>(kMaxRectangleTriangles))
            body.fail("edge_length", "would make about " + std::to_string(static_cast<long long>(estimate)) +
                                         " triangles (at most " + std::to_string(kMaxRectangleTriangles) +
                                         ")");
    };
    if (body.has("rectangle"))
    {
        if (edgeLength)
            body.fail("edge_length", "applies to a 'polygon' or a 'disc' (not to a 'rectangle' or a 'mesh')");
        body.table("rectangle"); // checks that it is a table and marks the key as read
        const toml::table* rect = bodyTable["rectangle"].as_table();
        ++kinds;
        toml::table copy = *rect;
        const std::string w = where + " [rectangle]";
        const Vec2 origin = takeVec2(copy, "origin", w, file).value_or(Vec2{});
        const auto size = takeVec2(copy, "size", w, file);
        io::TableReader r(copy, w, file);
        const Vec2 s = requirePositiveSize(r, "size", size);
        const auto nx = r.integer("nx", 1), ny = r.integer("ny", 1);
        if (nx < 1 || nx > 100000)
            r.fail("nx", "must be an integer in [1, 100000]");
        if (ny < 1 || ny > 100000)
            r.fail("ny", "must be an integer in [1, 100000]");
        if (2 * nx * ny > kMaxRectangleTriangles) // checked before the mesher allocates them
            r.fail("ny", "with nx would make " + std::to_string(2 * nx * ny) + " triangles (at most " +
                             std::to_string(kMaxRectangleTriangles) + " in a rectangle)");
        const std::string pattern = r.choice("pattern", "alternate", {"alternate", "right"});
        r.finish();
        mesh = meshRectangle(origin, s, static_cast<int>(nx), static_cast<int>(ny),
                             pattern == "right" ? DiagonalPattern::Right : DiagonalPattern::Alternate);
    }
    if (auto polygon = takePolygon(bodyTable, "polygon", where, file))
    {
        ++kinds;
        if (edgeLength)
        {
            Real area2 = 0;
            for (std::size_t i = 0; i < polygon->size(); ++i)
                area2 += cross((*polygon)[i], (*polygon)[(i + 1) % polygon->size()]);
            checkTriangleCount(std::abs(area2) / 2);
            mesh = meshPolygonRefined(*polygon, *edgeLength);
        }
        else
            mesh = meshPolygon(*polygon);
    }
    if (body.has("disc"))
    {
        body.table("disc"); // checks that it is a table and marks the key as read
        ++kinds;
        toml::table copy = *bodyTable["disc"].as_table();
        const std::string w = where + " [disc]";
        const Vec2 centre = takeVec2(copy, "centre", w, file).value_or(Vec2{});
        io::TableReader r(copy, w, file);
        const Real radius = r.requiredNumber("radius");
        if (!(radius > 0) || !std::isfinite(radius))
            r.fail("radius", "must be a positive length in m");
        r.finish();
        if (!edgeLength)
            body.fail("edge_length", "is required with 'disc' (the target edge length of its mesh, m)");
        checkTriangleCount(kPi * radius * radius);
        mesh = meshPolygonRefined(discOutline(centre, radius, *edgeLength), *edgeLength);
    }
    if (edgeLength && kinds == 0)
        body.fail("edge_length", "applies to a 'polygon' or a 'disc'");
    if (body.has("mesh"))
    {
        if (edgeLength)
            body.fail("edge_length", "applies to a 'polygon' or a 'disc' (not to a 'rectangle' or a 'mesh')");
        ++kinds;
        std::filesystem::path path = body.string("mesh", "");
        if (path.is_relative())
            path = std::filesystem::path(file).parent_path() / path;
        mesh = readGmsh(path.string());
    }
    if (kinds != 1)
        throw InputError(file + ": " + where +
                         ": give exactly one of 'rectangle', 'polygon', 'disc' or 'mesh'");
    return mesh;
}

} // namespace

Scene readScene(const toml::table& rootIn, const std::string& file)
{
    Scene scene;
    toml::table root = rootIn;
    io::TableReader top(root, "scene", file);

    // [simulation]
    toml::table simulationTable;
    if (const toml::table* t = root["simulation"].as_table())
        simulationTable = *t;
    const auto gravity = takeVec2(simulationTable, "gravity", "[simulation]", file);
    {
        io::TableReader sim(simulationTable, "[simulation]", file);
        sim.choice("type", "fdem2d", {"fdem2d"});
        if (const toml::table* original = rootIn["simulation"].as_table()) // the copy has no line numbers
            io::refuseRenamedKeys(io::TableReader(*original, "[simulation]", file));
        scene.settings.timeStep = sim.requiredNumber("dt");
        sim.requirePositive("dt", scene.settings.timeStep, "s");
        scene.duration = sim.requiredNumber("duration");
        sim.requirePositive("duration", scene.duration, "s");
        scene.outputInterval = sim.number("output_interval", 0);
        sim.requireNonNegative("output_interval", scene.outputInterval, "s");
        if (auto interval = sim.optionalNumber("checkpoint_interval"))
        {
            sim.requirePositive("checkpoint_interval", *interval, "s");
            scene.checkpointInterval = *interval;
        }
        scene.settleTime = sim.number("settle_time", 0);
        sim.requireNonNegative("settle_time", scene.settleTime, "s");
        scene.settings.gravity = gravity.value_or(Vec2{0, -9.81});
        scene.vtk = sim.boolean("vtk", true);
        scene.vtkFormat = sim.choice("vtk_format", "auto", {"auto", "ascii", "binary"});
        sim.finish();
    }
    top.table("simulation");

    // [contact]
    if (auto contact = top.table("contact"))
    {
        ContactParameters& c = scene.settings.contact;
        c.normalPenalty = contact->requiredNumber("normal_penalty");
        contact->requirePositive("normal_penalty", c.normalPenalty, "Pa");
        c.tangentialPenalty = contact->number("tangential_penalty", c.normalPenalty);
        contact->requirePositive("tangential_penalty", c.tangentialPenalty, "Pa");
        c.friction = contact->number("friction", 0);
        contact->requireNonNegative("friction", c.friction, "");
        c.normalDampingRatio = contact->number("normal_damping_ratio", 0);
        contact->requireNonNegative("normal_damping_ratio", c.normalDampingRatio, "");
        scene.settleNormalDampingRatio = contact->number("settle_normal_damping_ratio", c.normalDampingRatio);
        contact->requireNonNegative("settle_normal_damping_ratio", scene.settleNormalDampingRatio, "");
        c.tangentialDampingRatio = contact->number("tangential_damping_ratio", 0);
        contact->requireNonNegative("tangential_damping_ratio", c.tangentialDampingRatio, "");
        scene.settings.buffer = contact->number("buffer", 0);
        contact->requireNonNegative("buffer", scene.settings.buffer, "m");
        contact->finish();
    }
    else
        throw InputError(file + ": missing [contact] table (normal_penalty is required)");

    // [[material]]
    for (auto& m : top.arrayOfTables("material"))
    {
        Material mat;
        const std::string name = m.requiredString("name");
        for (const auto& existing : scene.materialNames)
            if (existing == name)
                m.fail("name", "material '" + name + "' is defined twice");
        mat.density = m.requiredNumber("density");
        m.requirePositive("density", mat.density, "kg/m^3");
        mat.youngsModulus = m.requiredNumber("youngs_modulus");
        m.requirePositive("youngs_modulus", mat.youngsModulus, "Pa");
        mat.poissonRatio = m.requiredNumber("poisson_ratio");
        if (!(mat.poissonRatio >= 0 && mat.poissonRatio < 0.5))
            m.fail("poisson_ratio", "must be in [0, 0.5)");
        mat.viscosity = m.number("viscosity", 0);
        m.requireNonNegative("viscosity", mat.viscosity, "Pa s");
        mat.law = m.choice("stress_law", "finite_strain", {"finite_strain", "linear"}) == "linear"
                      ? StressLaw::Linear
                      : StressLaw::FiniteStrain;
        mat.plane = m.choice("plane", "strain", {"strain", "stress"}) == "stress" ? PlaneModel::Stress
                                                                                  : PlaneModel::Strain;
        FractureParameters& f = mat.fracture; // checked where a body cracks (World::addBody)
        f.tensileStrength = m.number("tensile_strength", 0);
        m.requireNonNegative("tensile_strength", f.tensileStrength, "Pa");
        f.fractureEnergy = m.number("fracture_energy", 0);
        m.requireNonNegative("fracture_energy", f.fractureEnergy, "J/m^2");
        f.shearFractureEnergy = m.number("shear_fracture_energy", f.fractureEnergy);
        m.requireNonNegative("shear_fracture_energy", f.shearFractureEnergy, "J/m^2");
        f.cohesion = m.number("cohesion", 0);
        m.requireNonNegative("cohesion", f.cohesion, "Pa");
        const Real phi = m.number("internal_friction_degrees", 0);
        if (!(phi >= 0 && phi < 90))
            m.fail("internal_friction_degrees", "must be in [0, 90) degrees");
        f.frictionAngle = phi * 3.14159265358979323846 / 180;
        f.penalty = m.number("joint_penalty", 10 * mat.youngsModulus);
        m.requirePositive("joint_penalty", f.penalty, "Pa");
        const std::string curve = m.choice("softening", "munjiza", {"munjiza", "linear", "exponential"});
        f.curve = curve == "linear"        ? SofteningCurve::Linear
                  : curve == "exponential" ? SofteningCurve::Exponential
                                           : SofteningCurve::Munjiza;
        m.finish();
        scene.materialNames.push_back(name);
        scene.materials.push_back(mat);
    }
    if (scene.materials.empty())
        throw InputError(file + ": no [[material]] table");

    // [[body]]: the tables are copied so that 2D vectors and geometry can be taken out first.
    std::vector<std::string> bodyNames;
    if (toml::array* bodies = root["body"].as_array())
    {
        std::size_t index = 0;
        for (auto& element : *bodies)
        {
            const std::string where = "[[body]] #" + std::to_string(++index);
            toml::table* raw = element.as_table();
            if (!raw)
                throw InputError(file + ": 'body' must be written as [[body]] tables");
            toml::table copy = *raw;
            BodyDefinition def;
            def.velocity = takeVec2(copy, "velocity", where, file).value_or(Vec2{});
            const auto crackMin = takeVec2(copy, "crack_box_min", where, file);
            const auto crackMax = takeVec2(copy, "crack_box_max", where, file);
            io::TableReader b(copy, where, file);
            def.name = b.requiredString("name");
            for (const auto& existing : bodyNames)
                if (existing == def.name)
                    b.fail("name", "body '" + def.name + "' is defined twice");
            const std::string material = b.requiredString("material");
            bool found = false;
            for (std::size_t i = 0; i < scene.materialNames.size(); ++i)
                if (scene.materialNames[i] == material)
                {
                    def.material = static_cast<std::uint32_t>(i);
                    found = true;
                }
            if (!found)
                b.fail("material", "unknown material '" + material + "'");
            def.fixed = b.boolean("fixed", false);
            def.cracks = b.boolean("cracks", false);
            if (crackMin || crackMax)
            {
                if (!crackMin || !crackMax)
                    b.fail("crack_box_min", "crack_box_min and crack_box_max ([x, y] in m) go together");
                if (!def.cracks)
                    b.fail("crack_box_min", "needs cracks = true");
                if (!(crackMax->x >= crackMin->x && crackMax->y >= crackMin->y))
                    b.fail("crack_box_max", "must be >= crack_box_min in x and y");
                def.crackRegion = true;
                def.crackMin = *crackMin;
                def.crackMax = *crackMax;
            }
            def.mesh = readGeometry(copy, b, where, file);
            b.finish();
            bodyNames.push_back(def.name);
            scene.bodies.push_back(std::move(def));
        }
        top.arrayOfTables("body");
    }
    if (scene.bodies.empty())
        throw InputError(file + ": no [[body]] table");
    {
        std::vector<const TriangleMesh*> meshes;
        for (const auto& body : scene.bodies)
            meshes.push_back(&body.mesh);
        checkBodiesApart(meshes, bodyNames, file);
    }

    // [[boundary]]
    if (toml::array* boundaries = root["boundary"].as_array())
    {
        std::size_t index = 0;
        for (auto& element : *boundaries)
        {
            const std::string where = "[[boundary]] #" + std::to_string(++index);
            toml::table* raw = element.as_table();
            if (!raw)
                throw InputError(file + ": 'boundary' must be written as [[boundary]] tables");
            toml::table copy = *raw;
            SceneBoundary boundary;
            const auto lo = takeVec2(copy, "box_min", where, file);
            const auto hi = takeVec2(copy, "box_max", where, file);
            boundary.velocity = takeVec2(copy, "velocity", where, file).value_or(Vec2{});
            io::TableReader b(copy, where, file);
            const std::string body = b.requiredString("body");
            bool found = false;
            for (std::size_t i = 0; i < bodyNames.size(); ++i)
                if (bodyNames[i] == body)
                {
                    boundary.body = static_cast<std::uint32_t>(i);
                    found = true;
                }
            if (!found)
                b.fail("body", "unknown body '" + body + "'");
            if (!lo || !hi)
                b.fail("box_min", "box_min and box_max ([x, y] in m) are required");
            boundary.boxMin = *lo;
            boundary.boxMax = *hi;
            if (!(hi->x >= lo->x && hi->y >= lo->y))
                b.fail("box_max", "must be >= box_min in x and y");
            b.finish();
            scene.boundaries.push_back(boundary);
        }
        top.arrayOfTables("boundary");
    }
    top.finish();
    return scene;
}

World buildWorld(const Scene& scene, bool settle)
{
    World world(scene.settings);
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        world.addMaterial(scene.materials[i], scene.materialNames[i]);
    for (BodyDefinition body : scene.bodies)
    {
        if (settle && !body.fixed)
            body.velocity = {};
        world.addBody(body);
    }
    for (const auto& b : scene.boundaries)
        if (world.prescribeNodes(b.body, b.boxMin, b.boxMax, b.velocity) == 0)
            throw InputError("[[boundary]] on body '" + scene.bodies[b.body].name +
                             "': the box contains no node");
    return world;
}

} // namespace veridem::fdem
