// The [domain] table of a 3D scene: the domain box and its periodic axes (dem/periodic.h), checked
// against the scene's particles, walls and measurements.
#pragma once

#include "dem/world.h"
#include "io/measurement_keys.h"
#include "io/toml_reader.h"

#include <optional>

namespace veridem::io
{

/// Reads the optional [domain] table of `top` into world.domain, once the walls and the initial
/// particles are in `world`. Refuses (InputError naming the key and line): a periodic axis whose
/// box edge is not positive, a wall that crosses a periodic face (only infinite planes parallel to
/// every periodic axis are allowed), a particle outside the box along a periodic axis, and the
/// measurements that do not see pairs through a periodic image yet (`measurements`).
/// Returns the table's reader if some axis is periodic (to name its line when the box later proves
/// too short for the contact search: dem::PeriodicBoxError).
std::optional<TableReader> readDomain(TableReader& top, dem::World& world,
                                      const MeasurementOptions& measurements);

} // namespace veridem::io
