// Vector lanes shared by the contact kernels (forces.cpp) and the integration loops
// (integrate.cpp): GCC vector types, the target attribute of the four-lane (AVX2) variant, and
// unaligned loads and stores.
//
// Every lane performs the IEEE operations of the scalar code it replaces, in the same order, and
// no multiply-add is fused (-ffp-contract=off), so each variant gives the bits of the scalar path.
#pragma once

#include "core/hot.h"

#include <cstddef>
#include <cstring>

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

} // namespace veridem::dem::lanes
