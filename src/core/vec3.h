// 3-vector of doubles with the arithmetic the DEM kernels need.
// A plain aggregate (24 bytes) so that std::vector<Vec3> is a contiguous xyz array.
#pragma once

#include <cmath>

namespace veridem
{

using Real = double;

struct Vec3
{
    Real x = 0, y = 0, z = 0;

    constexpr Vec3& operator+=(const Vec3& o)
    {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    constexpr Vec3& operator-=(const Vec3& o)
    {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    constexpr Vec3& operator*=(Real s)
    {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr bool operator==(const Vec3&) const = default;
};
static_assert(sizeof(Vec3) == 24);

constexpr Vec3 operator+(Vec3 a, const Vec3& b)
{
    return a += b;
}
constexpr Vec3 operator-(Vec3 a, const Vec3& b)
{
    return a -= b;
}
constexpr Vec3 operator-(const Vec3& a)
{
    return {-a.x, -a.y, -a.z};
}
constexpr Vec3 operator*(Vec3 a, Real s)
{
    return a *= s;
}
constexpr Vec3 operator*(Real s, Vec3 a)
{
    return a *= s;
}
constexpr Vec3 operator/(const Vec3& a, Real s)
{
    return {a.x / s, a.y / s, a.z / s};
}

constexpr Real dot(const Vec3& a, const Vec3& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr Real lengthSquared(const Vec3& a)
{
    return dot(a, a);
}
inline Real length(const Vec3& a)
{
    return std::sqrt(dot(a, a));
}
/// Unit vector along a, or the zero vector when |a| == 0.
inline Vec3 normalizedOrZero(const Vec3& a)
{
    const Real l = length(a);
    return l > 0 ? a / l : Vec3{};
}
inline bool isFinite(const Vec3& a)
{
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

} // namespace veridem
