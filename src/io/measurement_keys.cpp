#include "io/measurement_keys.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace veridem::io
{

namespace
{
void readParticleFields(TableReader& output, OutputOptions& options)
{
    if (!output.has("particle_fields"))
        return;
    options.particleFields.clear();
    for (const std::string& name : output.strings("particle_fields"))
    {
        std::string known;
        bool found = false;
        for (const ParticleField field : allParticleFields())
        {
            if (!known.empty())
                known += ", ";
            known += particleFieldName(field);
            if (particleFieldName(field) == name)
            {
                if (options.has(field))
                    output.fail("particle_fields", "names '" + name + "' twice");
                options.particleFields.push_back(field);
                found = true;
            }
        }
        if (!found)
            output.fail("particle_fields", "has an unknown field '" + name + "' (known: " + known +
                                               "; t, id and the position are always written)");
    }
}
} // namespace

MeasurementOptions readMeasurementOptions(TableReader& top, OutputOptions& outputOptions)
{
    MeasurementOptions o;
    auto output = top.table("output");
    if (!output)
        return o;
    o.energy = output->boolean("energy", false);
    readParticleFields(*output, outputOptions);
    outputOptions.particlesCsv = output->boolean("particles_csv", true);
    outputOptions.contactsVtk = output->boolean("contacts", false);
    outputOptions.contactsCsv = output->boolean("contacts_csv", false);
    o.contacts = outputOptions.contactsVtk || outputOptions.contactsCsv;
    const std::optional<Vec3> low = output->optionalVec3("region_min");
    const std::optional<Vec3> high = output->optionalVec3("region_max");
    if (low.has_value() != high.has_value())
        output->fail(low ? "region_min" : "region_max",
                     "needs its partner: give both region_min and region_max [m] (the box's corners)");
    if (low)
    {
        if (!(low->x < high->x && low->y < high->y && low->z < high->z))
            output->fail("region_max", "must exceed region_min in every component (an axis-aligned box) [m]");
        o.region = true;
        o.regionMin = *low;
        o.regionMax = *high;
    }
    o.species = output->boolean("species", false);
    for (const Real id : output->numbers("track"))
    {
        if (!(id >= 0 && id <= 4294967294.0 && id == std::floor(id)))
            output->fail("track", "must be an array of particle ids (whole numbers in [0, 4294967294])");
        if (std::find(o.track.begin(), o.track.end(), std::uint32_t(id)) != o.track.end())
            output->fail("track", "names particle " + std::to_string(std::uint32_t(id)) + " twice");
        o.track.push_back(std::uint32_t(id));
    }
    output->finish();
    return o;
}

std::vector<dem::Zone> readZones(TableReader& top, const dem::World& world)
{
    std::vector<dem::Zone> zones;
    constexpr Real inf = std::numeric_limits<Real>::infinity();
    for (TableReader& t : top.arrayOfTables("zone"))
    {
        dem::Zone zone;
        zone.name = t.requiredString("name");
        if (zone.name.empty() || zone.name.find_first_of(",\"\n\r") != std::string::npos)
            t.fail("name",
                   "must be a non-empty name without commas, quotes or line breaks (a column of zones.csv)");
        for (const dem::Zone& other : zones)
            if (other.name == zone.name)
                t.fail("name", "'" + zone.name + "' names another [[zone]] too");
        zone.lo = t.vec3("min", {-inf, -inf, -inf});
        zone.hi = t.vec3("max", {inf, inf, inf});
        if (!(zone.lo.x < zone.hi.x && zone.lo.y < zone.hi.y && zone.lo.z < zone.hi.z))
            t.fail("max", "must exceed min in every component [m] (an axis-aligned box)");
        if (t.has("materials"))
        {
            const std::vector<std::string> names = t.strings("materials");
            if (names.empty())
                t.fail("materials", "must name at least one [[material]] (or leave the key out for all)");
            for (const std::string& name : names)
            {
                std::uint32_t found = std::uint32_t(world.materials.size());
                std::string known;
                for (std::size_t k = 0; k < world.materials.size(); ++k)
                {
                    if (!known.empty())
                        known += ", ";
                    known += world.materials[k].name;
                    if (world.materials[k].name == name)
                        found = std::uint32_t(k);
                }
                if (found == world.materials.size())
                    t.fail("materials", "names an unknown material '" + name +
                                            "' (the scene's [[material]] names: " + known + ")");
                if (std::find(zone.materials.begin(), zone.materials.end(), found) != zone.materials.end())
                    t.fail("materials", "names '" + name + "' twice");
                zone.materials.push_back(found);
            }
        }
        else
            for (std::size_t k = 0; k < world.materials.size(); ++k)
                zone.materials.push_back(std::uint32_t(k));
        t.finish();
        zones.push_back(std::move(zone));
    }
    return zones;
}

} // namespace veridem::io
