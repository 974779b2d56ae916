// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ButcherTableau.h
/// The explicit Runge-Kutta methods used to track characteristics (thesis
/// 2.3.1, (2.42)-(2.45), and (3.8)). Their abscissae c_k and weights b_k are
/// also the nodes xi_k and weights w_k of the cost quadrature on the stage
/// values (2.46), (3.9): rectangle (Euler), trapezoid (Heun), Simpson (RK3).
///
/// The stage count is a compile-time constant so that stage storage lives in
/// std::array; withTableau() turns a run-time RkOrder into that constant once
/// per call, outside the loops over nodes.

#include <array>

namespace sltk
{

/// Order of the RK method = number of its stages (2.43)-(2.45).
enum class RkOrder : int
{
  Euler = 1,
  Heun = 2,
  Kutta3 = 3
};

/// Explicit RK method with S stages: A strictly lower triangular.
template <int S>
struct ButcherTableau
{
  static_assert(S >= 1, "an RK method has at least one stage");
  static constexpr int Stages = S;

  std::array<double, S> C{};                  ///< abscissae c_k (quadrature nodes xi_k)
  std::array<std::array<double, S>, S> A{};   ///< A[k][j], j < k
  std::array<double, S> B{};                  ///< weights b_k (quadrature weights w_k)
};

/// (2.43) forward Euler: c = 0, b = 1 (rectangle rule).
constexpr ButcherTableau<1> eulerTableau()
{
  ButcherTableau<1> t{};
  t.C[0] = 0.0;
  t.B[0] = 1.0;
  return t;
}

/// (2.44) Heun: c = (0, 1), A21 = 1, b = (1/2, 1/2) (trapezoidal rule).
constexpr ButcherTableau<2> heunTableau()
{
  ButcherTableau<2> t{};
  t.C[0] = 0.0;
  t.C[1] = 1.0;
  t.A[1][0] = 1.0;
  t.B[0] = 0.5;
  t.B[1] = 0.5;
  return t;
}

/// (2.45) Kutta's third-order method: c = (0, 1/2, 1), A21 = 1/2, A31 = -1,
/// A32 = 2, b = (1/6, 2/3, 1/6) (Simpson's rule).
constexpr ButcherTableau<3> kutta3Tableau()
{
  ButcherTableau<3> t{};
  t.C[0] = 0.0;
  t.C[1] = 0.5;
  t.C[2] = 1.0;
  t.A[1][0] = 0.5;
  t.A[2][0] = -1.0;
  t.A[2][1] = 2.0;
  t.B[0] = 1.0 / 6.0;
  t.B[1] = 2.0 / 3.0;
  t.B[2] = 1.0 / 6.0;
  return t;
}

/// The tableau of a compile-time order.
template <RkOrder O>
constexpr auto rkTableau()
{
  if constexpr (O == RkOrder::Euler)
  {
    return eulerTableau();
  }
  else if constexpr (O == RkOrder::Heun)
  {
    return heunTableau();
  }
  else
  {
    static_assert(O == RkOrder::Kutta3, "unknown RK order");
    return kutta3Tableau();
  }
}

/// Calls body(tableau) with the ButcherTableau<S> of a run-time order, so that
/// the body is instantiated once per stage count. Returns what body returns.
template <class Body>
decltype(auto) withTableau(RkOrder order, Body&& body)
{
  switch (order)
  {
    case RkOrder::Euler:
      return body(eulerTableau());
    case RkOrder::Heun:
      return body(heunTableau());
    case RkOrder::Kutta3:
    default:
      return body(kutta3Tableau());
  }
}

/// True for the orders implemented above (validate user input with it).
constexpr bool isValidRkOrder(int order)
{
  return order >= 1 && order <= 3;
}

} // namespace sltk
