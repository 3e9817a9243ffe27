// DIR/thermo.csv of a DEM run: one row per output with the time t [s], the number of particles,
// the contacts touching (particle pairs and particle-wall, from the last force evaluation) and the
// translational and rotational kinetic energy [J]. Every write is checked (OutputError).
#pragma once

#include "dem/world.h"
#include "io/output_file.h"

#include <filesystem>

namespace veridem::io
{

class ThermoRecorder
{
  public:
    explicit ThermoRecorder(const std::filesystem::path& directory);
    void record(const dem::World& world);
    void close() { csv_.close(); }

  private:
    AppendFile csv_;
};

} // namespace veridem::io
