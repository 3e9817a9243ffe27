// thermo.csv of a 2D FEM/DEM run, one row per output (the 3D runs' summary file, written by the
// same io::ThermoTable): t [s] (after the settling), bodies, nodes, triangles, couples (candidate
// triangle pairs of the broad phase), contacts (edge contacts touching in the last step), sliding
// (of which at the Coulomb cap) and kinetic (sum m v^2 / 2 of the free nodes, half-step
// velocities, per unit thickness [J/m]).
#pragma once

#include "fdem/world.h"
#include "io/thermo_table.h"

#include <string>
#include <vector>

namespace veridem::fdem
{

std::vector<std::string> thermoColumns();

/// Appends the row of `world` at output time `time` [s].
void recordThermo(io::ThermoTable& table, const World& world, Real time);

} // namespace veridem::fdem
