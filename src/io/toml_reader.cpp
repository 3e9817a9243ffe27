#include "io/toml_reader.h"

#include "core/error.h"
#include "io/toml_guard.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace veridem::io
{

namespace
{
const char* typeName(const toml::node& n)
{
    switch (n.type())
    {
    case toml::node_type::string:
        return "a string";
    case toml::node_type::integer:
        return "an integer";
    case toml::node_type::floating_point:
        return "a number";
    case toml::node_type::boolean:
        return "a boolean";
    case toml::node_type::array:
        return "an array";
    case toml::node_type::table:
        return "a table";
    default:
        return "a date/time";
    }
}
} // namespace

std::string TableReader::missingKeyMessage(std::string_view key) const
{
    std::ostringstream s;
    s << location(nullptr) << ": " << where_ << ": missing required key '" << key << "'";
    for (const auto& [present, value] : *table_)
        if (present.str() != key &&
            editDistance(present.str(), key) <= std::max<std::size_t>(2, key.size() / 3))
        {
            s << " (line " << value.source().begin.line << " has '" << present.str() << "': a typo?)";
            break;
        }
    return s.str();
}

std::size_t editDistance(std::string_view a, std::string_view b)
{
    std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

toml::table parseFile(const std::string& path)
{
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status))
        throw InputError(path + ": no such scene file");
    if (std::filesystem::is_directory(status))
        throw InputError(path + ": is a directory, not a scene file");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(path + ": is not a regular file (a scene is a TOML text file)");
    const auto size = std::filesystem::file_size(path, error);
    if (error || size > kMaxSceneFileBytes)
        throw InputError(path + ": the scene file is larger than " +
                         std::to_string(kMaxSceneFileBytes >> 20) +
                         " MiB (bulk particle positions belong in a [[particles]] file)");
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!in || !in.read(text.data(), static_cast<std::streamsize>(size)))
        throw InputError(path + ": cannot read the scene file");
    return parseText(text, path);
}

toml::table parseText(std::string_view text, const std::string& source)
{
    checkTomlText(text, source); // before toml++ sees it: input on which the library misbehaves
    try
    {
        return toml::parse(text, source);
    }
    catch (const toml::parse_error& e)
    {
        std::ostringstream s;
        s << source;
        if (e.source().begin.line > 0)
            s << ":" << e.source().begin.line << ":" << e.source().begin.column;
        s << ": TOML syntax error: " << e.description();
        throw InputError(s.str());
    }
}

TableReader::TableReader(const toml::table& table, std::string where, std::string file)
    : table_(&table), where_(std::move(where)), file_(std::move(file))
{
}

std::string TableReader::location(const toml::node* n) const
{
    const toml::node* at = n ? n : table_;
    std::ostringstream s;
    s << file_;
    if (at->source().begin.line > 0)
        s << ":" << at->source().begin.line;
    return s.str();
}

bool TableReader::has(std::string_view key) const
{
    return table_->contains(key);
}

const toml::node* TableReader::node(std::string_view key)
{
    used_.insert(std::string(key));
    return table_->get(key);
}

void TableReader::fail(std::string_view key, std::string_view message) const
{
    const toml::node* n = table_->get(key);
    std::ostringstream s;
    s << location(n) << ": " << where_ << ": '" << key << "' " << message;
    throw InputError(s.str());
}

void TableReader::requirePositive(std::string_view key, Real value, std::string_view unit) const
{
    if (!(value > 0) || !std::isfinite(value))
    {
        std::ostringstream s;
        s << "must be > 0 " << unit << " (got " << value << ")";
        fail(key, s.str());
    }
}

void TableReader::requireNonNegative(std::string_view key, Real value, std::string_view unit) const
{
    if (!(value >= 0) || !std::isfinite(value))
    {
        std::ostringstream s;
        s << "must be >= 0 " << unit << " (got " << value << ")";
        fail(key, s.str());
    }
}

