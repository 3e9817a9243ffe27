// The volume of a sphere inside an axis-aligned box, V(sphere ∩ box), for the packing fraction of
// a region (region_measures.h; docs/measurements.md derives it), in closed form: a fixed number of
// elementary functions whatever the position (no iteration, no recursion beyond three levels).
//
// Inclusion-exclusion over the box's eight corners: with the centre at the origin and
// G(a, b, c) = V(sphere ∩ {x >= a, y >= b, z >= c}),
//   V(sphere ∩ [x0, x1] x [y0, y1] x [z0, z1]) = sum over i, j, k in {0, 1} of
//                                               (-1)^(i+j+k) G(x_i, y_j, z_k).
// A bound at or beyond the sphere (|a| >= r) removes its constraint or empties the region. A
// negative bound is reflected, G(a, b, c) = V(sphere ∩ {y >= b, z >= c}) - G(-a, b, c), until at
// most one is negative. What is left is a cap (one bound), a wedge (two, the first >= 0) or a
// corner (three, the first two >= 0), each by the divergence theorem applied to the position p:
//   V = (1/3) (r S - a A_x - b A_y - c A_z),
// S the area of the region's spherical surface (on which p.n = r) and A_x, A_y, A_z the areas of
// its flat faces on x = a, y = b, z = c (p.n = -a, -b, -c). Each face is a disk cut by one or two
// lines (diskQuadrantArea). S follows Archimedes' dS = r dphi dz: S = r * integral over z of the
// angle Phi(z) of the section's circle (radius rho = sqrt(r^2 - z^2)) inside the region,
// Phi = pi - 2 asin(b / rho) (wedge) or pi/2 - asin(a / rho) - asin(b / rho) (corner), over the z
// where the circle reaches the region, and in closed form
//   integral of asin(a / rho(z)) dz = z asin(a / rho) + a asin(z / sqrt(r^2 - a^2))
//                                     - r atan(a z / (r sqrt(r^2 - a^2 - z^2)))
// (differentiate to check: the last two terms' derivatives cancel z d/dz asin(a / rho)).
// Accuracy: rounding only; against a quadrature of slices and Monte Carlo the error is below 1e-13
// of the sphere's volume (tests/dem/sphere_box_volume_test.cpp). A sphere wholly inside the box
// gives 4/3 pi r^3 exactly, one wholly outside 0.
#pragma once

#include "core/vec3.h"

namespace veridem::dem
{

/// The area [m^2] of the disk x^2 + y^2 <= rho^2 (rho >= 0 [m]) where x <= X and y <= Y [m].
Real diskQuadrantArea(Real rho, Real X, Real Y);

/// The area [m^2] of the disk of radius rho [m] centred at (cx, cy) [m] inside [x0, x1] x [y0, y1].
Real diskRectangleArea(Real rho, Real cx, Real cy, Real x0, Real x1, Real y0, Real y1);

/// The volume [m^3] of the sphere of centre c [m] and radius r [m] inside the box [lo, hi] [m].
Real sphereBoxVolume(const Vec3& c, Real r, const Vec3& lo, const Vec3& hi);

} // namespace veridem::dem
