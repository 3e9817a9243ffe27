// DIR/thermo.csv of a DEM run (io/thermo_table.h): one row per output with the time t [s], the
// number of particles, the contacts touching (particle pairs and particle-wall, from the last force
// evaluation) and the translational and rotational kinetic energy [J]. Every write is checked
// (OutputError).
#pragma once

#include "dem/world.h"
#include "io/thermo_table.h"

#include <filesystem>
#include <optional>

namespace veridem::io
{

class ThermoRecorder
{
  public:
    /// With `resumeBytes` (a restart), continues an existing thermo.csv cut to that size.
    explicit ThermoRecorder(const std::filesystem::path& directory,
                            std::optional<std::uint64_t> resumeBytes = std::nullopt);
    void record(const dem::World& world);
    std::uint64_t size() { return table_.size(); }
    void close() { table_.close(); }

  private:
    ThermoTable table_;
};

} // namespace veridem::io
