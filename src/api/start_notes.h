// The notes a run prints as it starts (api::Simulation, on the first rank).
#pragma once

#include "io/dem_scene.h"

#include <string>

namespace veridem::api
{

/// Checks the scene's time step against the stability limit (dem/time_step.h): above it, an
/// InputError naming the scene and the limit unless `allowUnstable` (then a warning). With
/// `speak`, prints the time-step line and a warning when contacts get fewer than 20 steps.
void checkTimeStep(const io::DemScene& scene, const std::string& sceneName, bool allowUnstable, bool speak);

} // namespace veridem::api
