// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Characteristics.h
/// Backward tracking of one characteristic over a time step with an explicit
/// RK method, and the cost quadrature on its stage values (thesis 2.3.1 and
/// 3.2, (3.5)-(3.9)).
///
/// Sign convention (the thesis's chapter 3, (3.1)-(3.4), which we follow):
/// the dynamics f_D is the right-hand side of the characteristic system in the
/// backward variable s = t_{n+1} - t,
///     y'(s) = f_D(t_{n+1} - s, y(s), a(s)),  y(0) = x_i,          (3.2)
/// and the foot is y(dt) = x_i + dt * sum_k b_k K_k, (3.8). For a fixed
/// control, (3.1) with H of (3.3) is the transport equation
/// v_t - f_D . grad v = f_C, so a PDE v_t + f . grad v = g has f_D = -f,
/// f_C = g (Test 1, 3.5.1, writes exactly v_t - f_D . grad v = 0). Chapter 2
/// writes y' = +f in (2.9)/(2.40)/(2.42) for v_t + f v_x = g, which contradicts
/// its own (2.2)-(2.4) and CIR (2.12) (foot x_i - dt f): that sign is a slip,
/// and LinearSLStep.h passes f_D = -f.
///
/// Time convention: stage k is evaluated at t_{n+1} - c_k dt with control a_k,
/// as in (3.8)-(3.9) (the text after (3.5) says alpha(t_n + c_k dt), which is
/// a different instant unless c_k = 1/2; (3.8) is what we implement).
///
/// Everything here is allocation-free, with no virtual calls: the HJB solver
/// calls traceCharacteristic() and stageQuadrature() once per node and per
/// candidate control a = (a_1, ..., a_S).

#include "sltk/sl/ButcherTableau.h"

#include <array>

namespace sltk
{

/// Stage values of one traced characteristic (3.8).
template <int D, int S>
struct CharacteristicStages
{
  using Vector = std::array<double, D>;

  std::array<Vector, S> X{}; ///< stage values X_k, X_1 = x_i
  std::array<double, S> T{}; ///< stage times t_{n+1} - c_k dt
  Vector Foot{};             ///< y_i^n = x_i + dt sum_k b_k K_k
};

/// Traces the characteristic through node x at time tNext = t_{n+1} back over
/// dt with the tableau's RK method, (3.8) (and (2.42) with the sign of (3.2)):
///   K_k = fD(t_{n+1} - c_k dt, X_k, k),  X_k = x + dt sum_{j<k} A_kj K_j,
///   y   = x + dt sum_k b_k K_k.
/// fD(double t, const std::array<double, D>& X, int k) -> std::array<double, D>
/// is the dynamics of (3.2); the stage index k selects the control a_k of the
/// HJB scheme, plain advection ignores it.
template <int D, int S, class Dynamics>
inline void traceCharacteristic(const ButcherTableau<S>& tableau, const typename CharacteristicStages<D, S>::Vector& x,
  double tNext, double dt, Dynamics&& fD, CharacteristicStages<D, S>& out)
{
  std::array<std::array<double, D>, S> slope{}; // K_k
  for (int k = 0; k < S; ++k)
  {
    std::array<double, D> xk = x;
    for (int j = 0; j < k; ++j)
    {
      const double a = dt * tableau.A[k][j];
      for (int d = 0; d < D; ++d)
      {
        xk[d] += a * slope[j][d];
      }
    }
    out.X[k] = xk;
    out.T[k] = tNext - tableau.C[k] * dt;
    slope[k] = fD(out.T[k], xk, k);
  }
  std::array<double, D> y = x;
  for (int k = 0; k < S; ++k)
  {
    const double b = dt * tableau.B[k];
    for (int d = 0; d < D; ++d)
    {
      y[d] += b * slope[k][d];
    }
  }
  out.Foot = y;
}

/// The cost of the step along the traced characteristic, (3.9) with
/// xi_k = c_k, w_k = b_k and the stage values in place of the exact
/// trajectory ((2.46)-(2.56): rectangle, trapezoid, Simpson):
///   C = dt sum_k b_k fC(t_{n+1} - c_k dt, X_k, k).
/// fC(double t, const std::array<double, D>& X, int k) -> double is the running
/// cost f_C (or the source g of (2.7)); k selects a_k as in traceCharacteristic().
template <int D, int S, class Cost>
inline double stageQuadrature(const ButcherTableau<S>& tableau, const CharacteristicStages<D, S>& stages, double dt,
  Cost&& fC)
{
  double sum = 0.0;
  for (int k = 0; k < S; ++k)
  {
    sum += tableau.B[k] * fC(stages.T[k], stages.X[k], k);
  }
  return dt * sum;
}

} // namespace sltk
