// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbProblem.h
/// Definition of an HJB problem (3.1)-(3.3) for the scheme (3.7): a small
/// struct of callables whose types are template parameters, so that the
/// solver inlines them (no std::function, no virtual call per evaluation).
///
///   Dynamics(t, x, a)    -> std::array<double, D>  f_D of (3.2) (backward variable, see Characteristics.h)
///   RunningCost(t, x, a) -> double                 f_C of (3.4); NoCost: f_C = 0 (no quadrature)
///   Initial(x)           -> double                 v_0
///   Obstacle(x)          -> double                 g of (3.39); NoObstacle: unconstrained
///   Exact(t, x)          -> double                 exact solution; NoExact: unknown
///   Feedback(t, x)       -> std::array<double, M>  a closed-form argmin of (3.7) at node x, t = t_{n+1};
///                                                  NoFeedback: search A^nu (Minimizer.h)
/// with x a std::array<double, D>, a a std::array<double, M>, and the control
/// set A in Controls (ControlSet.h; ControlKind::None for pure transport).
/// H(t, x, p) = max_a { -f_D . p - f_C } (3.3).

#include "sltk/hjb/ControlSet.h"

#include <array>
#include <type_traits>
#include <utility>

namespace sltk
{

struct NoCost
{
};
struct NoObstacle
{
};
struct NoExact
{
};
struct NoFeedback
{
};

namespace detail
{
/// True for callables with a `bool enabled() const` member.
template <class F, class = void>
struct HasEnabledMember : std::false_type
{
};
template <class F>
struct HasEnabledMember<F, std::void_t<decltype(std::declval<const F&>().enabled())>> : std::true_type
{
};
} // namespace detail

template <int D, int M, class Dyn, class Cost, class Init, class Obs = NoObstacle, class Ex = NoExact,
  class Fb = NoFeedback>
struct HjbProblem
{
  static constexpr int Dim = D;
  static constexpr int ControlDim = M;
  using Point = std::array<double, D>;
  using Control = std::array<double, M>;
  using DynamicsType = Dyn;
  using CostType = Cost;
  using ObstacleType = Obs;
  using ExactType = Ex;
  using FeedbackType = Fb;

  static constexpr bool HasCost = !std::is_same_v<Cost, NoCost>;
  static constexpr bool HasObstacle = !std::is_same_v<Obs, NoObstacle>;
  static constexpr bool HasExact = !std::is_same_v<Ex, NoExact>;
  static constexpr bool HasFeedback = !std::is_same_v<Fb, NoFeedback>;

  ControlSet<M> Controls;
  Dyn Dynamics;
  Cost RunningCost;
  Init Initial;
  Obs Obstacle;
  Ex Exact;
  Fb Feedback;

  /// True when the closed-form argmin replaces the search: always for a
  /// feedback callable, unless it has enabled() (formulas the user may omit).
  bool usesFeedback() const
  {
    if constexpr (!HasFeedback)
    {
      return false;
    }
    else if constexpr (detail::HasEnabledMember<Fb>::value)
    {
      return this->Feedback.enabled();
    }
    else
    {
      return true;
    }
  }

  /// u^0_i = v_0(x_i), or max(v_0, g) with an obstacle ((3.39): v(x, 0) = max(v_0(x), g(x))).
  double initialValue(const Point& x) const
  {
    if constexpr (HasObstacle)
    {
      const double v = this->Initial(x);
      const double g = this->Obstacle(x);
      return v > g ? v : g;
    }
    else
    {
      return this->Initial(x);
    }
  }
};

/// HjbProblem with deduced callable types.
template <int D, int M, class Dyn, class Cost, class Init>
HjbProblem<D, M, Dyn, Cost, Init> makeHjbProblem(const ControlSet<M>& controls, Dyn dynamics, Cost cost, Init initial)
{
  return { controls, std::move(dynamics), std::move(cost), std::move(initial), NoObstacle{}, NoExact{}, NoFeedback{} };
}

/// The same problem with the state constraint g of (3.39).
template <int D, int M, class Dyn, class Cost, class Init, class Obs, class Ex, class Fb, class G>
HjbProblem<D, M, Dyn, Cost, Init, G, Ex, Fb> withObstacle(const HjbProblem<D, M, Dyn, Cost, Init, Obs, Ex, Fb>& p, G g)
{
  return { p.Controls, p.Dynamics, p.RunningCost, p.Initial, std::move(g), p.Exact, p.Feedback };
}

/// The same problem with its exact solution v(t, x).
template <int D, int M, class Dyn, class Cost, class Init, class Obs, class Ex, class Fb, class E>
HjbProblem<D, M, Dyn, Cost, Init, Obs, E, Fb> withExact(
  const HjbProblem<D, M, Dyn, Cost, Init, Obs, Ex, Fb>& p, E exact)
{
  return { p.Controls, p.Dynamics, p.RunningCost, p.Initial, p.Obstacle, std::move(exact), p.Feedback };
}

/// The same problem with a closed-form argmin a*(t_{n+1}, x_i) used in place of
/// the search (projected onto A; one evaluation per node and step).
template <int D, int M, class Dyn, class Cost, class Init, class Obs, class Ex, class Fb, class F>
HjbProblem<D, M, Dyn, Cost, Init, Obs, Ex, F> withFeedback(
  const HjbProblem<D, M, Dyn, Cost, Init, Obs, Ex, Fb>& p, F feedback)
{
  return { p.Controls, p.Dynamics, p.RunningCost, p.Initial, p.Obstacle, p.Exact, std::move(feedback) };
}

} // namespace sltk