std::optional<Real> TableReader::optionalNumber(std::string_view key)
{
    const toml::node* n = node(key);
    if (!n)
        return std::nullopt;
    if (const auto v = n->value<double>(); v && (n->is_floating_point() || n->is_integer()))
    {
        if (!std::isfinite(*v))
            fail(key, "must be a finite number");
        return *v;
    }
    fail(key, std::string("must be a number, got ") + typeName(*n));
}

Real TableReader::number(std::string_view key, Real defaultValue)
{
    return optionalNumber(key).value_or(defaultValue);
}

Real TableReader::requiredNumber(std::string_view key)
{
    if (auto v = optionalNumber(key))
        return *v;
    throw InputError(missingKeyMessage(key));
}

std::int64_t TableReader::integer(std::string_view key, std::int64_t defaultValue)
{
    const toml::node* n = node(key);
    if (!n)
        return defaultValue;
    if (!n->is_integer())
        fail(key, std::string("must be an integer, got ") + typeName(*n));
    return *n->value<std::int64_t>();
}

bool TableReader::boolean(std::string_view key, bool defaultValue)
{
    const toml::node* n = node(key);
    if (!n)
        return defaultValue;
    if (!n->is_boolean())
        fail(key, std::string("must be true or false, got ") + typeName(*n));
    return *n->value<bool>();
}

std::string TableReader::string(std::string_view key, std::string_view defaultValue)
{
    const toml::node* n = node(key);
    if (!n)
        return std::string(defaultValue);
    if (!n->is_string())
        fail(key, std::string("must be a string, got ") + typeName(*n));
    return *n->value<std::string>();
}

std::string TableReader::requiredString(std::string_view key)
{
    if (!has(key))
    {
        throw InputError(missingKeyMessage(key));
    }
    return string(key, "");
}

std::string TableReader::choice(std::string_view key, std::string_view defaultValue,
                                const std::vector<std::string>& choices)
{
    std::string value = string(key, defaultValue);
    if (std::find(choices.begin(), choices.end(), value) == choices.end())
    {
        std::ostringstream s;
        s << "must be one of";
        for (const auto& c : choices)
            s << " \"" << c << "\"";
        s << " (got \"" << value << "\")";
        fail(key, s.str());
    }
    return value;
}

std::optional<Vec3> TableReader::optionalVec3(std::string_view key)
{
    const toml::node* n = node(key);
    if (!n)
        return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 3)
        fail(key, "must be an array of 3 numbers [x, y, z]");
    Real c[3];
    for (std::size_t i = 0; i < 3; ++i)
    {
        const auto v = (*a)[i].value<double>();
        if (!v || !std::isfinite(*v))
            fail(key, "must be an array of 3 finite numbers [x, y, z]");
        c[i] = *v;
    }
    return Vec3{c[0], c[1], c[2]};
}

std::vector<std::vector<Real>> TableReader::numberRows(std::string_view key,
                                                       const std::vector<std::size_t>& widths)
{
    std::vector<std::vector<Real>> rows;
    const toml::node* n = node(key);
    if (!n)
        return rows;
    std::string expected;
    for (const std::size_t w : widths)
        expected += (expected.empty() ? "" : " or ") + std::to_string(w);
    const toml::array* a = n->as_array();
    if (!a || a->empty())
        fail(key, "must be a non-empty array of rows of " + expected + " numbers, e.g. [[0, 1], [2, 3]]");
    for (const auto& element : *a)
    {
        const toml::array* row = element.as_array();
        if (!row || std::find(widths.begin(), widths.end(), row->size()) == widths.end())
            fail(key, "must be an array of rows of " + expected + " numbers each; row " +
                          std::to_string(rows.size() + 1) + " is not");
        std::vector<Real> values;
        for (const auto& cell : *row)
        {
            const auto v = cell.value<double>();
            if (!v || !std::isfinite(*v))
                fail(key, "row " + std::to_string(rows.size() + 1) + " must hold finite numbers");
            values.push_back(*v);
        }
        if (!rows.empty() && values.size() != rows.front().size())
            fail(key, "rows must all have the same length");
        rows.push_back(std::move(values));
    }
    return rows;
}

