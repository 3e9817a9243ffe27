// DIR/thermo.csv of a DEM run (io/thermo_table.h): one row per output with the time t [s], the
// number of particles, the contacts touching (particle pairs and particle-wall, from the last force
// evaluation), the translational and rotational kinetic energy [J] and the elastic energy stored in
// the contact springs [J] (normal, tangential and EPSD rolling; dem/contact_diagnostics.h). With an
// energy ledger (dem/energy_ledger.h, `[output] energy = true`), also its terms [J]: the work of
// gravity and of the walls, the energy dissipated by normal damping, tangential damping, friction
// and rolling resistance, the initial energy and the balance residual
// E_kin + E_elastic - W_gravity - W_walls + D - E_initial. With bonds (`[bonds]`,
// dem/bonds/bond_set.h), also the intact bonds and the bonds broken so far. Every write is checked
// (OutputError).
#pragma once

#include "dem/contact_diagnostics.h"
#include "dem/energy_ledger.h"
#include "dem/world.h"
#include "io/output_options.h"
#include "io/thermo_table.h"

#include <filesystem>
#include <optional>

namespace veridem::io
{

class ThermoRecorder
{
  public:
    /// With `resumeBytes` (a restart), continues an existing thermo.csv cut to that size. `ledger`
    /// (not owned; null: none) adds its columns, `bonds` the bond counts. Times: outputTime(step
    /// count, options.dt).
    ThermoRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                   std::optional<std::uint64_t> resumeBytes = std::nullopt,
                   const dem::EnergyLedger* ledger = nullptr, bool bonds = false);
    /// One row; `contacts`: the world's contacts now (evaluateContacts(world, 0)), for the elastic
    /// energy (their stored energy) when there is no ledger (the ledger keeps that of its last
    /// step, the same).
    void record(const dem::World& world, const std::vector<dem::ContactRecord>& contacts);
    std::uint64_t size() { return table_.size(); }
    void close() { table_.close(); }

  private:
    Real dt_; // [s]
    const dem::EnergyLedger* ledger_;
    bool bonds_;
    ThermoTable table_;
};

} // namespace veridem::io
