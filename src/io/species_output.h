// The per-species files of a DEM run (dem/species_measures.h, docs/scene-format.md "Output"), one
// block of rows per output at the time t [s] = outputTime(step count, dt):
//   species.csv  `[output] species = true`: `t,material,count,mass,x,y,z`, one row per material:
//                its particles, their mass [kg] and centre of mass [m];
//   zones.csv    [[zone]] tables: `t,zone,material,count`, one row per zone and counted material;
//   tracked.csv  `[output] track = [ids]`: `t,id,x,y,z,vx,vy,vz`, one row per tracked particle
//                still in the run (position [m], velocity [m/s]).
// Every write is checked (OutputError) and flushed at every output; a restart continues each file
// cut to its size in the checkpoint.
#pragma once

#include "dem/species_measures.h"
#include "dem/world.h"
#include "io/output_file.h"
#include "io/output_options.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace veridem::io
{

/// One CSV file with a header, continued after a restart (the shared part of the recorders).
class SpeciesTable
{
  public:
    SpeciesTable(const std::filesystem::path& file, const std::string& header,
                 std::optional<std::uint64_t> resumeBytes);
    void write(const std::string& rows);
    std::uint64_t size() { return csv_.size(); }
    void close() { csv_.close(); }

  private:
    AppendFile csv_;
};

class SpeciesRecorder
{
  public:
    SpeciesRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                    std::optional<std::uint64_t> resumeBytes = std::nullopt);
    void record(const dem::World& world);
    std::uint64_t size() { return table_.size(); }
    void close() { table_.close(); }

  private:
    Real dt_; // [s]
    SpeciesTable table_;
};

class ZoneRecorder
{
  public:
    ZoneRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                 std::vector<dem::Zone> zones, std::optional<std::uint64_t> resumeBytes = std::nullopt);
    void record(const dem::World& world);
    std::uint64_t size() { return table_.size(); }
    void close() { table_.close(); }

  private:
    Real dt_; // [s]
    std::vector<dem::Zone> zones_;
    SpeciesTable table_;
};

class TrackRecorder
{
  public:
    TrackRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                  std::vector<std::uint32_t> ids, std::optional<std::uint64_t> resumeBytes = std::nullopt);
    void record(const dem::World& world);
    std::uint64_t size() { return table_.size(); }
    void close() { table_.close(); }

  private:
    Real dt_; // [s]
    std::vector<std::uint32_t> ids_;
    SpeciesTable table_;
};

} // namespace veridem::io
