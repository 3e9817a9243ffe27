// The `[bonds]` table of a 3D scene (docs/scene-format.md): which particles are bonded, when, and
// the parallel bond law's parameters (dem/bonds/bond_law.h). Every key is checked here, before
// the run, with a one-line error naming the key, its line and the valid range.
#pragma once

#include "dem/world.h"
#include "io/toml_reader.h"

namespace veridem::io
{

/// Reads `[bonds]` if present into world.bonds (enabled) once the scene's materials and particles
/// are in the world; dt [s] is the scene's step, checked against the bonds' stability limit.
/// `laterParticles`: particles may still come (inserters), so a table selecting none now is
/// accepted if it forms its bonds later. Refused with periodic boundaries and with the energy
/// ledger (`energyLedger`), which do not know bonds yet.
void readBonds(TableReader& top, dem::World& world, Real dt, bool laterParticles, bool energyLedger);

} // namespace veridem::io
