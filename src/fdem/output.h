// Output of the 2D FEM/DEM runs: ParaView .vtu per output step with a .pvd series (mesh,
// displacement, velocity, Cauchy stress), bodies.csv (centroid position and velocity per body) and
// energy.csv (energies and dissipated work). Written outside the step (STYLE.md: no output in step()).
#pragma once

#include "fdem/world.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace veridem::fdem
{

class OutputWriter
{
  public:
    /// Creates `directory` and opens bodies.csv and energy.csv. Throws InputError if it cannot.
    explicit OutputWriter(const std::filesystem::path& directory);
    ~OutputWriter();
    OutputWriter(const OutputWriter&) = delete;
    OutputWriter& operator=(const OutputWriter&) = delete;

    /// Writes frame_NNNNN.vtu, a row per body in bodies.csv and a row in energy.csv; `time` [s].
    void write(const World& world, Real time);
    /// Writes series.pvd listing the frames written so far (also done by the destructor).
    void finish();

  private:
    std::filesystem::path directory_;
    std::ofstream bodies_;
    std::ofstream energy_;
    std::vector<std::pair<Real, std::string>> frames_;
    bool finished_ = false;
};

/// Writes one .vtu file of the world's triangles (ASCII VTK XML UnstructuredGrid).
void writeVtu(const World& world, const std::filesystem::path& file);

} // namespace veridem::fdem
