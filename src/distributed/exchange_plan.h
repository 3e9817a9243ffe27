// Which particles a rank sends to which after a decomposition (distributed/bisection.h): the particles
// that left its region migrate to their owner, and every particle it owns is copied as a ghost to
// each other rank whose region comes within the particle's interaction range, so that each rank
// finds every pair of its own particles' contacts among its owned particles and its ghosts.
//
// The range. A pair (i, j) can touch before the next exchange if |x_i - x_j| < r_i + r_j + search
// (search: the neighbour skin plus the touch reach, dem/neighbor_list.h). For j owned by rank b,
// i within that distance of x_j is within r_i + r_max + search of b's region, so rank b needs a
// ghost of i if its region comes nearer than r_i + r_max + search to x_i (`halo` = r_max + search
// below, the same for every particle; r_i its own).
#pragma once

#include "core/vec3.h"
#include "distributed/bisection.h"

#include <cstdint>
#include <span>
#include <vector>

namespace veridem::distributed
{

struct ExchangePlan
{
    /// Per rank b: this rank's particles (indices into the arrays given, ascending) that b owns
    /// now and this rank does not (they migrate to b). Empty for this rank itself.
    std::vector<std::vector<std::uint32_t>> migrate;
    /// Per rank b: the particles this rank keeps (owns after the migration) whose ghost b needs
    /// (ascending). Empty for this rank itself.
    std::vector<std::vector<std::uint32_t>> ghost;
};

/// The plan of rank `me` for its particles at `position` [m] with radii `radius` [m], after the
/// decomposition `d` (file comment; `halo` [m]: r_max + search, > 0). O(particles x ranks near
/// each).
ExchangePlan planExchange(const Decomposition& d, int me, std::span<const Vec3> position,
                          std::span<const Real> radius, Real halo);

} // namespace veridem::distributed
