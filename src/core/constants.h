#pragma once

#include <numbers>

namespace veridem
{
inline constexpr double kPi = std::numbers::pi;
/// Standard gravity used by the paper's tests [m/s^2].
inline constexpr double kStandardGravity = 9.81;
inline constexpr double degToRad(double deg)
{
    return deg * kPi / 180.0;
}
} // namespace veridem
