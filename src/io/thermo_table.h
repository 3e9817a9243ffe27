// DIR/thermo.csv, the one-row-per-output summary of a run, shared by the 3D DEM (io/thermo_output.h)
// and the 2D FEM/DEM (fdem/output_thermo.h) drivers: a header of column names, then one row per
// output, counts as integers and quantities with round-trip precision. Every write is checked
// (OutputError); the file is flushed at every row, so it is complete at any moment.
#pragma once

#include "io/output_file.h"

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace veridem::io
{

/// One cell of a row: a count or a real number.
class ThermoValue
{
  public:
    ThermoValue(std::uint64_t count) : count_(count), integer_(true) {}
    ThermoValue(double value) : value_(value) {}
    void appendTo(std::string& out) const;

  private:
    double value_ = 0;
    std::uint64_t count_ = 0;
    bool integer_ = false;
};

class ThermoTable
{
  public:
    /// Creates DIR/`name` with `columns` as its header; with `resumeBytes` (a restart), continues
    /// an existing file cut to that size instead if there is one.
    ThermoTable(const std::filesystem::path& directory, const std::vector<std::string>& columns,
                std::optional<std::uint64_t> resumeBytes = std::nullopt,
                const std::string& name = "thermo.csv");
    /// Appends a row (as many values as columns) and flushes.
    void row(std::initializer_list<ThermoValue> values);
    void row(const std::vector<ThermoValue>& values);
    /// The file's size [bytes], for a checkpoint.
    std::uint64_t size() { return csv_.size(); }
    void close() { csv_.close(); }

  private:
    AppendFile csv_;
    std::size_t columns_;
};

} // namespace veridem::io
