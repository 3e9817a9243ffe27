#include "fdem/output_thermo.h"

namespace veridem::fdem
{

std::vector<std::string> thermoColumns()
{
    return {"t", "bodies", "nodes", "triangles", "couples", "contacts", "sliding", "kinetic"};
}

void recordThermo(io::ThermoTable& table, const World& world, Real time)
{
    const FrictionDiagnostics& d = world.frictionDiagnostics();
    table.row({time, std::uint64_t(world.bodyCount()), std::uint64_t(world.nodes().size()),
               std::uint64_t(world.triangles().size()), std::uint64_t(world.coupleCount()),
               std::uint64_t(d.contacts), std::uint64_t(d.sliding), world.energies().kinetic});
}

} // namespace veridem::fdem
