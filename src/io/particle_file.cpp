#include "io/particle_file.h"

#include "core/error.h"
#include "io/number_text.h"
#include "io/scene_limits.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>

namespace veridem::io
{

namespace
{

enum Column
{
    Id,
    Material,
    Radius,
    X,
    Y,
    Z,
    Vx,
    Vy,
    Vz,
    Wx,
    Wy,
    Wz,
    Fixed,
    kColumns
};

struct ColumnName
{
    const char* name;
    std::array<const char*, 2> aliases; // (nullptr: none)
    const char* unit;                   // SI unit a header may give in brackets ("": none)
};

// The names a header may use (case-insensitive, an optional "[unit]" suffix).
constexpr std::array<ColumnName, kColumns> kNames = {{
    {"id", {nullptr, nullptr}, ""},
    {"material", {nullptr, nullptr}, ""},
    {"radius", {"r", nullptr}, "m"},
    {"x", {"posx", "pos_x"}, "m"},
    {"y", {"posy", "pos_y"}, "m"},
    {"z", {"posz", "pos_z"}, "m"},
    {"vx", {"velx", "vel_x"}, "m/s"},
    {"vy", {"vely", "vel_y"}, "m/s"},
    {"vz", {"velz", "vel_z"}, "m/s"},
    {"wx", {"omegax", "omega_x"}, "rad/s"},
    {"wy", {"omegay", "omega_y"}, "rad/s"},
    {"wz", {"omegaz", "omega_z"}, "rad/s"},
    {"fixed", {nullptr, nullptr}, ""},
}};

std::string knownNames()
{
    std::string s;
    for (const ColumnName& c : kNames)
        s += (s.empty() ? "" : " ") + std::string(c.name);
    return s;
}

/// The fields of a line, split at commas, tabs, spaces and carriage returns.
std::vector<std::string_view> split(std::string_view line)
{
    const auto separator = [](char c) { return c == ',' || c == ' ' || c == '\t' || c == '\r'; };
    std::vector<std::string_view> fields;
    std::size_t k = 0;
    while (k < line.size())
    {
        while (k < line.size() && separator(line[k]))
            ++k;
        const std::size_t start = k;
        while (k < line.size() && !separator(line[k]))
            ++k;
        if (k > start)
            fields.push_back(line.substr(start, k - start));
    }
    return fields;
}

/// Where each column is in a line (-1: absent), from a header line.
struct Layout
{
    std::array<int, kColumns> at;
    std::size_t width = 0; // columns per line
    std::string names;     // as written, for messages
};

Layout headerless()
{
    Layout l;
    l.at.fill(-1);
    l.at[X] = 0;
    l.at[Y] = 1;
    l.at[Z] = 2;
    l.width = 3;
    l.names = "x y z";
    return l;
}

} // namespace

void readParticleFile(TableReader& t, dem::World& world, const std::string& sceneFile, double reserved,
                      std::vector<GivenIds>& given)
{
    std::filesystem::path path = t.requiredString("file");
    if (path.is_relative())
        path = std::filesystem::path(sceneFile).parent_path() / path;
    const bool materialKey = t.has("material"), radiusKey = t.has("radius"), velocityKey = t.has("velocity"),
               spinKey = t.has("angular_velocity"), fixedKey = t.has("fixed");
    const std::uint32_t keyMaterial = materialKey ? world.materialId(t.requiredString("material")) : 0;
    const Real keyRadius = radiusKey ? t.requiredNumber("radius") : 0;
    if (radiusKey)
        t.requirePositive("radius", keyRadius, "m");
    const Vec3 keyVelocity = t.vec3("velocity", {});
    const Vec3 keySpin = t.vec3("angular_velocity", {});
    const bool keyFixed = t.boolean("fixed", false);
    const std::optional<Real> rowsKey = t.optionalNumber("rows");
    if (rowsKey && !(*rowsKey >= 1 && *rowsKey == std::floor(*rowsKey) && *rowsKey <= 1e12))
        t.fail("rows", "must be a whole number >= 1 (the particle rows to read)");
    const std::size_t rows = rowsKey ? static_cast<std::size_t>(*rowsKey) : ~std::size_t(0);
    // A radius window selects rows (the DEM8 drum's file holds two species told apart by size).
    const Real minRadius = t.number("min_radius", 0);
    const Real maxRadius = t.number("max_radius", std::numeric_limits<Real>::infinity());
    t.requireNonNegative("min_radius", minRadius, "m");
    if (!(maxRadius > minRadius))
        t.fail("max_radius",
               "must exceed min_radius [m] (the rows kept have min_radius <= radius <= max_radius)");
    if ((t.has("min_radius") || t.has("max_radius")) && radiusKey)
        t.fail(t.has("min_radius") ? "min_radius" : "max_radius",
               "selects rows by a radius column; with the radius key every row has the same radius");
    t.finish();
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        t.fail("file", "is a directory: '" + path.string() + "'");
    std::ifstream in(path);
    if (!in)
        t.fail("file", "cannot be opened: '" + path.string() + "'");
    constexpr std::streamsize kMaxLine = 4096; // characters per line, comments included
    std::string line(kMaxLine, '\0');
    std::size_t lineNumber = 0;
    const double limit = maxSphereCount();
    auto where = [&] { return path.string() + ":" + std::to_string(lineNumber); };
    std::optional<Layout> layout;
    const std::size_t first = world.particles.size();
    std::vector<std::pair<std::uint32_t, std::size_t>> ids; // (id, line) of an id column
    std::vector<Real> row(kColumns);
    std::size_t read = 0; // particle rows
    while (read < rows && (in.getline(line.data(), kMaxLine) || in.gcount() > 0))
    {
        ++lineNumber;
        if (in.fail() && !in.eof()) // the line filled the buffer without ending
            throw InputError(where() + ": line longer than " + std::to_string(kMaxLine - 1) +
                             " characters: not a text file of particles, one per line");
        const std::vector<std::string_view> fields = split({line.data(), std::strlen(line.data())});
        if (fields.empty() || fields[0][0] == '#')
            continue;
        if (!layout) // the first line: a header of column names, or the first 'x y z' line
        {
            if (parseNumber(fields[0]))
                layout = headerless();
            else
            {
                layout.emplace();
                layout->at.fill(-1);
                layout->width = fields.size();
                for (std::size_t k = 0; k < fields.size(); ++k)
                {
                    std::string name(fields[k]), unit;
                    layout->names += (k ? " " : "") + name;
                    for (char& c : name)
                        c = char(std::tolower(static_cast<unsigned char>(c)));
                    if (const std::size_t open = name.find('[');
                        open != std::string::npos && name.back() == ']')
                    {
                        unit = name.substr(open + 1, name.size() - open - 2);
                        name.resize(open);
                    }
                    int column = -1;
                    for (int c = 0; c < kColumns; ++c)
                        if (name == kNames[c].name ||
                            (kNames[c].aliases[0] && name == kNames[c].aliases[0]) ||
                            (kNames[c].aliases[1] && name == kNames[c].aliases[1]))
                            column = c;
                    if (column < 0)
                        throw InputError(where() + ": unknown column '" + std::string(fields[k]) +
                                         "' (known: " + knownNames() +
                                         ", case-insensitive, with an optional [unit])");
                    if (layout->at[column] >= 0)
                        throw InputError(where() + ": column '" + kNames[column].name + "' appears twice");
                    if (!unit.empty() && unit != "-" && unit != kNames[column].unit)
                        throw InputError(where() + ": column '" + std::string(fields[k]) + "' must be in [" +
                                         kNames[column].unit + "]" +
                                         (*kNames[column].unit ? "" : " (no unit)"));
                    layout->at[column] = int(k);
                }
                for (const Column c : {X, Y, Z})
                    if (layout->at[c] < 0)
                        throw InputError(where() + ": the header has no '" + kNames[c].name +
                                         "' column (a header needs x y z; known: " + knownNames() + ")");
                for (const Column c : {Vx, Wx})
                    if ((layout->at[c] >= 0) != (layout->at[c + 1] >= 0) ||
                        (layout->at[c] >= 0) != (layout->at[c + 2] >= 0))
                        throw InputError(where() + ": give all three of '" + kNames[c].name + "', '" +
                                         kNames[c + 1].name + "' and '" + kNames[c + 2].name + "' or none");
                const auto once = [&](Column c, bool key, const char* keyName)
                {
                    if (layout->at[c] >= 0 && key)
                        t.fail(keyName,
                               std::string("is also a column of '") + path.string() + "': give it once");
                };
                once(Material, materialKey, "material");
                once(Radius, radiusKey, "radius");
                once(Vx, velocityKey, "velocity");
                once(Wx, spinKey, "angular_velocity");
                once(Fixed, fixedKey, "fixed");
            }
            if (layout->at[Material] < 0 && !materialKey)
                t.fail("material", "is missing: give material = \"<name>\" or a material column in '" +
                                       path.string() + "'");
            if (layout->at[Radius] < 0 && !radiusKey)
                t.fail("radius",
                       "is missing: give radius = <m> or a radius column in '" + path.string() + "'");
            if (!parseNumber(fields[0]))
                continue; // (a header line)
        }
        if (fields.size() != layout->width)
            throw InputError(where() + ": expected " + std::to_string(layout->width) + " columns (" +
                             layout->names + "), found " + std::to_string(fields.size()) +
                             " (to read only the rows before it, give rows = N in [[particles]])");
        ++read;
        std::uint32_t material = keyMaterial;
        std::uint32_t id = 0;
        bool fixed = keyFixed;
        for (int c = 0; c < kColumns; ++c)
        {
            const int k = layout->at[c];
            if (k < 0)
                continue;
            const std::string_view text = fields[std::size_t(k)];
            if (c == Material)
            {
                const auto known = std::find_if(world.materials.begin(), world.materials.end(),
                                                [&](const dem::Material& m) { return m.name == text; });
                if (known == world.materials.end())
                {
                    std::string names;
                    for (const dem::Material& m : world.materials)
                        names += (names.empty() ? "" : ", ") + m.name;
                    throw InputError(where() + ": unknown material '" + std::string(text) +
                                     "' (the scene's [[material]] names: " + names + ")");
                }
                material = static_cast<std::uint32_t>(known - world.materials.begin());
            }
            else if (c == Id)
            {
                std::uint64_t value = 0;
                const auto [end, failed] = std::from_chars(text.data(), text.data() + text.size(), value);
                if (failed != std::errc() || end != text.data() + text.size() || value >= 0xFFFFFFFFull)
                    throw InputError(where() + ": column 'id': '" + std::string(text) +
                                     "' is not a whole number in [0, 4294967294]");
                id = static_cast<std::uint32_t>(value);
            }
            else if (c == Fixed)
            {
                if (text != "0" && text != "1" && text != "true" && text != "false")
                    throw InputError(where() + ": column 'fixed': '" + std::string(text) +
                                     "' is not 0, 1, true or false");
                fixed = text == "1" || text == "true";
            }
            else
            {
                const std::optional<double> value = parseNumber(text);
                if (!value)
                    throw InputError(where() + ": column '" + kNames[c].name + "': '" + std::string(text) +
                                     "' is not a number");
                if (!std::isfinite(*value))
                    throw InputError(where() + ": column '" + kNames[c].name + "' must be finite (got " +
                                     std::string(text) + ")");
                row[std::size_t(c)] = *value;
            }
        }
        const Real radius = layout->at[Radius] >= 0 ? row[Radius] : keyRadius;
        if (!(radius > 0))
            throw InputError(where() + ": column 'radius' must be > 0 m (got " +
                             std::string(fields[std::size_t(layout->at[Radius])]) + ")");
        if (radius < minRadius || radius > maxRadius)
            continue; // (outside the radius window: not this table's)
        const Vec3 v = layout->at[Vx] >= 0 ? Vec3{row[Vx], row[Vy], row[Vz]} : keyVelocity;
        const Vec3 w = layout->at[Wx] >= 0 ? Vec3{row[Wx], row[Wy], row[Wz]} : keySpin;
        if (double(world.particles.size()) + 1 + reserved > limit)
            checkSphereCount(double(world.particles.size()) + 1 + reserved,
                             "the [[particles]] file '" + path.string() + "' (to line " +
                                 std::to_string(lineNumber) + ") and the other tables",
                             sceneFile);
        world.particles.add({row[X], row[Y], row[Z]}, v, w, radius, world.materials[material].density,
                            material);
        world.particles.fixed.back() = fixed;
        if (layout->at[Id] >= 0)
        {
            world.particles.id.back() = id;
            ids.emplace_back(id, lineNumber);
        }
    }
    if (in.bad())
        throw InputError(path.string() + ": read error");
    if (rowsKey && read < rows)
        t.fail("rows", "asks for " + std::to_string(rows) + " rows, '" + path.string() + "' has " +
                           std::to_string(read));
    if (layout && layout->at[Id] >= 0)
    {
        std::sort(ids.begin(), ids.end());
        for (std::size_t k = 1; k < ids.size(); ++k)
            if (ids[k].first == ids[k - 1].first)
                throw InputError(path.string() + ":" + std::to_string(ids[k].second) + ": id " +
                                 std::to_string(ids[k].first) + " is also on line " +
                                 std::to_string(ids[k - 1].second) + " (ids must be unique)");
        given.push_back({first, world.particles.size() - first, path.string()});
    }
}

void numberParticles(dem::ParticleStore& particles, const std::vector<GivenIds>& given)
{
    if (given.empty())
        return;
    std::vector<std::pair<std::uint32_t, std::size_t>> taken; // (id, file)
    std::vector<std::uint8_t> fromFile(particles.size(), 0);
    for (std::size_t f = 0; f < given.size(); ++f)
        for (std::size_t i = given[f].first; i < given[f].first + given[f].count; ++i)
        {
            taken.emplace_back(particles.id[i], f);
            fromFile[i] = 1;
        }
    std::sort(taken.begin(), taken.end());
    for (std::size_t k = 1; k < taken.size(); ++k)
        if (taken[k].first == taken[k - 1].first)
            throw InputError("id " + std::to_string(taken[k].first) +
                             " is given by two [[particles]] files, '" + given[taken[k - 1].second].file +
                             "' and '" + given[taken[k].second].file + "' (ids must be unique in a scene)");
    std::uint32_t next = 0;
    std::size_t k = 0; // the first taken id >= next
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        if (fromFile[i])
            continue;
        while (k < taken.size() && taken[k].first < next)
            ++k;
        while (k < taken.size() && taken[k].first == next)
        {
            ++next;
            ++k;
        }
        particles.id[i] = next++;
    }
}

} // namespace veridem::io
