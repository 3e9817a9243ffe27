#pragma once
// One word of a text file read as a number, for every reader of numeric text (Gmsh, STL/OBJ and
// triangle files, particle files). The readers add the file, the line and what they expected to
// their own error messages.

#include <optional>
#include <string_view>

namespace veridem::io
{

/// The whole of `word` as a double (decimal or scientific notation, an optional leading sign,
/// rounded to the nearest double; "inf" and "nan" are read as such, so callers that need a finite
/// value check it). std::nullopt when any character is left over, when the word is empty or not a
/// number, or when its magnitude is beyond the double range. Independent of the C locale.
std::optional<double> parseNumber(std::string_view word);

/// parseNumber, and std::nullopt also for infinities and NaN.
std::optional<double> parseFiniteNumber(std::string_view word);

} // namespace veridem::io
