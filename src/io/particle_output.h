// Output of a DEM run, written between steps by the driver (never inside the step):
//   DIR/particles.csv        t,id,x,y,z,vx,vy,vz,wx,wy,wz (SI units) at every output time
//   DIR/particles_NNNNNN.vtp ParaView PolyData per output (radius, velocity, angular_velocity)
//   DIR/particles.pvd        the series; rewritten every 50 outputs and when the recorder is
//                            destroyed (also on a blow-up), so a run that stops early still
//                            leaves a readable series
// Files are flushed at every output, so everything written before a blow-up stays readable.
#pragma once

#include "dem/world.h"

#include <filesystem>
#include <fstream>
#include <vector>

namespace veridem::io
{

class ParticleRecorder
{
  public:
    ParticleRecorder(const std::filesystem::path& directory, bool writeVtk);
    ~ParticleRecorder(); // completes the .pvd series (also when a run stops on an error)
    ParticleRecorder(const ParticleRecorder&) = delete;
    ParticleRecorder& operator=(const ParticleRecorder&) = delete;
    void record(const dem::World& world);
    std::size_t framesWritten() const { return frameTimes_.size(); }

  private:
    void writeVtp(const dem::World& world, const std::filesystem::path& path) const;
    void writePvd() const;

    std::filesystem::path directory_;
    bool writeVtk_;
    std::ofstream csv_;
    std::vector<double> frameTimes_;
};

} // namespace veridem::io
