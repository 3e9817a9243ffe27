// 2-vector and 2x2 matrix for the 2D FEM/DEM engine (plane problems, per unit thickness).
// Plain aggregates so that std::vector<Vec2> is a contiguous xy array.
#pragma once

#include "core/vec3.h"

#include <cmath>

namespace veridem::fdem
{

struct Vec2
{
    Real x = 0, y = 0;

    constexpr Vec2& operator+=(const Vec2& o)
    {
        x += o.x;
        y += o.y;
        return *this;
    }
    constexpr Vec2& operator-=(const Vec2& o)
    {
        x -= o.x;
        y -= o.y;
        return *this;
    }
    constexpr Vec2& operator*=(Real s)
    {
        x *= s;
        y *= s;
        return *this;
    }
    constexpr bool operator==(const Vec2&) const = default;
};
static_assert(sizeof(Vec2) == 16);

constexpr Vec2 operator+(Vec2 a, const Vec2& b)
{
    return a += b;
}
constexpr Vec2 operator-(Vec2 a, const Vec2& b)
{
    return a -= b;
}
constexpr Vec2 operator-(const Vec2& a)
{
    return {-a.x, -a.y};
}
constexpr Vec2 operator*(Vec2 a, Real s)
{
    return a *= s;
}
constexpr Vec2 operator*(Real s, Vec2 a)
{
    return a *= s;
}
constexpr Vec2 operator/(const Vec2& a, Real s)
{
    return {a.x / s, a.y / s};
}
constexpr Real dot(const Vec2& a, const Vec2& b)
{
    return a.x * b.x + a.y * b.y;
}
/// z component of the 3D cross product (a, 0) x (b, 0).
constexpr Real cross(const Vec2& a, const Vec2& b)
{
    return a.x * b.y - a.y * b.x;
}
/// a rotated by +90 degrees.
constexpr Vec2 perpendicular(const Vec2& a)
{
    return {-a.y, a.x};
}
constexpr Real lengthSquared(const Vec2& a)
{
    return dot(a, a);
}
inline Real length(const Vec2& a)
{
    return std::sqrt(dot(a, a));
}
inline bool isFinite(const Vec2& a)
{
    return std::isfinite(a.x) && std::isfinite(a.y);
}

/// 2x2 matrix, row major: [[xx, xy], [yx, yy]].
struct Mat2
{
    Real xx = 0, xy = 0, yx = 0, yy = 0;

    static constexpr Mat2 identity() { return {1, 0, 0, 1}; }
    /// The matrix whose columns are a and b.
    static constexpr Mat2 fromColumns(const Vec2& a, const Vec2& b) { return {a.x, b.x, a.y, b.y}; }
};
static_assert(sizeof(Mat2) == 32);

constexpr Mat2 operator*(const Mat2& a, const Mat2& b)
{
    return {a.xx * b.xx + a.xy * b.yx, a.xx * b.xy + a.xy * b.yy, a.yx * b.xx + a.yy * b.yx,
            a.yx * b.xy + a.yy * b.yy};
}
constexpr Vec2 operator*(const Mat2& a, const Vec2& v)
{
    return {a.xx * v.x + a.xy * v.y, a.yx * v.x + a.yy * v.y};
}
constexpr Mat2 operator+(const Mat2& a, const Mat2& b)
{
    return {a.xx + b.xx, a.xy + b.xy, a.yx + b.yx, a.yy + b.yy};
}
constexpr Mat2 operator*(Real s, const Mat2& a)
{
    return {s * a.xx, s * a.xy, s * a.yx, s * a.yy};
}
constexpr Mat2 transpose(const Mat2& a)
{
    return {a.xx, a.yx, a.xy, a.yy};
}
constexpr Real determinant(const Mat2& a)
{
    return a.xx * a.yy - a.xy * a.yx;
}
/// Inverse; the caller guarantees determinant(a) != 0.
constexpr Mat2 inverse(const Mat2& a)
{
    const Real d = determinant(a);
    return {a.yy / d, -a.xy / d, -a.yx / d, a.xx / d};
}

/// Symmetric 2x2 tensor (in-plane stress or strain) [Pa or 1].
struct SymTensor2
{
    Real xx = 0, yy = 0, xy = 0;
};

constexpr Vec2 operator*(const SymTensor2& t, const Vec2& n)
{
    return {t.xx * n.x + t.xy * n.y, t.xy * n.x + t.yy * n.y};
}

} // namespace veridem::fdem
