// Reading a [[particles]] table of a 3D scene: a text file of spheres, one per line, its columns
// named by a header line (docs/scene-format.md lists the names, aliases and units), so that the
// state file a run writes (io/particle_state.h, DIR/state.csv) and plain packing files such as
// `Radius[m] PosX[m] PosY[m] PosZ[m]` both load; a file without a header holds 'x y z' lines.
// Columns are separated by commas, tabs or spaces; '#' starts a comment line. Bad input is an
// InputError naming the file, the line and what was expected.
#pragma once

#include "dem/world.h"
#include "io/toml_reader.h"

#include <cstddef>
#include <string>
#include <vector>

namespace veridem::io
{

/// The particles [first, first + count) of the store whose ids a file's `id` column gave.
struct GivenIds
{
    std::size_t first = 0;
    std::size_t count = 0;
    std::string file;
};

/// Reads a [[particles]] table and adds its spheres to `world` (in file order); `reserved` spheres
/// are still to come from other tables (counted against maxSphereCount() line by line, so a huge
/// file or a device cannot exhaust memory). Relative paths are relative to `sceneFile`. With an
/// `id` column, the ids it gave (unique within the file) are appended to `given`.
void readParticleFile(TableReader& t, dem::World& world, const std::string& sceneFile, double reserved,
                      std::vector<GivenIds>& given);

/// Numbers the particles whose ids no file gave, in store order from 0, skipping the ids the files
/// gave; refuses an id given by two files. Without `given`, the ids stay 0, 1, 2, ... in input
/// order.
void numberParticles(dem::ParticleStore& particles, const std::vector<GivenIds>& given);

} // namespace veridem::io
