// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Lanes.h
/// L doubles in one SIMD vector, for the interpolators that evaluate the
/// 2^(d-1) feet of a node of the SL step (4.22)/(4.24) at once, one foot per
/// lane (Weno3Lanes.h, LsqQ1Lanes.h). A lane does the scalar code's
/// operations in its order, and the code is built without fused
/// multiply-adds (the "avx2" target below does not enable FMA, and the build
/// sets -ffp-contract=off), so a lane's value is the scalar code's bit for bit. On x86-64 GCC/Clang the
/// lanes run as AVX2 when the processor has it (one run-time test), as SSE2
/// pairs otherwise; elsewhere as the compiler vectorises them.

#include "sltk/core/AlwaysInline.h"

#include <cmath>
#if defined(__GNUC__) && defined(__x86_64__)
#include <emmintrin.h> // SSE2, part of every x86-64 processor
#endif

namespace sltk
{
namespace lanes
{
#define SLTK_LANES_INLINE SLTK_ALWAYS_INLINE

// x86-64 only: on i386 the scalar code may keep x87 excess precision.
#if defined(__GNUC__) && defined(__x86_64__)
#define SLTK_LANES_AVX2 1
#define SLTK_LANES_AVX2_TARGET __attribute__((target("avx2")))
/// Whether the processor runs AVX2 (asked once).
inline bool hasAvx2()
{
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
#endif

/// The GCC/Clang vector of L doubles. Spelled out: GCC drops the attribute
/// from an alias template whose size depends on its parameter.
template <int L>
struct LanesOf;
template <>
struct LanesOf<2>
{
  typedef double type __attribute__((vector_size(16), __may_alias__));
};
template <>
struct LanesOf<4>
{
  typedef double type __attribute__((vector_size(32), __may_alias__));
};
template <int L>
using Lanes = typename LanesOf<L>::type;

/// A comparison's result on Lanes<L>: all ones (true) or zero per lane.
template <int L>
struct MaskOf;
template <>
struct MaskOf<2>
{
  typedef long long type __attribute__((vector_size(16)));
};
template <>
struct MaskOf<4>
{
  typedef long long type __attribute__((vector_size(32)));
};
template <int L>
using Mask = typename MaskOf<L>::type;

// Always inlined, so the vector ABI of their signatures never applies.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

// The operations that a scalar and a lane spell differently, so that one
// template serves both (ReinitScheme.h): |x| and the square root, each the
// scalar's value bit for bit. Results go by
// reference (a vector returned by value would change the ABI).
SLTK_LANES_INLINE void absOf(const double& x, double& out)
{
  out = std::fabs(x);
}
template <int L>
SLTK_LANES_INLINE void absOfLanes(const Lanes<L>& x, Lanes<L>& out)
{
  const Mask<L> magnitude =
    (Mask<L>)x & 0x7fffffffffffffffLL; // fabs clears the sign bit (a vector cast keeps the bits)
  out = (Lanes<L>)magnitude;
}
SLTK_LANES_INLINE void absOf(const Lanes<2>& x, Lanes<2>& out)
{
  absOfLanes<2>(x, out);
}
SLTK_LANES_INLINE void absOf(const Lanes<4>& x, Lanes<4>& out)
{
  absOfLanes<4>(x, out);
}

SLTK_LANES_INLINE void sqrtOf(const double& x, double& out)
{
  out = std::sqrt(x);
}
#if defined(SLTK_LANES_AVX2)
// One vector square root: IEEE 754 rounds a square root correctly, so each lane
// is std::sqrt's value bit for bit (a negative or NaN lane gives NaN, as std::sqrt
// does, without errno); the four scalar roots of a lane-by-lane loop waited on
// each other's latency (Documentation/Profile.md, "The pseudo-time steps' loads and square roots").
SLTK_LANES_INLINE void sqrtOf(const Lanes<2>& x, Lanes<2>& out)
{
  out = _mm_sqrt_pd(x);
}
/// Two halves: the same instruction serves the AVX2 functions and the tests'
/// lanes of four outside them (an always-inlined AVX2 intrinsic may not sit in
/// the templates between it and those functions).
SLTK_LANES_INLINE void sqrtOf(const Lanes<4>& x, Lanes<4>& out)
{
  const Lanes<2> low = _mm_sqrt_pd(Lanes<2>{ x[0], x[1] });
  const Lanes<2> high = _mm_sqrt_pd(Lanes<2>{ x[2], x[3] });
  out = Lanes<4>{ low[0], low[1], high[0], high[1] };
}
#else
SLTK_LANES_INLINE void sqrtOf(const Lanes<2>& x, Lanes<2>& out)
{
  out = Lanes<2>{ std::sqrt(x[0]), std::sqrt(x[1]) };
}
SLTK_LANES_INLINE void sqrtOf(const Lanes<4>& x, Lanes<4>& out)
{
  out = Lanes<4>{ std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3]) };
}
#endif

/// out[l] = p[l]: L consecutive values, one vector load (p need not be aligned).
template <int L>
SLTK_LANES_INLINE void loadOf(const double* p, Lanes<L>& out)
{
  typedef double Unaligned __attribute__((vector_size(8 * L), aligned(8), __may_alias__));
  static_assert(alignof(Unaligned) == alignof(double), "an unaligned vector type: a plain load, not an aligned one");
  out = *reinterpret_cast<const Unaligned*>(p);
}

/// out[l] = value(l) in every lane l: the scattered values of L nodes (the
/// band's pseudo-time steps, ReinitLanes.h).
template <int L, class F>
SLTK_LANES_INLINE void gatherOf(const F& value, Lanes<L>& out)
{
  static_assert(L == 2 || L == 4, "two or four lanes");
  if constexpr (L == 2)
  {
    out = Lanes<2>{ value(0), value(1) };
  }
  else
  {
    out = Lanes<4>{ value(0), value(1), value(2), value(3) };
  }
}

/// out[l] = all ones where test(l), else zero.
template <int L, class F>
SLTK_LANES_INLINE void maskOf(const F& test, Mask<L>& out)
{
  static_assert(L == 2 || L == 4, "two or four lanes");
  if constexpr (L == 2)
  {
    out = Mask<2>{ test(0) ? -1LL : 0LL, test(1) ? -1LL : 0LL };
  }
  else
  {
    out = Mask<4>{ test(0) ? -1LL : 0LL, test(1) ? -1LL : 0LL, test(2) ? -1LL : 0LL, test(3) ? -1LL : 0LL };
  }
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
} // namespace lanes
} // namespace sltk