std::vector<Real> TableReader::numbers(std::string_view key)
{
    std::vector<Real> out;
    const toml::node* n = node(key);
    if (!n)
        return out;
    const toml::array* a = n->as_array();
    if (!a || a->empty())
        fail(key, "must be a non-empty array of numbers");
    for (const auto& element : *a)
    {
        const auto v = element.value<double>();
        if (!v || !std::isfinite(*v))
            fail(key, "must be an array of finite numbers");
        out.push_back(*v);
    }
    return out;
}

std::vector<std::string> TableReader::strings(std::string_view key)
{
    std::vector<std::string> out;
    const toml::node* n = node(key);
    if (!n)
        return out;
    const toml::array* a = n->as_array();
    if (!a || a->empty())
        fail(key, "must be a non-empty array of strings");
    for (const auto& element : *a)
    {
        const auto v = element.value<std::string>();
        if (!v)
            fail(key, "must be an array of strings");
        out.push_back(*v);
    }
    return out;
}

std::vector<bool> TableReader::booleans(std::string_view key)
{
    std::vector<bool> out;
    const toml::node* n = node(key);
    if (!n)
        return out;
    const toml::array* a = n->as_array();
    if (!a || a->empty())
        fail(key, "must be a non-empty array of booleans (true or false)");
    for (const auto& element : *a)
    {
        const auto v = element.value<bool>();
        if (!v || !element.is_boolean())
            fail(key, "must be an array of booleans (true or false)");
        out.push_back(*v);
    }
    return out;
}

Vec3 TableReader::vec3(std::string_view key, Vec3 defaultValue)
{
    return optionalVec3(key).value_or(defaultValue);
}

Vec3 TableReader::requiredVec3(std::string_view key)
{
    if (auto v = optionalVec3(key))
        return *v;
    throw InputError(missingKeyMessage(key));
}

std::optional<TableReader> TableReader::table(std::string_view key)
{
    const toml::node* n = node(key);
    if (!n)
        return std::nullopt;
    if (!n->is_table())
        fail(key, std::string("must be a table [") + std::string(key) + "], got " + typeName(*n));
    return TableReader(*n->as_table(), "[" + std::string(key) + "]", file_);
}

std::vector<TableReader> TableReader::arrayOfTables(std::string_view key)
{
    std::vector<TableReader> out;
    const toml::node* n = node(key);
    if (!n)
        return out;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables())
        fail(key, "must be written as [[" + std::string(key) + "]] tables");
    std::size_t index = 0;
    for (const auto& element : *a)
        out.emplace_back(*element.as_table(), "[[" + std::string(key) + "]] #" + std::to_string(++index),
                         file_);
    return out;
}

void refuseRenamedKeys(const TableReader& simulation)
{
    static const std::pair<const char*, const char*> kRenamed[] = {
        {"time_step", "dt"}, {"timestep", "dt"}, {"end_time", "duration"}, {"write_vtk", "vtk"}};
    for (const auto& [other, key] : kRenamed)
        if (simulation.has(other))
            simulation.fail(other, std::string("is not a key: use '") + key +
                                       "' (the same name in 2D and 3D scenes, docs/scene-format.md)");
}

void TableReader::finish() const
{
    for (const auto& [key, value] : *table_)
    {
        if (used_.count(key.str()))
            continue;
        std::string nearest;
        std::size_t best = 1000;
        for (const auto& candidate : used_)
        {
            const std::size_t d = editDistance(key.str(), candidate);
            if (d < best)
            {
                best = d;
                nearest = candidate;
            }
        }
        std::ostringstream s;
        s << location(&value) << ": " << where_ << ": unknown key '" << key.str() << "'";
        if (!nearest.empty() && best <= std::max<std::size_t>(2, key.str().size() / 3))
            s << " (did you mean '" << nearest << "'?)";
        else if (!used_.empty())
        {
            s << " (valid keys:";
            for (const auto& c : used_)
                s << " " << c;
            s << ")";
        }
        throw InputError(s.str());
    }
}

} // namespace veridem::io
