// Range checks on the derived quantities of a 3D scene, made before they are used: the number of
// spheres and the memory they need (before anything is allocated), and each sphere's mass, moment
// of inertia, kinetic energy, distance from the origin and travel per step. Violations are
// InputErrors with a one-line message naming the sphere or table, the value and the limit.
#pragma once

#include "core/vec3.h"
#include "dem/world.h"

#include <cstdint>
#include <string>

namespace veridem::io
{

/// Most spheres in one scene ([[sphere]], [[particles]] and [[lattice]] together).
inline constexpr double kMaxSpheres = 2e7;

/// Peak memory of a run per sphere [bytes]: particle arrays, neighbour list and grid, contact
/// history. Measured: 577 B/sphere peak resident for 1.26e6 spheres on a lattice (GNU time,
/// 727 MB); rounded up to cover the denser neighbour lists of random packings.
inline constexpr double kBytesPerSphere = 600;

/// A coordinate may be at most this many radii from the origin: a double then still resolves
/// 1e9 * 2.2e-16 = 2.2e-7 of a radius, so overlaps of 1e-4 radius keep three digits.
inline constexpr double kMaxDistanceInRadii = 1e9;

/// Physical memory of this machine [bytes] (0 if unknown).
double physicalMemoryBytes();

/// The most spheres this machine can run: kMaxSpheres, or fewer if its memory holds fewer (or
/// the lower limit set by limitSpheres).
double maxSphereCount();

/// Lowers the sphere limit of this process (the fuzz harness: small scenes, bounded memory).
void limitSpheres(double count);

/// Refuses `count` spheres (`what` describes where they come from) above kMaxSpheres or above the
/// machine's memory by the kBytesPerSphere estimate, with the figures, before any is allocated.
void checkSphereCount(double count, const std::string& what, const std::string& file);

/// Refuses a sphere whose mass, inertia or kinetic energy is zero or not finite, that lies further
/// than kMaxDistanceInRadii radii from the origin, or that moves more than its radius in one step.
void checkSphereRanges(const dem::World& world, Real dt, const std::string& file);

} // namespace veridem::io
