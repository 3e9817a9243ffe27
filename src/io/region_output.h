// DIR/region.csv of a DEM run with `[output] region_min/region_max` (dem/region_measures.h): one
// row per output with t [s], the particles whose centres are in the box, their particle-particle
// contacts (counted per member particle), the coordination number [-], the packing fraction [-]
// and the Love-Weber stress sxx, syy, szz, sxy, sxz, syz [Pa] (contact plus kinetic part, tension
// positive), then its kinetic part kinetic_sxx ... kinetic_syz [Pa]. Every write is checked
// (OutputError).
#pragma once

#include "dem/region_measures.h"
#include "io/output_options.h"
#include "io/thermo_table.h"

#include <filesystem>
#include <optional>

namespace veridem::io
{

class RegionRecorder
{
  public:
    /// The box [lo, hi] [m]; with `resumeBytes` (a restart), continues region.csv cut to that size.
    /// Times: outputTime(step count, options.dt).
    RegionRecorder(const std::filesystem::path& directory, const OutputOptions& options, const Vec3& lo,
                   const Vec3& hi, std::optional<std::uint64_t> resumeBytes = std::nullopt);
    void record(const dem::World& world, const std::vector<dem::ContactRecord>& contacts);
    std::uint64_t size() { return table_.size(); }
    void close() { table_.close(); }

  private:
    Real dt_; // [s]
    Vec3 lo_, hi_;
    ThermoTable table_;
};

} // namespace veridem::io
