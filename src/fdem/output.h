// Output of the 2D FEM/DEM runs: ParaView .vtu per output step with a .pvd series (mesh,
// displacement, velocity, Cauchy stress), bodies.csv (centroid position and velocity per body) and
// energy.csv (energies and dissipated work). Written outside the step (STYLE.md: no output in step()).
// Every write is checked (a failure throws OutputError naming the file); the CSVs are flushed and
// the .pvd is rewritten under a temporary name and renamed at every output, each .vtu likewise, so
// the files are complete at any moment. Numbers have round-trip precision.
#pragma once

#include "fdem/world.h"
#include "io/output_file.h"
#include "io/vtk_xml.h"

#include <filesystem>
#include <string>
#include <vector>

namespace veridem::fdem
{

class OutputWriter
{
  public:
    /// Creates `directory` and opens bodies.csv and energy.csv; without `vtk` no .vtu/.pvd.
    /// Throws OutputError if it cannot.
    OutputWriter(const std::filesystem::path& directory, bool vtk, io::VtkFormat format);
    OutputWriter(const OutputWriter&) = delete;
    OutputWriter& operator=(const OutputWriter&) = delete;

    /// Writes frame_NNNNN.vtu and series.pvd, a row per body in bodies.csv and a row in
    /// energy.csv; `time` [s].
    void write(const World& world, Real time);
    /// Closes the CSVs, checking the last writes.
    void finish();
    std::size_t framesWritten() const { return frames_; }

  private:
    std::filesystem::path directory_;
    bool vtk_;
    io::VtkFormat format_;
    io::AppendFile bodies_;
    io::AppendFile energy_;
    std::string series_; // the .pvd's DataSet lines
    std::size_t frames_ = 0;
};

/// Writes one .vtu file of the world's triangles (VTK XML UnstructuredGrid).
void writeVtu(const World& world, const std::filesystem::path& file, io::VtkFormat format);

} // namespace veridem::fdem
