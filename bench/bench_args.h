// Command-line helpers shared by the benchmark programs.
#pragma once

#include <chrono>
#include <exception>
#include <stdexcept>
#include <string>

namespace veridem::bench
{

/// The option's value as a whole number in [low, high]; throws std::runtime_error naming the
/// option, the range and the text otherwise.
inline long long wholeNumber(const std::string& option, const std::string& text, long long low,
                             long long high)
{
    std::size_t used = 0;
    long long value = 0;
    try
    {
        value = std::stoll(text, &used);
    }
    catch (const std::exception&)
    {
        used = 0;
    }
    if (used != text.size() || value < low || value > high)
        throw std::runtime_error(option + ": expected a whole number from " + std::to_string(low) + " to " +
                                 std::to_string(high) + ", got '" + text + "'");
    return value;
}

/// Wall-clock seconds since `since`.
inline double seconds(std::chrono::steady_clock::time_point since)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

} // namespace veridem::bench
