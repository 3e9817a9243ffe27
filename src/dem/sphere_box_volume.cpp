#include "dem/sphere_box_volume.h"

#include "core/constants.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace veridem::dem
{

namespace
{

/// The integral of sqrt(rho^2 - x^2) dx from -rho to x (|x| <= rho) [m^2], up to a constant:
/// (x h + rho^2 asin(x / rho)) / 2 with h = sqrt(rho^2 - x^2), the arcsine taken as atan2(x, h) of
/// the same h: the sum's derivative in h vanishes (x - rho^2 x / (x^2 + h^2) = 0), so the rounding
/// of h near x = +-rho cancels, where asin of a rounded ratio near 1 would be off by ~1e-8.
Real halfChordIntegral(Real rho, Real x)
{
    const Real h = std::sqrt(std::max(Real(0), rho * rho - x * x));
    return 0.5 * (x * h + rho * rho * std::atan2(x, h));
}

} // namespace

Real diskQuadrantArea(Real rho, Real X, Real Y)
{
    if (!(rho > 0) || X <= -rho || Y <= -rho)
        return 0;
    const Real end = std::min(X, rho); // the x range is [-rho, end]
    // S(a, b): the integral of the half chord s(x) = sqrt(rho^2 - x^2) over [a, b].
    const auto S = [&](Real a, Real b)
    { return b > a ? halfChordIntegral(rho, b) - halfChordIntegral(rho, a) : 0; };
    if (Y >= rho)
        return 2 * S(-rho, end);
    // The chord at x is [-s, s]; below Y it has length Y + s where s > |Y| (|x| < xY), and 2s
    // (Y > 0) or 0 (Y < 0) where s < |Y|.
    const Real xY = std::sqrt(std::max(Real(0), rho * rho - Y * Y));
    Real area = 0;
    const Real middleEnd = std::min(xY, end);
    if (middleEnd > -xY)
        area += Y * (middleEnd + xY) + S(-xY, middleEnd);
    if (Y > 0)
        area += 2 * (S(-rho, std::min(-xY, end)) + S(xY, end));
    return area;
}

Real diskRectangleArea(Real rho, Real cx, Real cy, Real x0, Real x1, Real y0, Real y1)
{
    const Real X0 = x0 - cx, X1 = x1 - cx, Y0 = y0 - cy, Y1 = y1 - cy;
    return diskQuadrantArea(rho, X1, Y1) - diskQuadrantArea(rho, X0, Y1) - diskQuadrantArea(rho, X1, Y0) +
           diskQuadrantArea(rho, X0, Y0);
}

namespace
{

/// The volume [m^3] of the sphere of radius r [m] (centre at the origin) where z >= c, |c| < r:
/// the cap pi (r - c)^2 (2r + c) / 3.
Real capVolume(Real r, Real c)
{
    return kPi * (r - c) * (r - c) * (2 * r + c) / 3;
}

/// integral of asin(a / sqrt(r^2 - z^2)) dz [m] (0 <= a < r [m], z^2 <= r^2 - a^2), up to a
/// constant (the header derives it), with every arcsine as an atan2 of the one
/// q = sqrt(r^2 - a^2 - z^2): asin(a / rho) = atan2(a, q), asin(z / sqrt(r^2 - a^2)) = atan2(z, q).
/// The sum's derivative in q is q^2 / (a z), zero at the ends of the range (q -> 0), so the
/// rounding of q there cancels (asin of a rounded ratio near 1 would be off by ~1e-8). At q = 0
/// (z != 0) the last arctangent is its limit sign(z) pi/2 taken directly: a * z underflows to 0 for a bound
/// a as small as 1e-300 r, and atan2(0, 0) = 0 would put r pi/2 into the sphere's surface.
Real arcsinePrimitive(Real r, Real a, Real z)
{
    if (!(a > 0))
        return 0;
    const Real q = std::sqrt(std::max(Real(0), r * r - a * a - z * z));
    const Real last = q > 0 || z == 0 ? std::atan2(a * z, r * q) : std::copysign(0.5 * kPi, z);
    return z * std::atan2(a, q) + a * std::atan2(z, q) - r * last;
}

/// The volume [m^3] of the sphere of radius r where y >= b and z >= c, 0 <= b < r, |c| < r.
Real wedgeVolume(Real r, Real b, Real c)
{
    const Real top = std::sqrt(std::max(Real(0), r * r - b * b)); // the circle reaches y >= b below
    const Real bottom = std::max(c, -top);
    if (!(bottom < top))
        return 0;
    // Phi(z) = pi - 2 asin(b / rho(z)).
    const Real S =
        r * (kPi * (top - bottom) - 2 * (arcsinePrimitive(r, b, top) - arcsinePrimitive(r, b, bottom)));
    const Real rhoB = top, rhoC = std::sqrt(std::max(Real(0), r * r - c * c));
    const Real faceB = diskQuadrantArea(rhoB, rhoB, -c); // on y = b: z >= c
    const Real faceC = diskQuadrantArea(rhoC, rhoC, -b); // on z = c: y >= b
    return std::max(Real(0), (r * S - b * faceB - c * faceC) / 3);
}

/// The volume [m^3] of the sphere of radius r where x >= a, y >= b and z >= c, 0 <= a, b < r,
/// |c| < r.
Real cornerVolume(Real r, Real a, Real b, Real c)
{
    const Real top = std::sqrt(std::max(Real(0), r * r - a * a - b * b));
    const Real bottom = std::max(c, -top);
    if (!(bottom < top))
        return 0;
    // Phi(z) = pi/2 - asin(a / rho(z)) - asin(b / rho(z)).
    const Real S =
        r * (0.5 * kPi * (top - bottom) - (arcsinePrimitive(r, a, top) - arcsinePrimitive(r, a, bottom)) -
             (arcsinePrimitive(r, b, top) - arcsinePrimitive(r, b, bottom)));
    const Real rhoA = std::sqrt(std::max(Real(0), r * r - a * a));
    const Real rhoB = std::sqrt(std::max(Real(0), r * r - b * b));
    const Real rhoC = std::sqrt(std::max(Real(0), r * r - c * c));
    const Real faceA = diskQuadrantArea(rhoA, -b, -c), faceB = diskQuadrantArea(rhoB, -a, -c),
               faceC = diskQuadrantArea(rhoC, -a, -b);
    return std::max(Real(0), (r * S - a * faceA - b * faceB - c * faceC) / 3);
}

/// G: the volume [m^3] of the sphere of radius r (centre at the origin) where x_k >= bounds[k] for
/// the `count` (<= 3) coordinates listed, any bounds [m]. Reflects negative bounds (at most three
/// levels deep; the header).
Real orthantVolume(Real r, std::array<Real, 3> bounds, int count)
{
    int kept = 0;
    for (int k = 0; k < count; ++k)
    {
        const Real bound = bounds[static_cast<std::size_t>(k)];
        if (bound >= r)
            return 0;
        if (bound > -r) // (a bound at or below -r does not cut the sphere)
            bounds[static_cast<std::size_t>(kept++)] = bound;
    }
    // The non-negative bounds first.
    std::stable_partition(bounds.begin(), bounds.begin() + kept, [](Real b) { return b >= 0; });
    const int nonNegative =
        static_cast<int>(std::count_if(bounds.begin(), bounds.begin() + kept, [](Real b) { return b >= 0; }));
    if (kept == 0)
        return (4.0 / 3.0) * kPi * r * r * r;
    if (kept == 1)
        return capVolume(r, bounds[0]);
    if (nonNegative < kept - 1) // two negative bounds: reflect the last
    {
        const Real last = bounds[static_cast<std::size_t>(kept - 1)];
        std::array<Real, 3> reflected = bounds;
        reflected[static_cast<std::size_t>(kept - 1)] = -last;
        return orthantVolume(r, bounds, kept - 1) - orthantVolume(r, reflected, kept);
    }
    return kept == 2 ? wedgeVolume(r, bounds[0], bounds[1])
                     : cornerVolume(r, bounds[0], bounds[1], bounds[2]);
}

} // namespace

Real sphereBoxVolume(const Vec3& c, Real r, const Vec3& lo, const Vec3& hi)
{
    // The faces relative to the centre, rounded once: the tests for a sphere wholly inside or
    // outside use the same numbers as the corner terms (orthantVolume's bound >= r and <= -r), so
    // the shortcut and the general path cannot disagree by a rounding of c - r (~1e-4 r for
    // r = 1e-9 m at 1e3 m from the origin).
    const Real xs[2] = {lo.x - c.x, hi.x - c.x}, ys[2] = {lo.y - c.y, hi.y - c.y},
               zs[2] = {lo.z - c.z, hi.z - c.z};
    if (xs[0] <= -r && xs[1] >= r && ys[0] <= -r && ys[1] >= r && zs[0] <= -r && zs[1] >= r)
        return (4.0 / 3.0) * kPi * r * r * r;
    if (xs[1] <= -r || xs[0] >= r || ys[1] <= -r || ys[0] >= r || zs[1] <= -r || zs[0] >= r)
        return 0;
    // Inclusion-exclusion over the eight corners.
    Real volume = 0;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k)
            {
                const Real sign = (i + j + k) % 2 == 0 ? 1 : -1;
                volume += sign * orthantVolume(r, {xs[i], ys[j], zs[k]}, 3);
            }
    return std::clamp(volume, Real(0), (4.0 / 3.0) * kPi * r * r * r);
}

} // namespace veridem::dem
