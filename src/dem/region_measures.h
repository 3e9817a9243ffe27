// Measures of the packing inside an axis-aligned box (docs/measurements.md): particle count,
// coordination number, packing fraction and the Love-Weber (static) stress tensor, from the
// touching contacts as the contact law gives them (contact_diagnostics.h).
//
// A particle belongs to the box if its centre lies inside it (lo <= x <= hi in every component).
//   coordination   Z = (particle-particle contacts of the box's particles, each counted once per
//                  member particle) / (particles in the box); wall contacts are not counted [-]
//   packing        phi = (sum of the box's particles' volumes 4/3 pi r^3) / V_box [-] (the centre
//                  rule: exact when no sphere crosses the box's faces)
//   stress         sigma_ij = (1/V_box) sum over the box's particles p, over p's contacts c (walls
//                  included) of (f_c)_i (x_c - x_p)_j, f_c the contact force on p, x_c the contact
//                  point; its symmetric part is reported, tension positive (a compressed packing
//                  has negative diagonal) [Pa]. The static (contact) part only: the kinetic part
//                  -(1/V) sum m v'_i v'_j is not included.
#pragma once

#include "dem/contact_diagnostics.h"

#include <array>
#include <cstdint>
#include <vector>

namespace veridem::dem
{

struct RegionMeasures
{
    std::uint64_t particles = 0;  // centres inside the box
    std::uint64_t contacts = 0;   // particle-particle contacts counted per member particle
    Real coordination = 0;        // contacts / particles [-] (0 if the box is empty)
    Real packingFraction = 0;     // [-]
    std::array<Real, 6> stress{}; // xx, yy, zz, xy, xz, yz [Pa]
};

/// The measures of the box [lo, hi] [m] from `contacts` (evaluateContacts of `world`).
RegionMeasures measureRegion(const World& world, const std::vector<ContactRecord>& contacts, const Vec3& lo,
                             const Vec3& hi);

} // namespace veridem::dem
