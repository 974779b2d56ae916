// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReinitScheme.h
/// The monotone schemes for the reinitialisation PDE (1.30),
///   phi_tau + S(phi0) (|grad phi| - 1) = 0,
/// thesis 1.5.1: the sign approximation (1.31) and one forward-Euler
/// pseudo-time step of the upwind scheme (1.32) or of Godunov's scheme (1.35),
/// both built on the one-sided differences (1.33) and monotone under a
/// Courant condition ((1.34); ReinitOptions::courantLimit).
///
/// Reading of the text conversion: a, b, c, d of (1.33) are divided
/// differences, so the step is phi - dtau s (H - 1) (the printed dtau/dx
/// factor belongs to undivided differences), and Godunov's scheme takes the
/// max on every axis, as in Russo-Smereka [100]: the printed "min" on the y
/// terms of (1.35) would drop the y derivative wherever phi is monotone in y.

#include "sltk/interp/Lanes.h"

#include <cmath>
#include <cstdint>

namespace sltk
{

enum class ReinitScheme : std::uint8_t
{
  Upwind = 0, ///< (1.32): sqrt((a+)^2 + (b-)^2 + ...) for s > 0
  Godunov = 1 ///< (1.35): sqrt(max[(a+)^2, (b-)^2] + ...) for s > 0
};

/// Sign approximation (1.31): phi0 / sqrt(phi0^2 + |D phi0|^2 dx^2); 0 at phi0 = 0.
inline double reinitSign(double phi0, double gradientNorm, double dx)
{
  const double den = std::sqrt(phi0 * phi0 + gradientNorm * gradientNorm * dx * dx);
  return den == 0.0 ? 0.0 : phi0 / den; // a NaN stays a NaN
}

/// Upwind approximation of |grad phi| at a node for the characteristic
/// direction of the sign s, from u = {u_i, u_{i-e_0}, u_{i+e_0}, u_{i-e_1}, ...}
/// (ReinitStencil::axes) and the inverse spacings, into `norm`. V is double or
/// a vector of nodes in lanes that make these operations in this order
/// (Lanes.h; the band's pseudo-time steps, Reinitialise.cxx).
template <int D, class V>
SLTK_LANES_INLINE void upwindGradientNorm(
  ReinitScheme scheme, const V* u, const double* inverseSpacing, const V& s, V& norm)
{
  const V zero{};
  const auto positive = s > zero;
  V sum = zero;
  for (int axis = 0; axis < D; ++axis)
  {
    const V minus = (u[0] - u[1 + 2 * axis]) * inverseSpacing[axis]; // a = D^- phi (1.33)
    const V plus = (u[2 + 2 * axis] - u[0]) * inverseSpacing[axis];  // b = D^+ phi (1.33)
    // s > 0: a+ and b-; s < 0: a- and b+. Selections (std::fmax is a libm call)
    // written so that a NaN neighbour gives a NaN, never a silent 0.
    const V left = (positive ? minus <= zero : minus >= zero) ? zero : minus;
    const V right = (positive ? plus >= zero : plus <= zero) ? zero : plus;
    const V l2 = left * left;
    const V r2 = right * right;
    sum += scheme == ReinitScheme::Godunov ? (l2 > r2 ? l2 : r2) // (1.35)
                                           : l2 + r2;            // (1.32)
  }
  lanes::sqrtOf(sum, norm);
}

/// One pseudo-time step of (1.32) / (1.35) at a node, u_i - dtau s (|grad phi| - 1)
/// (u_i where s = 0), into `next`.
template <int D, class V>
SLTK_LANES_INLINE void reinitStep(
  ReinitScheme scheme, const V* u, const double* inverseSpacing, const V& s, double dtau, V& next)
{
  V norm;
  upwindGradientNorm<D>(scheme, u, inverseSpacing, s, norm);
  const V moved = u[0] - dtau * s * (norm - 1.0);
  next = s == V{} ? u[0] : moved;
}

/// upwindGradientNorm of one node.
template <int D>
inline double upwindGradientNorm(ReinitScheme scheme, const double* u, const double* inverseSpacing, double s)
{
  double norm = 0.0;
  upwindGradientNorm<D, double>(scheme, u, inverseSpacing, s, norm);
  return norm;
}

/// reinitStep of one node.
template <int D>
inline double reinitStep(ReinitScheme scheme, const double* u, const double* inverseSpacing, double s, double dtau)
{
  double next = 0.0;
  reinitStep<D, double>(scheme, u, inverseSpacing, s, dtau, next);
  return next;
}

/// One step of Russo and Smereka's relaxation (1.36) next to the front:
/// phi - dtau/dx (S(phi0) |phi| - d), S(phi0) the sign of d (1.37), into `next`.
template <class V>
SLTK_LANES_INLINE void russoSmerekaStep(const V& u, const V& distance, double courant, V& next)
{
  const V zero{};
  const V one = zero + 1.0;
  const V sign = distance > zero ? one : (distance < zero ? zero - one : zero);
  V magnitude;
  lanes::absOf(u, magnitude);
  next = u - courant * (sign * magnitude - distance);
}

/// The pseudo-time step of band nodes in lanes (Reinitialise.cxx,
/// TiledReinitStep.h): (1.32)/(1.35) with the sign c of (1.31), or, in the
/// lanes of `*relax` when given, (1.36) towards the distance c of (1.37);
/// into `next`. M is the comparison mask of V.
template <int D, class V, class M>
SLTK_LANES_INLINE void bandNodeStep(ReinitScheme scheme, const V* u, const double* inverseSpacing, const V& c,
  double dtau, double courant, const M* relax, V& next)
{
  reinitStep<D>(scheme, u, inverseSpacing, c, dtau, next); // (1.32)/(1.35)
  if (relax)
  {
    V relaxed;
    russoSmerekaStep(u[0], c, courant, relaxed); // (1.36)
    next = *relax ? relaxed : next;
  }
}

/// russoSmerekaStep of one node.
inline double russoSmerekaStep(double u, double distance, double courant)
{
  double next = 0.0;
  russoSmerekaStep<double>(u, distance, courant, next);
  return next;
}

} // namespace sltk
