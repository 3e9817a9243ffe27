#include "io/thermo_table.h"

#include "core/error.h"

namespace veridem::io
{

void ThermoValue::appendTo(std::string& out) const
{
    if (integer_)
        out += std::to_string(count_);
    else
        appendNumber(out, value_);
}

ThermoTable::ThermoTable(const std::filesystem::path& directory, const std::vector<std::string>& columns,
                         std::optional<std::uint64_t> resumeBytes, const std::string& name)
    : columns_(columns.size())
{
    const std::filesystem::path path = directory / name;
    if (resumeBytes && csv_.resume(path, *resumeBytes))
        return;
    csv_.open(path);
    std::string header;
    for (const auto& c : columns)
        header += (header.empty() ? "" : ",") + c;
    csv_.stream() << header << '\n';
    csv_.flush();
}

void ThermoTable::row(std::initializer_list<ThermoValue> values)
{
    row(std::vector<ThermoValue>(values));
}

void ThermoTable::row(const std::vector<ThermoValue>& values)
{
    if (values.size() != columns_)
        throw std::logic_error("a table row of " + std::to_string(values.size()) + " values for " +
                               std::to_string(columns_) + " columns");
    std::string text;
    for (const ThermoValue& v : values)
    {
        if (!text.empty())
            text += ',';
        v.appendTo(text);
    }
    text += '\n';
    csv_.stream() << text;
    csv_.flush();
}

} // namespace veridem::io
