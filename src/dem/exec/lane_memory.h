// Moving contacts' values between memory and SIMD lanes (dem/lanes.h): gathers of particle rows by
// index, and transposes of per-quantity lanes into one (x, y, z, 0) row per contact for the
// scatter. Data movement only: no physics here.
#pragma once

#include "dem/lanes.h"

#include <cstdint>

namespace veridem::dem::lanes
{

/// Four contacts' x, y, z lanes -> one (x, y, z, 0) vector per contact: unpacks within 128-bit
/// halves, then half swaps (8 shuffles; interleaving across halves first costs 14).
VERIDEM_HOT_INLINE void transpose(const Lanes4& x, const Lanes4& y, const Lanes4& z, Lanes4* out)
{
    const Lanes4 zero = {};
    const Lanes4 xyEven = __builtin_shufflevector(x, y, 0, 4, 2, 6);    // x0 y0 x2 y2
    const Lanes4 xyOdd = __builtin_shufflevector(x, y, 1, 5, 3, 7);     // x1 y1 x3 y3
    const Lanes4 z0Even = __builtin_shufflevector(z, zero, 0, 4, 2, 6); // z0 0 z2 0
    const Lanes4 z0Odd = __builtin_shufflevector(z, zero, 1, 5, 3, 7);  // z1 0 z3 0
    out[0] = __builtin_shufflevector(xyEven, z0Even, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(xyOdd, z0Odd, 0, 1, 4, 5);
    out[2] = __builtin_shufflevector(xyEven, z0Even, 2, 3, 6, 7);
    out[3] = __builtin_shufflevector(xyOdd, z0Odd, 2, 3, 6, 7);
}

/// Two contacts (the portable variant: one SSE2 register per quantity).
VERIDEM_HOT_INLINE void transpose(const Lanes2& x, const Lanes2& y, const Lanes2& z, Lanes4* out)
{
    out[0] = Lanes4{x[0], y[0], z[0], 0.0};
    out[1] = Lanes4{x[1], y[1], z[1], 0.0};
}

/// sum[0..3] += v; sum[0..3] -= v (a PaddedVec3).
VERIDEM_HOT_INLINE void addInto(double* sum, const Lanes4& v)
{
    store(sum, load<Lanes4>(sum) + v);
}
VERIDEM_HOT_INLINE void subtractFrom(double* sum, const Lanes4& v)
{
    store(sum, load<Lanes4>(sum) - v);
}

/// Lanes l = a[index[l]].*field (element loads and inserts, no staging through memory).
template <class V> VERIDEM_HOT_INLINE V gather(const Vec3* a, const std::uint32_t* index, double Vec3::*field)
{
    if constexpr (kWidth<V> == 4)
        return V{a[index[0]].*field, a[index[1]].*field, a[index[2]].*field, a[index[3]].*field};
    else
        return V{a[index[0]].*field, a[index[1]].*field};
}
template <class V> VERIDEM_HOT_INLINE V gather(const double* a, const std::uint32_t* index)
{
    if constexpr (kWidth<V> == 4)
        return V{a[index[0]], a[index[1]], a[index[2]], a[index[3]]};
    else
        return V{a[index[0]], a[index[1]]};
}

/// The three components of a[index[l]] in lanes. Four lanes: (x, y) of each vector with one
/// 16-byte load, two of them joined per register and split by unpacking (4 shuffles for x and y
/// instead of 6 with element inserts: the shuffle port bounds the four-lane kernel on Zen 3).
template <class V> struct Lanes3
{
    V x, y, z;
};
template <class V> VERIDEM_HOT_INLINE Lanes3<V> gatherVec3(const Vec3* a, const std::uint32_t* index)
{
    if constexpr (kWidth<V> == 4)
    {
        const Lanes2 xy0 = load<Lanes2>(&a[index[0]].x), xy1 = load<Lanes2>(&a[index[1]].x),
                     xy2 = load<Lanes2>(&a[index[2]].x), xy3 = load<Lanes2>(&a[index[3]].x);
        const Lanes4 even = __builtin_shufflevector(xy0, xy2, 0, 1, 2, 3); // x0 y0 x2 y2
        const Lanes4 odd = __builtin_shufflevector(xy1, xy3, 0, 1, 2, 3);  // x1 y1 x3 y3
        return {__builtin_shufflevector(even, odd, 0, 4, 2, 6),
                __builtin_shufflevector(even, odd, 1, 5, 3, 7), gather<V>(a, index, &Vec3::z)};
    }
    else
        return {gather<V>(a, index, &Vec3::x), gather<V>(a, index, &Vec3::y), gather<V>(a, index, &Vec3::z)};
}

} // namespace veridem::dem::lanes
