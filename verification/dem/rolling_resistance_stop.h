// The type A rolling-resistance stop (rolling_resistance_stop.cpp) as a set-up that other cases
// run on another floor.
#pragma once

#include "support.h"

#include <vector>

namespace veridem::verify
{

/// A ball rolling at 0.1 m/s on `floor` (z = 0, normal +z) under the type A rolling resistance of
/// the paper's flat ball: returns where it stopped [m] and sets its drift over the next 5 s [m];
/// if `path` is given, the centre [m] every kPathStride steps (bowling_ball.h) is appended.
Real rollingStopDistance(const CaseContext& context, const dem::Wall& floor, Real& driftAfterStop,
                         std::vector<Vec3>* path);

} // namespace veridem::verify
