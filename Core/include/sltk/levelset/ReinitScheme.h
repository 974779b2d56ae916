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
/// (ReinitStencil::axes) and the inverse spacings.
template <int D>
inline double upwindGradientNorm(ReinitScheme scheme, const double* u, const double* inverseSpacing, double s)
{
  double sum = 0.0;
  for (int axis = 0; axis < D; ++axis)
  {
    const double minus = (u[0] - u[1 + 2 * axis]) * inverseSpacing[axis]; // a = D^- phi (1.33)
    const double plus = (u[2 + 2 * axis] - u[0]) * inverseSpacing[axis];  // b = D^+ phi (1.33)
    // s > 0: a+ and b-; s < 0: a- and b+. Ternaries (std::fmax is a libm call)
    // written so that a NaN neighbour gives a NaN, never a silent 0.
    const double left = (s > 0.0 ? !(minus <= 0.0) : !(minus >= 0.0)) ? minus : 0.0;
    const double right = (s > 0.0 ? !(plus >= 0.0) : !(plus <= 0.0)) ? plus : 0.0;
    const double l2 = left * left;
    const double r2 = right * right;
    sum += scheme == ReinitScheme::Godunov ? (l2 > r2 ? l2 : r2) // (1.35)
                                           : l2 + r2;            // (1.32)
  }
  return std::sqrt(sum);
}

/// One pseudo-time step of (1.32) / (1.35) at a node: u_i - dtau s (|grad phi| - 1).
template <int D>
inline double reinitStep(ReinitScheme scheme, const double* u, const double* inverseSpacing, double s, double dtau)
{
  if (s == 0.0)
  {
    return u[0];
  }
  return u[0] - dtau * s * (upwindGradientNorm<D>(scheme, u, inverseSpacing, s) - 1.0);
}

} // namespace sltk
