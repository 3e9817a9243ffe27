#include "dem/walls/cylinder.h"

#include "dem/walls/wall.h"

#include <cmath>

namespace veridem::dem
{

Vec3 normalTo(const Vec3& axis)
{
    // Cross with the coordinate direction least aligned with the axis (never parallel to it).
    const Real ax = std::fabs(axis.x), ay = std::fabs(axis.y), az = std::fabs(axis.z);
    const Vec3 e = ax <= ay && ax <= az ? Vec3{1, 0, 0} : ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    const Vec3 n = cross(axis, e);
    return n / length(n);
}

WallGap wallGap(const CylinderShape& c, const Vec3& offset, const Vec3& x, Real r)
{
    WallGap g;
    const Vec3 relative = x - (c.point + offset);
    const Real s = dot(relative, c.axis);
    if (!(s >= 0 && s <= c.length)) // beyond an end (or NaN): no contact with the side
        return g;
    const Vec3 radial = relative - s * c.axis;
    const Real rho = length(radial);
    const Real R = c.radius;
    // Effective radius: the surface's principal curvatures at the contact are 1/R around the
    // circumference and 0 along the axis. We take the circumferential one, 1/R* = 1/r -+ 1/R
    // (concave inside, convex outside), as for the dish: it is the curvature in the direction a
    // ball rolls in a drum, and it differs from the Hertz equivalent radius of the elliptic contact
    // (the geometric mean of r and this R*) by a relative O(r / 2R).
    if (c.inside)
    {
        const Real overlap = rho + r - R;
        if (!(overlap > 0) || overlap > 2 * r || rho == 0) // (rho = 0 touches only if r > R)
            return g;
        g.touching = true;
        g.overlap = overlap;
        g.normal = radial / -rho;
        g.effectiveRadius = R > r ? r * R / (R - r) : r; // (a sphere wider than the drum: r)
        return g;
    }
    const Real overlap = R + r - rho;
    if (!(overlap > 0) || overlap > 2 * r)
        return g;
    g.touching = true;
    g.overlap = overlap;
    // Within rounding of the axis the radial direction is noise (it may even lean along the axis):
    // take a fixed one across it.
    g.normal = rho > 1e-12 * (R + r) ? radial / rho : normalTo(c.axis);
    g.effectiveRadius = r * R / (R + r);
    return g;
}

bool wallNear(const CylinderShape& c, const Vec3& offset, const Vec3& x, Real r, Real reach)
{
    const Vec3 relative = x - (c.point + offset);
    const Real s = dot(relative, c.axis);
    if (!(s >= -reach && s <= c.length + reach))
        return false;
    const Real rho = length(relative - s * c.axis);
    const Real overlap = c.inside ? rho + r - c.radius : c.radius + r - rho;
    return overlap > -reach;
}

} // namespace veridem::dem
