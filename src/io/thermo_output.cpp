#include "io/thermo_output.h"

namespace veridem::io
{

namespace
{
std::vector<std::string> columns(bool ledger, bool bonds)
{
    std::vector<std::string> c = {"t",
                                  "particles",
                                  "pair_contacts",
                                  "wall_contacts",
                                  "kinetic_translational",
                                  "kinetic_rotational",
                                  "elastic"};
    if (ledger)
        for (const char* name : {"work_gravity", "work_walls", "dissipated_normal_damping",
                                 "dissipated_tangential_damping", "dissipated_friction", "dissipated_rolling",
                                 "dissipated_adhesion", "energy_initial", "energy_residual"})
            c.push_back(name);
    if (bonds)
        for (const char* name : {"bonds_intact", "bonds_broken"})
            c.push_back(name);
    return c;
}
} // namespace

ThermoRecorder::ThermoRecorder(const std::filesystem::path& directory, const OutputOptions& options,
                               std::optional<std::uint64_t> resumeBytes, const dem::EnergyLedger* ledger,
                               bool bonds)
    : dt_(options.dt), ledger_(ledger), bonds_(bonds),
      table_(directory, columns(ledger != nullptr, bonds), resumeBytes)
{
}

void ThermoRecorder::record(const dem::World& world, const std::vector<dem::ContactRecord>& contacts)
{
    const dem::KineticEnergyParts kinetic = dem::kineticEnergyParts(world);
    Real elastic = 0;
    if (ledger_)
        elastic = ledger_->state.elasticEnergy;
    else
        for (const dem::ContactRecord& c : contacts)
            elastic += c.storedEnergy();
    std::vector<ThermoValue> row = {outputTime(world.stepCount, dt_),
                                    std::uint64_t(world.particles.liveCount()),
                                    std::uint64_t(world.health.touchingPairs),
                                    std::uint64_t(world.health.touchingWalls),
                                    kinetic.translational,
                                    kinetic.rotational,
                                    elastic};
    if (ledger_)
    {
        const dem::EnergyLedgerState& s = ledger_->state;
        for (const Real v : {s.gravityWork, s.wallWork, s.normalDamping, s.tangentialDamping, s.friction,
                             s.rolling, s.adhesion, s.initialEnergy, ledger_->residual(world)})
            row.emplace_back(v);
    }
    if (bonds_)
    {
        row.emplace_back(std::uint64_t(world.bonds.bonds.size()));
        row.emplace_back(std::uint64_t(world.bonds.broken));
    }
    table_.row(row);
}

} // namespace veridem::io
