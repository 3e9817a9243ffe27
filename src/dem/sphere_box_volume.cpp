#include "dem/sphere_box_volume.h"

#include "core/constants.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace veridem::dem
{

namespace
{

/// Gauss-Legendre nodes and weights on [-1, 1] (Newton's method on P_n from the Chebyshev-like
/// first guesses, to full precision).
struct GaussLegendre
{
    std::array<Real, kSphereBoxNodes> node{}, weight{};
    GaussLegendre()
    {
        constexpr int n = kSphereBoxNodes;
        for (int k = 0; k < n; ++k)
        {
            Real x = std::cos(kPi * (k + 0.75) / (n + 0.5));
            Real derivative = 1;
            for (int iteration = 0; iteration < 100; ++iteration)
            {
                Real p0 = 1, p1 = x; // P_0, P_1
                for (int m = 2; m <= n; ++m)
                {
                    const Real p2 = ((2 * m - 1) * x * p1 - (m - 1) * p0) / m;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = n * (x * p1 - p0) / (x * x - 1);
                const Real next = x - p1 / derivative;
                const bool done = std::abs(next - x) <= 1e-16;
                x = next;
                if (done)
                    break;
            }
            node[static_cast<std::size_t>(k)] = x;
            weight[static_cast<std::size_t>(k)] = 2 / ((1 - x * x) * derivative * derivative);
        }
    }
};

const GaussLegendre& gaussLegendre()
{
    static const GaussLegendre rule;
    return rule;
}

/// Gauss-Legendre of f over [a, b].
template <class F> Real gaussLegendreOn(const F& f, Real a, Real b)
{
    const GaussLegendre& rule = gaussLegendre();
    Real sum = 0;
    for (std::size_t q = 0; q < rule.node.size(); ++q)
        sum += rule.weight[q] * f(a + 0.5 * (b - a) * (1 + rule.node[q]));
    return 0.5 * (b - a) * sum;
}

/// The integral of f over [a, b], `whole` its Gauss-Legendre value: accepted when the two halves'
/// sum agrees with it to `tolerance`, else each half to half the tolerance (at most 40 levels).
template <class F> Real adaptiveIntegral(const F& f, Real a, Real b, Real whole, Real tolerance, int depth)
{
    const Real middle = 0.5 * (a + b);
    const Real left = gaussLegendreOn(f, a, middle), right = gaussLegendreOn(f, middle, b);
    if (std::abs(left + right - whole) <= tolerance || depth >= 40)
        return left + right;
    return adaptiveIntegral(f, a, middle, left, 0.5 * tolerance, depth + 1) +
           adaptiveIntegral(f, middle, b, right, 0.5 * tolerance, depth + 1);
}

/// The integral of sqrt(rho^2 - x^2) dx from -rho to x (|x| <= rho) [m^2], up to a constant.
Real halfChordIntegral(Real rho, Real x)
{
    const Real ratio = std::clamp(x / rho, Real(-1), Real(1));
    return 0.5 * (x * std::sqrt(std::max(Real(0), rho * rho - x * x)) + rho * rho * std::asin(ratio));
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

Real sphereBoxVolume(const Vec3& c, Real r, const Vec3& lo, const Vec3& hi)
{
    if (c.x - r >= lo.x && c.x + r <= hi.x && c.y - r >= lo.y && c.y + r <= hi.y && c.z - r >= lo.z &&
        c.z + r <= hi.z)
        return (4.0 / 3.0) * kPi * r * r * r;
    if (c.x + r <= lo.x || c.x - r >= hi.x || c.y + r <= lo.y || c.y - r >= hi.y || c.z + r <= lo.z ||
        c.z - r >= hi.z)
        return 0;
    const Real za = std::max(lo.z, c.z - r), zb = std::min(hi.z, c.z + r);
    // Breakpoints: the heights where the section's circle passes through an edge's line or a corner.
    std::array<Real, 2 + 2 * 8> cut{};
    std::size_t count = 0;
    cut[count++] = za;
    const Real dx[2] = {lo.x - c.x, hi.x - c.x}, dy[2] = {lo.y - c.y, hi.y - c.y};
    const auto addDistance = [&](Real d2)
    {
        if (d2 > 0 && d2 < r * r)
        {
            const Real h = std::sqrt(r * r - d2);
            for (const Real z : {c.z - h, c.z + h})
                if (z > za && z < zb)
                    cut[count++] = z;
        }
    };
    for (int a = 0; a < 2; ++a)
    {
        addDistance(dx[a] * dx[a]);
        addDistance(dy[a] * dy[a]);
        for (int b = 0; b < 2; ++b)
            addDistance(dx[a] * dx[a] + dy[b] * dy[b]);
    }
    cut[count++] = zb;
    std::sort(cut.begin(), cut.begin() + static_cast<std::ptrdiff_t>(count));
    // Each piece adaptively: Gauss-Legendre on [t0, t1] against the sum over its halves, to an
    // absolute tolerance of kSphereBoxTolerance of the sphere's volume.
    const Real tolerance = kSphereBoxTolerance * (4.0 / 3.0) * kPi * r * r * r;
    Real volume = 0;
    for (std::size_t k = 0; k + 1 < count; ++k)
    {
        const Real z0 = cut[k], length = cut[k + 1] - z0;
        if (!(length > 0))
            continue;
        // z = z0 + L (3t^2 - 2t^3), dz = 6 L t (1 - t) dt.
        const auto integrand = [&](Real t)
        {
            const Real z = z0 + length * t * t * (3 - 2 * t);
            const Real rho = std::sqrt(std::max(Real(0), r * r - (z - c.z) * (z - c.z)));
            return 6 * length * t * (1 - t) * diskRectangleArea(rho, c.x, c.y, lo.x, hi.x, lo.y, hi.y);
        };
        volume += adaptiveIntegral(integrand, 0, 1, gaussLegendreOn(integrand, 0, 1), tolerance, 0);
    }
    return volume;
}

} // namespace veridem::dem
