// The `[output]` table of a 3D scene: which measurements a run writes beyond the particle output
// (docs/scene-format.md, docs/measurements.md).
#pragma once

#include "core/vec3.h"
#include "io/toml_reader.h"

namespace veridem::io
{

struct MeasurementOptions
{
    bool energy = false;       // energy ledger columns in thermo.csv (a diagnostic pass every step)
    bool contacts = false;     // contact network: DIR/contacts_<n>.vtp and DIR/contacts.pvd
    bool region = false;       // DIR/region.csv for the box [regionMin, regionMax]
    Vec3 regionMin, regionMax; // corners of the axis-aligned measuring box [m]
};

/// Reads the optional `[output]` table of `top` (defaults if absent); bad values are InputErrors
/// naming the key.
MeasurementOptions readMeasurementOptions(TableReader& top);

} // namespace veridem::io
