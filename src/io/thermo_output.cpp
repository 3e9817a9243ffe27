#include "io/thermo_output.h"

namespace veridem::io
{

ThermoRecorder::ThermoRecorder(const std::filesystem::path& directory)
{
    csv_.open(directory / "thermo.csv");
    csv_.stream() << "t,particles,pair_contacts,wall_contacts,kinetic_translational,kinetic_rotational\n";
    csv_.flush();
}

void ThermoRecorder::record(const dem::World& world)
{
    const dem::KineticEnergyParts kinetic = dem::kineticEnergyParts(world);
    std::string row;
    appendNumber(row, world.time);
    row += ',' + std::to_string(world.particles.size()) + ',' + std::to_string(world.health.touchingPairs) +
           ',' + std::to_string(world.health.touchingWalls) + ',';
    appendNumber(row, kinetic.translational);
    row += ',';
    appendNumber(row, kinetic.rotational);
    row += '\n';
    csv_.stream() << row;
    csv_.flush();
}

} // namespace veridem::io
