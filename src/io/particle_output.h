// Output of a DEM run, written between steps by the driver (never inside the step):
//   DIR/particles.csv        t,id,x,y,z and the chosen fields' columns (OutputOptions::particleFields,
//                            `[output] particle_fields`; default vx,vy,vz,wx,wy,wz) in SI units at
//                            every output time (t = outputTime(step count, dt); id: the particle's
//                            stable id, ParticleStore::id; positions wrapped into the box along
//                            periodic axes, dem/periodic.h; material by name), each number in its
//                            shortest round-trip form (reads back to the same bits); not written
//                            with `particles_csv = false`
//   DIR/particles_NNNNNN.vtp ParaView PolyData per output (id, radius and the chosen fields; the
//                            material as its index; each file its own particle count),
//                            ASCII or appended zlib-compressed binary (VtkFormat)
//   DIR/particles.pvd        the series, rewritten under a temporary name and renamed at every
//                            output, so it is complete at any moment (also after a kill)
// After a restart (ParticleRecorder::Resume) the frame numbers continue from the checkpoint's, the
// CSV continues an existing particles.csv cut to its size at the checkpoint (else a new one), and
// the .pvd lists the earlier frames whose .vtp files are in DIR.
// Every write is checked: a failure throws OutputError naming the file and the run stops. The CSV
// is flushed at every output, and each .vtp is written under a temporary name and renamed.
#pragma once

#include "dem/contact_diagnostics.h"
#include "dem/world.h"
#include "io/output_file.h"
#include "io/output_options.h"
#include "io/vtk_xml.h"

#include <filesystem>
#include <string>
#include <vector>

namespace veridem::io
{

/// Per particle (store order), its touching contacts with other particles among `contacts`.
std::vector<std::uint32_t> coordinationNumbers(const dem::World& world,
                                               const std::vector<dem::ContactRecord>& contacts);

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
    /// The files and fields `options` asks for (copied).
    ParticleRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                     const Resume* resume = nullptr);
    ParticleRecorder(const ParticleRecorder&) = delete;
    ParticleRecorder& operator=(const ParticleRecorder&) = delete;
    /// One frame. `contacts`: the world's touching contacts now (dem::evaluateContacts(world, 0)),
    /// for the coordination field; null: evaluated here if that field is asked for.
    void record(const dem::World& world, const std::vector<dem::ContactRecord>* contacts = nullptr);
    /// Closes the CSV, checking the last writes.
    void close();
    std::size_t framesWritten() const { return frameTimes_.size(); }
    const std::vector<double>& frameTimes() const { return frameTimes_; }
    /// Size of particles.csv [bytes], for a checkpoint (0 without it).
    std::uint64_t csvBytes() { return csv_.isOpen() ? csv_.size() : 0; }

  private:
    void writeCsv(const dem::World& world, const std::vector<std::uint32_t>& coordination);
    void writeVtp(const dem::World& world, const std::vector<std::uint32_t>& coordination,
                  const std::filesystem::path& path) const;
    void writePvd() const;

    std::filesystem::path directory_;
    OutputOptions options_;
    AppendFile csv_;
    std::vector<double> frameTimes_;
    std::vector<bool> listed_; // per frame: in the .pvd (false: written before a restart, not in DIR)
};

} // namespace veridem::io
