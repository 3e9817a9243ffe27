// Spatial ordering of particles: renumbers them along a Morton (Z-order) curve of grid cells, so
// that particles close in space are close in memory. Contact loops then read neighbouring
// particles from the same cache lines (LAMMPS sorts its atoms by bins for the same reason).
//
// Renumbering changes particle indices, so it is opt-in and done by the driver before the first
// step (before prepare()), when no contact history exists yet. The returned map gives the input
// index of every new index, for output in the input's order.
#pragma once

#include "dem/world.h"

#include <cstdint>
#include <vector>

namespace veridem::dem
{

/// Reorders world.particles by the Morton code of cubic cells of edge cellSize [m] (<= 0: twice
/// the largest radius plus the neighbour skin). Throws InputError if the world was prepared.
/// Returns originalIndex with originalIndex[new] = old.
std::vector<std::uint32_t> sortParticlesSpatially(World& world, Real cellSize = 0);

} // namespace veridem::dem
