#include "io/thermo_output.h"

namespace veridem::io
{

ThermoRecorder::ThermoRecorder(const std::filesystem::path& directory,
                               std::optional<std::uint64_t> resumeBytes)
    : table_(
          directory,
          {"t", "particles", "pair_contacts", "wall_contacts", "kinetic_translational", "kinetic_rotational"},
          resumeBytes)
{
}

void ThermoRecorder::record(const dem::World& world)
{
    const dem::KineticEnergyParts kinetic = dem::kineticEnergyParts(world);
    table_.row({world.time, std::uint64_t(world.particles.size()), std::uint64_t(world.health.touchingPairs),
                std::uint64_t(world.health.touchingWalls), kinetic.translational, kinetic.rotational});
}

} // namespace veridem::io
