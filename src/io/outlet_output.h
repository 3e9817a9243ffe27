// DIR/outlets.csv of a DEM run with [[outlet]] tables: at every output time one row per outlet,
// `t,outlet,count,mass`: the time [s], the outlet's name, and the particles and mass [kg] it has
// removed since the start of the run (cumulative). Every write is checked (OutputError), and the
// file is flushed at every output.
#pragma once

#include "dem/particle_flow.h"
#include "io/output_file.h"
#include "io/output_options.h"

#include <filesystem>
#include <optional>

namespace veridem::io
{

class OutletRecorder
{
  public:
    /// With `resumeBytes` (a restart), continues an existing outlets.csv cut to that size.
    /// Times: outputTime(step count, options.dt).
    OutletRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                   std::optional<std::uint64_t> resumeBytes = std::nullopt);
    /// One row per outlet at the world's time; `outlets`: their totals.
    void record(const dem::World& world, const std::vector<dem::Outlet>& outlets);
    std::uint64_t size() { return csv_.size(); }
    void close() { csv_.close(); }

  private:
    AppendFile csv_;
    Real dt_; // [s]
};

} // namespace veridem::io
