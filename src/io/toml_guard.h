// A lexical check of a TOML scene before the TOML library parses it. Debian's toml++ 3.3.0 reaches
// undefined behaviour on some malformed input (a non-ASCII character in a bare key, upstream
// marzer/tomlplusplus#295 and #190; table headers such as `[[*a]]`, #301). These are refused here
// with a one-line InputError naming the file and the line, so the library never sees them.
#pragma once

#include <string>
#include <string_view>

namespace veridem::io
{

/// Throws InputError "file:line: ..." on text that is not UTF-8 or holds a control character other
/// than tab, CR and LF; on a byte >= 0x80 outside strings and comments (TOML allows non-ASCII text
/// only there); on a quote that does not start a key or a value (not at the line start or after
/// = [ , { .); and on a table header that is not `[key(.key)*]` or `[[key(.key)*]]` with bare keys
/// of A-Z a-z 0-9 _ - or quoted keys.
void checkTomlText(std::string_view text, const std::string& file);

} // namespace veridem::io
