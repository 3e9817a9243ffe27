// The contact network of a DEM run, for ParaView's force chains (docs/measurements.md):
//   DIR/contacts_NNNNNN.vtp  PolyData per output: one line per touching contact, from particle i's
//                            centre to its partner's centre (a wall contact: to the contact point);
//                            cell data: ids (i, partner), wall (1 if the partner is a wall),
//                            contact_point [m], normal (unit, partner to i), normal_force and
//                            tangential_force on i [N], force_magnitude [N]
//   DIR/contacts.pvd         the series (rewritten under a temporary name and renamed)
// The forces are the contact law's at the output instant (dem/contact_diagnostics.h, dt = 0).
// Written at the particle output's times, with its frame numbers. Every write is checked.
#pragma once

#include "dem/contact_diagnostics.h"
#include "io/vtk_xml.h"

#include <filesystem>
#include <vector>

namespace veridem::io
{

class ContactRecorder
{
  public:
    /// `frameTimes`: the output times of frames written before a restart [s] (empty: a new run).
    ContactRecorder(const std::filesystem::path& directory, VtkFormat format,
                    const std::vector<double>& frameTimes = {});
    void record(const dem::World& world, const std::vector<dem::ContactRecord>& contacts);

  private:
    void writePvd() const;

    std::filesystem::path directory_;
    VtkFormat format_;
    std::vector<double> frameTimes_;
    std::vector<bool> listed_;
};

} // namespace veridem::io
