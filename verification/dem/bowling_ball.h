// The bowling-ball case (bowling_ball.cpp) as a set-up that other cases run on another floor.
#pragma once

#include "support.h"

#include <vector>

namespace veridem::verify
{

/// Steps between the centre positions recorded into a path [-].
inline constexpr std::uint64_t kPathStride = 100;

/// The bowling ball launched on `floor` (z = 0, normal +z) with its checked quantities; if `path`
/// is given, the ball's centre [m] every kPathStride steps is appended to it.
CaseResult bowlingBall(const CaseContext& context, const dem::Wall& floor, std::vector<Vec3>* path);

} // namespace veridem::verify
