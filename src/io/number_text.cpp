#include "io/number_text.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace veridem::io
{

std::optional<double> parseNumber(std::string_view word)
{
    if (!word.empty() && word[0] == '+') // from_chars accepts '-' only
    {
        word.remove_prefix(1);
        if (!word.empty() && (word[0] == '-' || word[0] == '+'))
            return std::nullopt;
    }
    double value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size())
        return std::nullopt;
    return value;
}

std::optional<double> parseFiniteNumber(std::string_view word)
{
    const std::optional<double> value = parseNumber(word);
    if (value && !std::isfinite(*value))
        return std::nullopt;
    return value;
}

} // namespace veridem::io
