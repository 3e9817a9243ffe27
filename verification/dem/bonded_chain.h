// A straight chain of equal spheres joined by parallel bonds (dem/bonds/bond_law.h), clamped at
// its first sphere, relaxed to its static state under a load on its last: the bonded-particle
// cases' shared set-up (bonded_chain_beam.cpp).
#pragma once

#include "support.h"

namespace veridem::verify
{

struct BondedChain
{
    int bonds = 10;      // N: spheres 0..N along x, sphere 0 frozen (the clamp)
    Real radius = 1e-3;  // [m]
    Real gap = 2e-6;     // surface gap between neighbours [m] (the contact law never acts)
    Real density = 2500; // [kg/m^3]
    dem::BondParams law; // kn, ks [N/m^3], lambda
    Real spacing() const { return 2 * radius + gap; } // L [m]
};

/// The chain's world: spheres on the x axis, no gravity, bonds formed at the start.
World chainWorld(const BondedChain& chain);

/// Relaxes `world` under its external loads by mass-proportional damping (every velocity scaled
/// by exp(-rate dt) after each step, rate [1/s]) for `steps` steps of dt [s]; returns the tip's
/// rotation about x accumulated as the integrator drifts it (sum of dt w_x(t + dt/2)) [rad].
Real relaxChain(World& world, Real dt, Real rate, std::uint64_t steps);

} // namespace veridem::verify
