// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CwenoWeights.h
/// Linear and nonlinear weights of the CWENO and CWENOZ operators (Definition 3.1):
/// one optimal polynomial (k = 0) and 2^D octant polynomials (k = 1..2^D).

#include "sltk/interp/Lanes.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace sltk
{

/// Which operator of Definition 3.1 builds the reconstruction polynomial.
enum class CwenoVariant : std::uint8_t
{
  Cweno = 0,  ///< weights (3.13), polynomial (3.15)
  CwenoZ = 1, ///< weights (3.14) with the global indicator tau (3.22)/(3.27), polynomial (3.16)
  Optimal = 2 ///< omega = d: the optimal polynomial itself (unlimited; reference for tests)
};

namespace cweno
{

/// Linear coefficients d_k. d_0 = 3/4 as in the thesis (1D: d_L = d_R = 1/8,
/// 3.3.1; 2D: d_k = 1/16, 3.3.2); in 3D d_0 = 3/4 is kept and the remaining 1/4
/// is shared by the eight octants (d_k = 1/32). The convergence estimate of 3.4
/// bounds |P_0 - I_1| by (C_opt + (1 - d_0) C_low) / d_0, so the same d_0 keeps
/// the thesis's margin (d_0 >= 0.336 is needed in 1D).
template <int D>
struct LinearWeights
{
  static constexpr int Octants = 1 << D;
  static constexpr int Count = 1 + Octants;
  static constexpr double Optimal = 0.75;
  static constexpr double Octant = 0.25 / Octants;

  static constexpr std::array<double, Count> values()
  {
    std::array<double, Count> d{};
    d[0] = Optimal;
    for (int k = 1; k < Count; ++k)
    {
      d[k] = Octant;
    }
    return d;
  }
};

/// Global smoothness indicator of CWENOZ: tau = |2^D OSC_0 - sum_k OSC_k|,
/// (3.22) in 1D, (3.27) in 2D; in 3D the eight octant indicators share the
/// O(h^2) term with OSC_0 and their O(h^3) terms are odd under the reflections
/// that swap octants, so tau = O(h^4) (checked by bench/derive/derive_cweno.py --taylor).
/// T is double or a SIMD vector of lanes (Lanes.h), each lane with the same
/// operations in the same order.
/// (Into `tau`: a vector returned by value would change the ABI.)
template <int Count, class T>
SLTK_LANES_INLINE void globalIndicatorOf(const T* osc, T& tau)
{
  T s = static_cast<double>(Count - 1) * osc[0];
  for (int k = 1; k < Count; ++k)
  {
    s -= osc[k];
  }
  lanes::absOf(s, tau);
}

template <size_t Count>
inline double globalIndicator(const std::array<double, Count>& osc)
{
  double tau = 0.0;
  globalIndicatorOf<static_cast<int>(Count)>(osc.data(), tau);
  return tau;
}

/// Nonlinear weights w[k] from the indicators osc[k] (k = 0: optimal polynomial)
/// with l = 2 and the given epsilon: (3.13) for CWENO, (3.14) for CWENOZ;
/// T as in globalIndicatorOf().
template <int D, CwenoVariant V, class T>
SLTK_LANES_INLINE void nonlinearWeightsOf(const T* osc, double epsilon, T* w)
{
  constexpr int count = LinearWeights<D>::Count;
  constexpr std::array<double, count> d = LinearWeights<D>::values();
  if constexpr (V == CwenoVariant::Optimal)
  {
    for (int k = 0; k < count; ++k)
    {
      w[k] = T{} + d[k];
    }
    return;
  }
  else if constexpr (V == CwenoVariant::Cweno)
  {
    for (int k = 0; k < count; ++k)
    {
      const T s = osc[k] + epsilon;
      w[k] = d[k] / (s * s); // (3.13), l = 2
    }
  }
  else
  {
    T tau;
    globalIndicatorOf<count>(osc, tau);
    for (int k = 0; k < count; ++k)
    {
      const T r = tau / (osc[k] + epsilon);
      w[k] = d[k] * (1.0 + r * r); // (3.14), l = 2
    }
  }
  T sum = w[0];
  for (int k = 1; k < count; ++k)
  {
    sum += w[k];
  }
  const T inverse = 1.0 / sum;
  for (int k = 0; k < count; ++k)
  {
    w[k] *= inverse;
  }
}

/// nonlinearWeightsOf() on arrays of doubles.
template <int D, CwenoVariant V>
inline std::array<double, LinearWeights<D>::Count> nonlinearWeights(
  const std::array<double, LinearWeights<D>::Count>& osc, double epsilon)
{
  std::array<double, LinearWeights<D>::Count> w{};
  nonlinearWeightsOf<D, V>(osc.data(), epsilon, w.data());
  return w;
}

} // namespace cweno
} // namespace sltk
