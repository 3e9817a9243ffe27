#include "io/measurement_keys.h"

namespace veridem::io
{

MeasurementOptions readMeasurementOptions(TableReader& top)
{
    MeasurementOptions o;
    auto output = top.table("output");
    if (!output)
        return o;
    o.energy = output->boolean("energy", false);
    o.contacts = output->boolean("contacts", false);
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
