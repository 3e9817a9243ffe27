#include "io/measurement_keys.h"

#include <algorithm>

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
            known += (known.empty() ? "" : ", ") + std::string(particleFieldName(field));
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
    output->finish();
    return o;
}

} // namespace veridem::io
