// Measures of the packing inside an axis-aligned box (docs/measurements.md): particle count,
// coordination number, packing fraction and the Love-Weber stress tensor (contact and kinetic
// parts), from the touching contacts as the contact law gives them (contact_diagnostics.h).
//
// A particle belongs to the box if its centre lies inside it (lo <= x <= hi in every component).
//   coordination   Z = (particle-particle contacts of the box's particles, each counted once per
//                  member particle) / (particles in the box); wall contacts are not counted [-]
//   packing        phi = (sum over all particles of the volume of the sphere inside the box,
//                  sphereBoxVolume, exact to ~1e-14) / V_box [-]
//   stress         sigma = sigma_c + sigma_k [Pa], symmetric parts, tension positive (a
//                  compressed packing has negative diagonal):
//                  sigma_c,ij = (1/V_box) sum over the box's particles p, over p's contacts c
//                  (walls included) of (f_c)_i (x_c - x_p)_j, f_c the contact force on p, x_c the
//                  contact point;
//                  sigma_k,ij = -(1/V_box) sum over the box's particles p of m_p v'_i v'_j,
//                  v' = v_p - V, V the box's particles' mass-averaged velocity (the momentum flux
//                  of the velocity fluctuations: compressive, like a gas's pressure).
#pragma once

#include "dem/contact_diagnostics.h"

#include <array>
#include <cstdint>
#include <vector>

namespace veridem::dem
{

struct RegionMeasures
{
    std::uint64_t particles = 0; // centres inside the box
    std::uint64_t contacts = 0;  // particle-particle contacts counted per member particle
    Real coordination = 0;       // contacts / particles [-] (0 if the box is empty)
    Real packingFraction = 0;    // [-]
    // xx, yy, zz, xy, xz, yz [Pa]: the total, and its contact and kinetic parts.
    std::array<Real, 6> stress{}, contactStress{}, kineticStress{};
};

/// The measures of the box [lo, hi] [m] from `contacts` (evaluateContacts of `world`).
RegionMeasures measureRegion(const World& world, const std::vector<ContactRecord>& contacts, const Vec3& lo,
                             const Vec3& hi);

} // namespace veridem::dem
