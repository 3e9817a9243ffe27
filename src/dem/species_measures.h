// Per-species measures of the particles (docs/measurements.md, "Species and zones"): a species is
// a [[material]]. For each material the count, mass and centre of mass of its particles, and for
// a zone (an axis-aligned box whose bounds may be infinite: a half-space or a slab) the count of
// each material's particles whose centre lies in it (lo <= x <= hi in every component, as the
// region measures count members). Frozen particles count like the others.
#pragma once

#include "dem/particles.h"

#include <cstdint>
#include <string>
#include <vector>

namespace veridem::dem
{

struct Zone
{
    std::string name;
    Vec3 lo, hi;                          // bounds [m]; components may be -inf / +inf
    std::vector<std::uint32_t> materials; // the materials counted, in the order written
};

struct SpeciesMeasure
{
    std::uint64_t count = 0;
    Real mass = 0; // [kg]
    Vec3 centre;   // centre of mass [m] (0 if there is none of the species)
};

/// One entry per material index below `materialCount`, summed in store order.
std::vector<SpeciesMeasure> measureSpecies(const ParticleStore& particles, std::size_t materialCount);

/// The count of each of `zone.materials`' particles with the centre in the zone, in that order.
std::vector<std::uint64_t> countInZone(const ParticleStore& particles, const Zone& zone);

} // namespace veridem::dem
