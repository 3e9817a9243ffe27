// DIR/walls.csv of a DEM run: at each output, one row per wall with the time t [s], the wall's
// name, the total force ON the wall from its particle contacts [N] (fx, fy, fz: minus the sum of
// the contact forces on the particles) and its torque [N m] (tx, ty, tz) about the wall's load
// point (Wall::loadPoint, moved with the wall's displacement), from the last force evaluation
// (zero before the first step). Summed in contact-slot order: the same bits on any thread count
// (dem::wallLoad). Every write is checked (OutputError).
#pragma once

#include "dem/world.h"
#include "io/output_file.h"
#include "io/output_options.h"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace veridem::io
{

class WallLoadRecorder
{
  public:
    /// Creates DIR/walls.csv; with `resumeBytes` (a restart), continues an existing one cut to
    /// that size.
    /// Times: outputTime(step count, options.dt).
    WallLoadRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                     std::optional<std::uint64_t> resumeBytes = std::nullopt);
    /// One row per wall (world.wallContacts must record loads: setRecordLoads(true)).
    void record(const dem::World& world);
    std::uint64_t size() { return csv_.size(); }
    void close() { csv_.close(); }

  private:
    AppendFile csv_;
    Real dt_; // [s]
};

} // namespace veridem::io
