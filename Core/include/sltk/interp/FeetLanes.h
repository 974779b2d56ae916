// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file FeetLanes.h
/// The dispatch shared by the interpolators that take the 2^(d-1) feet of a
/// node of the SL step (4.22)/(4.24) in SIMD lanes (Weno3Lanes.h,
/// LsqQ1Lanes.h): `Derived::evalLanes(at, out)` (always inlined) runs in an
/// AVX2 function when the processor has AVX2, otherwise as the compiler lowers
/// the vectors (SSE2 pairs on x86-64; Lanes.h).

#include "sltk/interp/Interpolator.h"
#include "sltk/interp/Lanes.h"

#include <array>

namespace sltk
{

template <class Derived, int D>
class FeetLanes
{
public:
  static constexpr int Count = 1 << (D - 1); ///< the feet of a node, one per lane

  /// The values at `at[l]`, l < Count, into out[l].
  void eval(const std::array<CellLocation<D>, Count>& at, double* out) const
  {
#if defined(SLTK_LANES_AVX2)
    if (lanes::hasAvx2())
    {
      this->evalAvx2(at, out);
      return;
    }
#endif
    this->evalAny(at, out);
  }

  /// eval() without the AVX2 lanes (the SSE2 pairs on x86-64), for the tests.
  void evalAny(const std::array<CellLocation<D>, Count>& at, double* out) const
  {
    static_cast<const Derived*>(this)->evalLanes(at, out);
  }

private:
#if defined(SLTK_LANES_AVX2)
  SLTK_LANES_AVX2_TARGET void evalAvx2(const std::array<CellLocation<D>, Count>& at, double* out) const
  {
    static_cast<const Derived*>(this)->evalLanes(at, out);
  }
#endif
};

} // namespace sltk
