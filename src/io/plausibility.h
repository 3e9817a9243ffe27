// Plausibility of a 3D scene: values that are valid but most likely a unit mistake or a misplaced
// particle, each reported as one warning naming the key and the likely mistake (the user may mean
// it, so they are not errors; `veridem run --strict` makes the first one an error, exit 2):
//   - a mesh wall whose extent differs by more than kScaleRatio from the scene's (the particles'
//     cloud, at least 10 largest radii, and the finite walls): an STL in mm without `scale`;
//   - a radius above kLargestRadius or below kSmallestRadius [m] (radii are in metres);
//   - a Young's modulus below kSmallestModulus [Pa] (given in MPa or GPa?);
//   - a density below kSmallestDensity [kg/m^3] (given in g/cm^3?);
//   - a sphere wholly behind an infinite plane wall (it never touches it and falls through) or,
//     when no wall is an infinite plane, farther outside the box around every wall than its
//     diagonal;
//   - an [[insert]] region reaching outside the box of a periodic domain along a periodic axis
//     (its particles are wrapped into the box).
// docs/scene-format.md ("Plausibility warnings") lists them with their thresholds.
#pragma once

#include "io/dem_scene.h"

#include <string>
#include <vector>

namespace veridem::io
{

inline constexpr double kScaleRatio = 100;      // [-]
inline constexpr double kLargestRadius = 0.5;   // [m]
inline constexpr double kSmallestRadius = 1e-6; // [m]
inline constexpr double kSmallestModulus = 1e4; // [Pa]
inline constexpr double kSmallestDensity = 100; // [kg/m^3]

/// The warnings for `scene` (read from `file`), one line each, "file: what: likely mistake".
std::vector<std::string> plausibilityWarnings(const DemScene& scene, const std::string& file);

/// Prints the warnings on stderr ("veridem: warning: ...") if `speak`; with `strict`, throws the
/// first as an InputError instead (every rank does, so an MPI job ends alike).
void reportPlausibility(const DemScene& scene, const std::string& file, bool strict, bool speak);

} // namespace veridem::io
