// Output of a DEM run, written between steps by the driver (never inside the step):
//   DIR/particles.csv        t,id,x,y,z,vx,vy,vz,wx,wy,wz (SI units) at every output time (id: the
//                            particle's stable id, ParticleStore::id; positions wrapped into the
//                            box along periodic axes, dem/periodic.h), each
//                            number in its shortest round-trip form (reads back to the same bits)
//   DIR/particles_NNNNNN.vtp ParaView PolyData per output (id, radius, velocity, angular_velocity;
//                            each file its own particle count),
//                            ASCII or appended zlib-compressed binary (VtkFormat)
//   DIR/particles.pvd        the series, rewritten under a temporary name and renamed at every
//                            output, so it is complete at any moment (also after a kill)
// After a restart (ParticleRecorder::Resume) the frame numbers continue from the checkpoint's, the
// CSV continues an existing particles.csv cut to its size at the checkpoint (else a new one), and
// the .pvd lists the earlier frames whose .vtp files are in DIR.
// Every write is checked: a failure throws OutputError naming the file and the run stops. The CSV
// is flushed at every output, and each .vtp is written under a temporary name and renamed.
#pragma once

#include "dem/world.h"
#include "io/output_file.h"
#include "io/vtk_xml.h"

#include <filesystem>
#include <string>
#include <vector>

namespace veridem::io
{

class ParticleRecorder
{
  public:
    /// Where a restarted run continues: the output times of the frames written before the
    /// checkpoint [s] and the size of particles.csv then [bytes].
    struct Resume
    {
        std::vector<double> frameTimes;
        std::uint64_t csvBytes = 0;
    };
    /// Without `vtk`, only the CSV is written.
    ParticleRecorder(const std::filesystem::path& directory, bool vtk, VtkFormat format,
                     const Resume* resume = nullptr);
    ParticleRecorder(const ParticleRecorder&) = delete;
    ParticleRecorder& operator=(const ParticleRecorder&) = delete;
    void record(const dem::World& world);
    /// Closes the CSV, checking the last writes.
    void close();
    std::size_t framesWritten() const { return frameTimes_.size(); }
    const std::vector<double>& frameTimes() const { return frameTimes_; }
    /// Size of particles.csv [bytes], for a checkpoint.
    std::uint64_t csvBytes() { return csv_.size(); }

  private:
    void writeVtp(const dem::World& world, const std::filesystem::path& path) const;
    void writePvd() const;

    std::filesystem::path directory_;
    bool vtk_;
    VtkFormat format_;
    AppendFile csv_;
    std::vector<double> frameTimes_;
    std::vector<bool> listed_; // per frame: in the .pvd (false: written before a restart, not in DIR)
};

} // namespace veridem::io
