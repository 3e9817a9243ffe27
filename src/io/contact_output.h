// The contact network of a DEM run, for ParaView's force chains and for analysis
// (docs/measurements.md):
//   DIR/contacts_NNNNNN.vtp  (OutputOptions::contactsVtk) PolyData per output: one line per
//                            touching contact, from particle i's centre to its partner's centre (a
//                            wall contact: to the contact point); cell data: ids (i, partner; a
//                            wall by its index in the scene's wall list), wall (1 if the partner is
//                            a wall), contact_point [m], normal (unit, partner to i), normal_force
//                            and tangential_force on i [N], force_magnitude [N]
//   DIR/contacts.pvd         the series (rewritten under a temporary name and renamed)
//   DIR/contacts_NNNNNN.csv  (OutputOptions::contactsCsv) the same contacts, one row each:
//                            t,id,partner,wall,overlap,cx,cy,cz,nx,ny,nz,fnx,fny,fnz,ftx,fty,ftz
//                            (partner: the other particle's id, empty for a wall; wall: the wall's
//                            name from the scene, empty for a pair; overlap [m]; c the contact
//                            point [m]; n the unit normal; fn, ft the normal and tangential force
//                            on particle `id` [N]), numbers in shortest round-trip form
// The forces are the contact law's at the output instant (dem/contact_diagnostics.h, dt = 0).
// Written at the particle output's times, with its frame numbers. Every write is checked.
#pragma once

#include "dem/contact_diagnostics.h"
#include "io/output_options.h"
#include "io/vtk_xml.h"

#include <filesystem>
#include <vector>

namespace veridem::io
{

class ContactRecorder
{
  public:
    /// The files `options` asks for (contactsVtk, contactsCsv; times outputTime(step count, dt)).
    /// `frameTimes`: the output times of frames written before a restart [s] (empty: a new run).
    ContactRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                    const std::vector<double>& frameTimes = {});
    void record(const dem::World& world, const std::vector<dem::ContactRecord>& contacts);

  private:
    void writeVtp(const dem::World& world, const std::vector<dem::ContactRecord>& contacts) const;
    void writeCsv(const dem::World& world, const std::vector<dem::ContactRecord>& contacts) const;
    void writePvd() const;

    std::filesystem::path directory_;
    OutputOptions options_;
    std::vector<double> frameTimes_;
    std::vector<bool> listed_;
};

} // namespace veridem::io
