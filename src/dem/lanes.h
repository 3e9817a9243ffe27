// The number types the contact law and the integration loops are compiled for: `double` (width
// one, the scalar path) and GCC vector types of two (SSE2) or four (AVX2) doubles, with the small
// interface the law is written against (lane.h's any/all reductions, sqrt, abs, a 3-vector of
// lanes), unaligned loads and stores, and the target attribute of the four-lane variant.
//
// The law (contact/law.h) is one template over the number type T. A comparison gives a bool for
// `double` and a lane mask for a vector; `mask ? a : b` selects in both; `anyLane`/`allLanes`
// reduce a mask (identity for bool). Every lane performs the IEEE operations of the scalar code in
// the same order, and no multiply-add is fused (-ffp-contract=off), so every width gives the bits
// of width one by construction.
#pragma once

#include "core/hot.h"
#include "core/vec3.h"

#include <cmath>
#include <cstddef>
#include <cstring>
#include <type_traits>

// The four-lane variant is compiled for x86-64-v3 (AVX2, FMA unused: -ffp-contract=off), unless
// the whole build already targets a CPU that has it (VERIDEM_NATIVE): then the attribute would
// be a narrower target than its callees' and GCC could not inline them.
#if defined(__AVX2__) && defined(__FMA__) && defined(__BMI2__)
#define VERIDEM_AVX2_TARGET
#else
#define VERIDEM_AVX2_TARGET [[gnu::target("arch=x86-64-v3")]]
#endif

namespace veridem::dem::lanes
{

using Lanes2 = double __attribute__((vector_size(16)));
using Lanes4 = double __attribute__((vector_size(32)));
using Index4 = long long __attribute__((vector_size(32)));

template <class V> constexpr std::size_t kWidth = sizeof(V) / sizeof(double);

// Always inlined, so that they compile for the instruction set of the function that calls them.
template <class V> VERIDEM_HOT_INLINE V load(const double* a)
{
    V v;
    std::memcpy(&v, a, sizeof v);
    return v;
}
template <class V> VERIDEM_HOT_INLINE void store(double* a, const V& v)
{
    std::memcpy(a, &v, sizeof v);
}

/// The value v in every lane of T (T = double: v itself).
template <class T> VERIDEM_HOT_INLINE T broadcast(double v)
{
    if constexpr (std::is_same_v<T, double>)
        return v;
    else
        return T{} + v;
}

/// Correctly rounded square root, as std::sqrt, lane by lane (one packed instruction).
VERIDEM_HOT_INLINE double laneSqrt(double x)
{
    return __builtin_sqrt(x); // -fno-math-errno: the instruction itself
}
template <class V> VERIDEM_HOT_INLINE V laneSqrt(V x)
{
    V r;
    for (std::size_t l = 0; l < kWidth<V>; ++l)
        r[l] = __builtin_sqrt(x[l]);
    return r;
}

/// Cube root, as std::cbrt, lane by lane (the same library call per lane, so the same bits at
/// every width; only the cohesion models use it).
VERIDEM_HOT_INLINE double laneCbrt(double x)
{
    return std::cbrt(x);
}
template <class V> VERIDEM_HOT_INLINE V laneCbrt(V x)
{
    V r;
    for (std::size_t l = 0; l < kWidth<V>; ++l)
        r[l] = std::cbrt(x[l]);
    return r;
}

/// |x|, lane by lane (clears the sign bit, as std::fabs).
VERIDEM_HOT_INLINE double laneAbs(double x)
{
    return std::fabs(x);
}
template <class V> VERIDEM_HOT_INLINE V laneAbs(V x)
{
    using Mask = decltype(x < x);
    return reinterpret_cast<V>(reinterpret_cast<Mask>(x) & 0x7fffffffffffffffLL);
}

// Reductions of a comparison mask (lanes 0 or -1) by halving: a few register operations, where a
// loop over the lanes compiled to a chain of extracts and branches. (movmskpd would be one
// instruction, but a target-specific builtin cannot be inlined into these untargeted templates.)
VERIDEM_HOT_INLINE bool anyLane(bool b)
{
    return b;
}
VERIDEM_HOT_INLINE bool allLanes(bool b)
{
    return b;
}
template <class M> VERIDEM_HOT_INLINE bool anyLane(const M& mask)
{
    if constexpr (sizeof(M) == 32)
    {
        const auto half =
            __builtin_shufflevector(mask, mask, 0, 1) | __builtin_shufflevector(mask, mask, 2, 3);
        return (half[0] | half[1]) != 0;
    }
    else
        return (mask[0] | mask[1]) != 0;
}
template <class M> VERIDEM_HOT_INLINE bool allLanes(const M& mask)
{
    if constexpr (sizeof(M) == 32)
    {
        const auto half =
            __builtin_shufflevector(mask, mask, 0, 1) & __builtin_shufflevector(mask, mask, 2, 3);
        return (half[0] & half[1]) != 0;
    }
    else
        return (mask[0] & mask[1]) != 0;
}

/// A 3-vector of lanes: component c of contact l is c[l]. The operations are Vec3's, component
/// by component in the same order.
template <class T> struct V3
{
    T x, y, z;
};
template <class T> VERIDEM_HOT_INLINE V3<T> operator+(const V3<T>& a, const V3<T>& b)
{
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T> VERIDEM_HOT_INLINE V3<T> operator-(const V3<T>& a, const V3<T>& b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T> VERIDEM_HOT_INLINE V3<T> operator-(const V3<T>& a)
{
    return {-a.x, -a.y, -a.z};
}
template <class T> VERIDEM_HOT_INLINE V3<T> operator*(const V3<T>& a, const T& s)
{
    return {a.x * s, a.y * s, a.z * s};
}
template <class T> VERIDEM_HOT_INLINE V3<T> operator*(const T& s, const V3<T>& a)
{
    return {a.x * s, a.y * s, a.z * s};
}
template <class T> VERIDEM_HOT_INLINE V3<T> operator*(const V3<T>& a, double s)
{
    return {a.x * s, a.y * s, a.z * s};
}
template <class T> VERIDEM_HOT_INLINE V3<T> operator*(double s, const V3<T>& a)
{
    return {a.x * s, a.y * s, a.z * s};
}
template <class T> VERIDEM_HOT_INLINE V3<T> operator/(const V3<T>& a, const T& s)
{
    return {a.x / s, a.y / s, a.z / s};
}
template <class T> VERIDEM_HOT_INLINE T dot(const V3<T>& a, const V3<T>& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T> VERIDEM_HOT_INLINE V3<T> cross(const V3<T>& a, const V3<T>& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> VERIDEM_HOT_INLINE T lengthSquared(const V3<T>& a)
{
    return dot(a, a);
}
/// mask ? a : b, component by component.
template <class M, class T> VERIDEM_HOT_INLINE V3<T> select(const M& mask, const V3<T>& a, const V3<T>& b)
{
    return {mask ? a.x : b.x, mask ? a.y : b.y, mask ? a.z : b.z};
}
VERIDEM_HOT_INLINE Vec3 select(bool mask, const Vec3& a, const Vec3& b)
{
    return mask ? a : b;
}

/// The 3-vector of number type T: Vec3 for double (the scalar path's own type and operations),
/// V3<T> for lanes.
template <class T> using Vec3Of = std::conditional_t<std::is_same_v<T, double>, Vec3, V3<T>>;

/// The comparison mask of T: bool for double, the lane mask for a vector.
template <class T> using MaskOf = decltype(T{} < T{});

} // namespace veridem::dem::lanes
