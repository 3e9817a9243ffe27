// Output of the 2D FEM/DEM runs: ParaView .vtu per output step with a .pvd series (mesh,
// displacement, velocity, Cauchy stress), bodies.csv (centroid position and velocity per body),
// energy.csv (energies and dissipated work) and thermo.csv (counts and kinetic energy, the 3D
// runs' summary file: fdem/output_thermo.h). After a restart (OutputWriter::Resume) the frame
// numbers continue, each CSV continues an existing file cut to its size at the checkpoint (else a
// new one) and the .pvd lists the earlier frames whose .vtu files are in the directory. Written outside the
// step (STYLE.md: no output in step()). Every write is checked (a failure throws OutputError naming the
// file); the CSVs are flushed and the .pvd is rewritten under a temporary name and renamed at every output,
// each .vtu likewise, so the files are complete at any moment. Numbers have round-trip precision; each
// CSV starts with the time t [s] after the settling, step count x dt (io::outputTime), as the 3D files.
#pragma once

#include "fdem/world.h"
#include "io/output_file.h"
#include "io/thermo_table.h"
#include "io/vtk_xml.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace veridem::fdem
{

class OutputWriter
{
  public:
    /// Where a restarted run continues: the output times of the frames written before the
    /// checkpoint [s] and the sizes of bodies.csv, energy.csv and thermo.csv then [bytes].
    struct Resume
    {
        std::vector<double> frameTimes;
        std::vector<std::uint64_t> csvBytes; // bodies, energy, thermo
    };
    /// Creates `directory` and opens bodies.csv, energy.csv and thermo.csv; without `vtk` no
    /// .vtu/.pvd. Throws OutputError if it cannot.
    OutputWriter(const std::filesystem::path& directory, bool vtk, io::VtkFormat format,
                 const Resume* resume = nullptr);
    OutputWriter(const OutputWriter&) = delete;
    OutputWriter& operator=(const OutputWriter&) = delete;

    /// Writes frame_NNNNN.vtu and series.pvd, a row per body in bodies.csv and a row in
    /// energy.csv; `time` [s].
    void write(const World& world, Real time);
    /// Closes the CSVs, checking the last writes.
    void finish();
    std::size_t framesWritten() const { return frameTimes_.size(); }
    /// What a checkpoint records to continue these files (sizes after flushing).
    Resume resumeState();

  private:
    void writePvd();

    std::filesystem::path directory_;
    bool vtk_;
    io::VtkFormat format_;
    io::AppendFile bodies_;
    io::AppendFile energy_;
    std::optional<io::ThermoTable> thermo_;
    std::vector<double> frameTimes_; // output time of every frame written [s]
    std::vector<bool> listed_;       // per frame: in the .pvd (false: before a restart, not in DIR)
};

/// Writes fragments.csv: one row per fragment (fdem/fragments.h), largest first: fragment, body,
/// name, triangles, area [m^2], mass [kg/m], x, y [m] (centroid), equivalent_diameter [m], and
/// passing [1] (the mass fraction of the fragments of this body no larger: the size distribution).
void writeFragments(const World& world, const std::filesystem::path& file);

/// Writes one .vtu file of the world's triangles (VTK XML UnstructuredGrid).
void writeVtu(const World& world, const std::filesystem::path& file, io::VtkFormat format);

} // namespace veridem::fdem
