// Fragments of the bodies that crack: the pieces a body has broken into. Two triangles of one body
// are in the same fragment when they share a node (the continuum) or an intact joint ties them
// (fracture/joints.h); a fragment is a connected component of that relation (union-find, Tarjan
// 1975). A body that does not crack is one fragment.
#pragma once

#include "fdem/world.h"

#include <cstdint>
#include <vector>

namespace veridem::fdem
{

struct Fragment
{
    std::uint32_t body = 0;      ///< body id
    std::size_t triangles = 0;   ///< count
    Real area = 0;               ///< reference area [m^2] (per unit thickness: volume per m)
    Real mass = 0;               ///< [kg/m]
    Vec2 centroid{};             ///< mass-weighted current centroid [m]
    Real equivalentDiameter = 0; ///< diameter of the disc of the same area, sqrt(4 A / pi) [m]
};

/// The fragments of every body, ordered by body, then by their lowest triangle id (deterministic).
std::vector<Fragment> findFragments(const World& world);

} // namespace veridem::fdem
