// Strict reading of TOML scene tables: every key that is read is recorded, and finish() rejects
// any key that was not, naming the file, the line and the nearest valid key. Errors are thrown as
// veridem::InputError with a one-line message.
#pragma once

#include "core/vec3.h"

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace veridem::io
{

class TableReader
{
  public:
    /// `where` names the table in messages, e.g. "[[sphere]] #2"; `file` is the scene path.
    TableReader(const toml::table& table, std::string where, std::string file);

    bool has(std::string_view key) const;

    Real number(std::string_view key, Real defaultValue);
    Real requiredNumber(std::string_view key);
    std::optional<Real> optionalNumber(std::string_view key);
    std::int64_t integer(std::string_view key, std::int64_t defaultValue);
    bool boolean(std::string_view key, bool defaultValue);
    std::string string(std::string_view key, std::string_view defaultValue);
    std::string requiredString(std::string_view key);
    /// A string that must be one of `choices`.
    std::string choice(std::string_view key, std::string_view defaultValue,
                       const std::vector<std::string>& choices);
    Vec3 vec3(std::string_view key, Vec3 defaultValue);
    Vec3 requiredVec3(std::string_view key);
    std::optional<Vec3> optionalVec3(std::string_view key);
    /// An array of rows of finite numbers, e.g. [[0, 1.5], [2, 3]], every row of the same length,
    /// one of `widths`; empty if the key is absent.
    std::vector<std::vector<Real>> numberRows(std::string_view key, const std::vector<std::size_t>& widths);
    /// An array of finite numbers (empty if the key is absent).
    std::vector<Real> numbers(std::string_view key);
    /// An array of strings (empty if the key is absent).
    std::vector<std::string> strings(std::string_view key);
    /// An array of booleans (empty if the key is absent).
    std::vector<bool> booleans(std::string_view key);

    std::optional<TableReader> table(std::string_view key);
    std::vector<TableReader> arrayOfTables(std::string_view key);

    /// Throws on the first key that no accessor asked for.
    void finish() const;

    /// Throws an InputError located at `key` (or at the table if the key is absent).
    [[noreturn]] void fail(std::string_view key, std::string_view message) const;

    /// Throws unless value > 0 (names key, value and unit).
    void requirePositive(std::string_view key, Real value, std::string_view unit) const;
    void requireNonNegative(std::string_view key, Real value, std::string_view unit) const;

    const std::string& file() const { return file_; }
    const std::string& where() const { return where_; }

  private:
    std::string missingKeyMessage(std::string_view key) const;
    std::string location(const toml::node* node) const;
    const toml::node* node(std::string_view key);

    const toml::table* table_;
    std::string where_;
    std::string file_;
    std::set<std::string, std::less<>> used_;
};

/// The [simulation] keys shared by the 3D and 2D scenes have one name each (docs/scene-format.md):
/// a key of the other vocabulary ('time_step', 'end_time', 'timestep', 'write_vtk') is refused
/// with its line and the key to use instead.
void refuseRenamedKeys(const TableReader& simulation);

/// Largest scene file read [bytes]; bulk positions go in [[particles]] files.
inline constexpr std::uintmax_t kMaxSceneFileBytes = 64u << 20;

/// Parses a TOML file; a syntax error becomes an InputError with file:line:column. A missing path,
/// a directory, a device or a file above kMaxSceneFileBytes is refused before reading.
toml::table parseFile(const std::string& path);

/// Parses TOML text (checkTomlText first); `source` names it in messages.
toml::table parseText(std::string_view text, const std::string& source);

/// Edit distance used to suggest the nearest valid key.
std::size_t editDistance(std::string_view a, std::string_view b);

} // namespace veridem::io
