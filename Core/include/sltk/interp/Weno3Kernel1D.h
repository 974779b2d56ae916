// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Weno3Kernel1D.h
/// The 1D building block of the third-order WENO interpolation of thesis
/// 2.3.4, (2.65)-(2.76): in the cell [x_i, x_{i+1}], with x = x_i + t dx,
/// the parabolas P_L on {x_{i-1}, x_i, x_{i+1}} and P_R on {x_i, x_{i+1},
/// x_{i+2}} are blended with nonlinear weights built from the point-dependent
/// linear weights C_L, C_R (2.76), which reproduce the cubic Q of (2.65).
///
/// Both parabolas share the Newton form
///   P_k(t) = (1 - t) f0 + t f1 + t (t - 1) / 2 * D2_k,
/// with the second increments D2_L = f_{-1} - 2 f0 + f1, D2_R = f0 - 2 f1 + f2,
/// so the reconstruction (2.69) is the linear interpolant plus
/// t (t - 1) / 2 * (w_L D2_L + w_R D2_R): it interpolates the nodal values
/// whatever the weights, and |I - I_1| <= max(|D2_L|, |D2_R|) / 8 (the
/// constant C_2 = 1/8 of (2.91)/(3.31)).

namespace sltk
{

/// Nonlinear weights (2.68) of the left and right parabolas; they sum to 1.
struct Weno3Weights
{
  double Left = 0.0;
  double Right = 0.0;
};

/// Weights (2.67)-(2.68) at local coordinate t (x = x_i + t dx, t in [0, 1])
/// from the values f(x_{i-1}), f(x_i), f(x_{i+1}), f(x_{i+2}).
///
/// `eps` must be the thesis's epsilon = dx^2 of this axis (2.67), with dx
/// in the units of the grid. The indicators (2.70) of the parabolas are
/// OSC_k = D2_k^2 / dx^2 (the quadratic forms U^T A_k U / dx^2 of 2.3.4), so
/// dx^2 (OSC_k + eps) = D2_k^2 + eps^2: the weights are computed from these
/// scaled quantities, which leaves (2.68) unchanged and needs no dx. Valid
/// while eps^4 does not underflow (dx > 1e-38) and D2^4 does not overflow.
inline Weno3Weights weno3Weights1D(double fm1, double f0, double f1, double f2, double t, double eps)
{
  const double d2L = fm1 - 2.0 * f0 + f1;
  const double d2R = f0 - 2.0 * f1 + f2;
  // indicators (2.70), scaled by dx^2 and shifted by eps (2.67)
  const double eps2 = eps * eps;
  const double bL = d2L * d2L + eps2;
  const double bR = d2R * d2R + eps2;
  // linear weights (2.76): C_L = (x_{i+2} - x) / (3 dx), C_R = (x - x_{i-1}) / (3 dx)
  const double cL = (2.0 - t) * (1.0 / 3.0);
  const double cR = (1.0 + t) * (1.0 / 3.0);
  // alpha_k = C_k / (OSC_k + eps)^2 (2.67), normalised (2.68); multiplied through by bL^2 bR^2
  const double aL = cL * (bR * bR);
  const double aR = cR * (bL * bL);
  const double inv = 1.0 / (aL + aR);
  return { aL * inv, aR * inv };
}

/// WENO3 interpolation (2.69) at x = x_i + t dx; see weno3Weights1D for `eps`.
inline double weno3Interpolate1D(double fm1, double f0, double f1, double f2, double t, double eps)
{
  const Weno3Weights w = weno3Weights1D(fm1, f0, f1, f2, t, eps);
  const double d2L = fm1 - 2.0 * f0 + f1;
  const double d2R = f0 - 2.0 * f1 + f2;
  // sum_k w_k P_k (2.69) in the shared Newton form (exact at t = 0 and t = 1)
  return (1.0 - t) * f0 + t * f1 + 0.5 * t * (t - 1.0) * (w.Left * d2L + w.Right * d2R);
}

} // namespace sltk
