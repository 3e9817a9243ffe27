// The start-up note on rolling friction: for every material pair whose contacts can occur (both
// materials on spheres, or one on a sphere and one on a wall) and that has a rolling model, the
// values the run will use, from the pair table (dem/materials.h): mixed from the two materials, or
// set by a [[pair]] entry (said so). The friction is printed in both conventions (a length mu_r
// and dimensionless mu_r' = mu_r / R_r) over the radii present, so the two are never confused;
// the viscous model prints its coefficient c_r.
#pragma once

#include "dem/world.h"

namespace veridem::api
{

/// The scene-file name of a rolling model (`rolling_model`) and its class in Ai et al. (2011).
const char* rollingModelName(dem::RollingModel model);

/// Prints the note on stderr, one line per pair.
void printRollingFrictionNote(const dem::World& world);

} // namespace veridem::api
