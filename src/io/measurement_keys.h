// The `[output]` table of a 3D scene: which measurements a run writes beyond the particle output
// (docs/scene-format.md, docs/measurements.md).
#pragma once

#include "core/vec3.h"
#include "dem/species_measures.h"
#include "dem/world.h"
#include "io/output_options.h"
#include "io/toml_reader.h"

namespace veridem::io
{

struct MeasurementOptions
{
    bool energy = false;       // energy ledger columns in thermo.csv (a diagnostic pass every step)
    bool contacts = false;     // contact network: .vtp (contacts) and/or .csv (contacts_csv) per output
    bool region = false;       // DIR/region.csv for the box [regionMin, regionMax]
    Vec3 regionMin, regionMax; // corners of the axis-aligned measuring box [m]
    bool species = false;      // DIR/species.csv: each material's count, mass, centre of mass
    std::vector<std::uint32_t> track; // ids of the particles in DIR/tracked.csv
    std::vector<dem::Zone> zones;     // [[zone]] tables: DIR/zones.csv
};

/// Reads the optional `[output]` table of `top` (defaults if absent); bad values are InputErrors
/// naming the key. Its file choices (particle_fields, particles_csv, contacts, contacts_csv) go
/// to `output`.
MeasurementOptions readMeasurementOptions(TableReader& top, OutputOptions& output);

/// The [[zone]] tables of `top` (after the materials are known): a material name that `world` does
/// not define is an InputError naming the key `materials` and its line.
std::vector<dem::Zone> readZones(TableReader& top, const dem::World& world);

} // namespace veridem::io
