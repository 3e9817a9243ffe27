#include "fdem/contact/potential.h"

#include <algorithm>

namespace veridem::fdem
{

std::array<Real, 3> barycentric(const Vec2& p, const std::array<Vec2, 3>& target)
{
    // lambda_k is the area of (p, node k+1, node k+2) over the triangle's area.
    const Real inverseTwiceArea = 1 / cross(target[1] - target[0], target[2] - target[0]);
    std::array<Real, 3> l;
    for (int k = 0; k < 3; ++k)
    {
        const Vec2& q1 = target[(k + 1) % 3];
        l[k] = cross(target[(k + 2) % 3] - q1, p - q1) * inverseTwiceArea;
    }
    return l;
}

EdgePenetration edgeInTriangle(const Vec2& p0, const Vec2& p1, const std::array<Vec2, 3>& target)
{
    return edgeInTriangle(barycentric(p0, target), barycentric(p1, target));
}

EdgePenetration edgeInTriangle(const std::array<Real, 3>& start, const std::array<Real, 3>& end)
{
    EdgePenetration r;
    // lambda_k(s) = a[k] + b[k] s along the edge
    Real a[3], b[3];
    Real sMin = 0, sMax = 1;
    for (int k = 0; k < 3; ++k)
    {
        a[k] = start[k];
        b[k] = end[k] - start[k];
        if (b[k] > 0)
            sMin = std::max(sMin, -a[k] / b[k]);
        else if (b[k] < 0)
            sMax = std::min(sMax, -a[k] / b[k]);
        else if (a[k] < 0)
            return r;
    }
    if (!(sMax > sMin))
        return r;
    // Break points of min(lambda_k) inside (sMin, sMax).
    Real points[5] = {sMin, sMax, 0, 0, 0};
    int count = 2;
    for (int k = 0; k < 3; ++k)
        for (int l = k + 1; l < 3; ++l)
        {
            const Real db = b[k] - b[l];
            if (db == 0)
                continue;
            const Real s = (a[l] - a[k]) / db;
            if (s > sMin && s < sMax)
                points[count++] = s;
        }
    for (int i = 1; i < count; ++i) // insertion sort of at most 5 values
        for (int j = i; j > 0 && points[j] < points[j - 1]; --j)
            std::swap(points[j], points[j - 1]);
    const auto phi = [&](Real s)
    {
        const Real m = std::min({a[0] + b[0] * s, a[1] + b[1] * s, a[2] + b[2] * s});
        return 3 * std::max(m, Real(0));
    };
    Real i0 = 0, i1 = 0;
    Real sa = points[0], fa = phi(sa);
    for (int i = 1; i < count; ++i)
    {
        const Real sb = points[i], fb = phi(sb), h = sb - sa;
        i0 += 0.5 * h * (fa + fb);
        i1 += h / 6 * (fa * (2 * sa + sb) + fb * (sa + 2 * sb));
        sa = sb;
        fa = fb;
    }
    if (!(i0 > 0))
        return r;
    r.integral = i0;
    r.firstMoment = i1;
    r.insideFraction = sMax - sMin;
    for (int k = 0; k < 3; ++k)
        r.targetWeight[k] = (a[k] * i0 + b[k] * i1) / i0;
    return r;
}

TrianglePairForces potentialContactForces(const std::array<Vec2, 3>& a, const std::array<Vec2, 3>& b,
                                          Real penalty)
{
    TrianglePairForces f;
    const auto oneRole = [penalty](const std::array<Vec2, 3>& c, const std::array<Vec2, 3>& t,
                                   std::array<Vec2, 3>& fc, std::array<Vec2, 3>& ft)
    {
        for (int e = 0; e < 3; ++e)
        {
            const Vec2 &p0 = c[e], &p1 = c[(e + 1) % 3];
            const EdgePenetration pen = edgeInTriangle(p0, p1, t);
            if (!pen.touching())
                continue;
            const Vec2 n = outwardNormal(p0, p1);
            const Real scale = penalty * length(p1 - p0);
            fc[e] -= scale * (pen.integral - pen.firstMoment) * n;
            fc[(e + 1) % 3] -= scale * pen.firstMoment * n;
            for (int k = 0; k < 3; ++k)
                ft[k] += scale * pen.integral * pen.targetWeight[k] * n;
        }
    };
    oneRole(a, b, f.onFirst, f.onSecond);
    oneRole(b, a, f.onSecond, f.onFirst);
    return f;
}

} // namespace veridem::fdem
