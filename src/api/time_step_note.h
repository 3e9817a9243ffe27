// The start-up line on the time step: "veridem: dt = ... s; stability limit ... s (contact a-b);
// shortest contact time ... s, recommended dt <= tc/50 = ... s". When no contact can occur (a lone
// particle and no wall: the estimate is infinite and names no contact) it says so instead of
// printing "inf" and an empty name.
#pragma once

#include "dem/time_step.h"

#include <string>

namespace veridem::api
{

/// The line (without "\n") for the step `dt` [s] of a scene of `particles` spheres and `walls`
/// walls, given its estimate.
std::string timeStepNote(Real dt, const dem::TimeStepEstimate& estimate, std::size_t particles,
                         std::size_t walls);

} // namespace veridem::api
