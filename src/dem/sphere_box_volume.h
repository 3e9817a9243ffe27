// The volume of a sphere inside an axis-aligned box, V(sphere ∩ box), for the packing fraction of
// a region (region_measures.h; docs/measurements.md derives it).
//
// V = integral over z of A(rho(z)) dz, rho(z) = sqrt(r^2 - (z - z_c)^2) the radius of the sphere's
// section at height z and A(rho) the area of the disk of radius rho (centre (x_c, y_c)) inside the
// rectangle [x0, x1] x [y0, y1], in closed form by inclusion-exclusion of four quadrant areas
// (diskQuadrantArea). A(rho(z)) is smooth in z except where the section's circle passes through a
// rectangle edge's line (rho = distance from the centre to the line, where A has a (z - z_b)^(3/2)
// term) or a corner (a jump of A''). The z range is cut at these breakpoints; on each piece the
// substitution z = z0 + L (3t^2 - 2t^3) makes the (z - z_b)^(3/2) terms at either end smooth in t
// (t^3). A piece may still have a singularity just beyond an end (a pole of the sphere, where the
// section's radius is sqrt(r^2 - (z - z_c)^2)), so it is integrated adaptively: Gauss-Legendre
// with kSphereBoxNodes nodes on an interval against the sum over its halves, bisecting until they
// agree to kSphereBoxTolerance of the sphere's volume (tests/dem/sphere_box_volume_test.cpp). A sphere wholly
// inside the box gives 4/3 pi r^3 exactly, one wholly outside 0.
#pragma once

#include "core/vec3.h"

namespace veridem::dem
{

/// Gauss-Legendre nodes per interval of the z integral, and the adaptive bisection's absolute
/// tolerance as a fraction of the sphere's volume.
inline constexpr int kSphereBoxNodes = 16;
inline constexpr double kSphereBoxTolerance = 1e-14;

/// The area [m^2] of the disk x^2 + y^2 <= rho^2 (rho >= 0 [m]) where x <= X and y <= Y [m].
Real diskQuadrantArea(Real rho, Real X, Real Y);

/// The area [m^2] of the disk of radius rho [m] centred at (cx, cy) [m] inside [x0, x1] x [y0, y1].
Real diskRectangleArea(Real rho, Real cx, Real cy, Real x0, Real x1, Real y0, Real y1);

/// The volume [m^3] of the sphere of centre c [m] and radius r [m] inside the box [lo, hi] [m].
Real sphereBoxVolume(const Vec3& c, Real r, const Vec3& lo, const Vec3& hi);

} // namespace veridem::dem
