// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbScheme.h
/// The semi-Lagrangian scheme (3.7) for the HJB equation (3.1) in 1D/2D/3D:
///     u_i^{n+1} = min_{a in A^nu} { I[U^n](y_i^n(a)) + C_i^n(a) },
/// y_i^n(a) the RK foot (3.8) with control a_k in stage k, C_i^n(a) the cost
/// quadrature (3.9) on the stage values (Characteristics.h), the minimum by
/// tabulation + local search (Minimizer.h) or a closed-form feedback
/// (HjbProblem.h). With an obstacle g (3.39):
///     u_i^{n+1} = max( min_a {...}, g(x_i) ),
/// and the reachable set (3.40) R^n = { x_i : u_i^k <= 0 for some k <= n } is
/// kept as the field of the first time t_k at which u_i^k <= 0 (+inf: not
/// reached by the current time), so R^n = { i : reach_i <= t_n }.
///
/// Interp is any interpolator of Interpolator.h (Weno3, Cweno, CwenoZ, Q1);
/// each chunk of nodes owns a CellCache of HjbOptions::CellCacheSize prepared
/// cells so that a CWENO polynomial serves all the feet of a node that fall in
/// its cell (Remarks 3.1-3.2). dt = (T - t0) / ceil((T - t0) / MaxTimeStep).
/// With MinimizerOptions::WarmTabulationPoints > 0 and an HjbArgmins store,
/// each node's minimisation starts from its argmin of the previous step.

#include "sltk/core/Status.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/hjb/HjbArgmins.h"
#include "sltk/hjb/HjbProblem.h"
#include "sltk/hjb/Minimizer.h"
#include "sltk/interp/CellCache.h"
#include "sltk/sl/Characteristics.h"
#include "sltk/sl/LinearSLStep.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace sltk
{

struct HjbOptions
{
  RkOrder Order = RkOrder::Kutta3; ///< RK for the feet (3.8) and its quadrature (3.9)
  double StartTime = 0.0;          ///< t_0
  double FinalTime = 1.0;          ///< T
  double MaxTimeStep = 0.0;        ///< lambda dx, shortened so that (T - t0) / dt is an integer
  MinimizerOptions Minimizer;      ///< tabulation + local search over A^nu
  /// Prepared cells kept per thread chunk (CellCache.h): 1 (prepareIfNeeded),
  /// 8 (linear search), 256 or 4096 (hashed tables; CWENO keeps only the
  /// polynomials), 0 = automatic: 4096 for CWENO/CWENOZ, whose builds are the
  /// expensive part, 256 for the others (an interpolator object per entry).
  /// Large tables let consecutive nodes reuse the cells of their neighbours' feet.
  /// Measured (sltkBenchHjb, one thread, same run; builds per node and step,
  /// CWENO time gain over WENO): Test 4 N = 41: 1 -> 203 builds, -98%;
  /// 8 -> 32, +26%; 256 -> 6.5, +49%. Test 2 N = 641: 1 -> 42, -58%;
  /// 8 -> 33, -49%; 256 -> 2.9, +13%. Results are identical for every size.
  int CellCacheSize = 0;
};

/// Work counters, summed over the steps done.
struct HjbStats
{
  Index Steps = 0;
  double NodeUpdates = 0.0; ///< nodes x steps
  double Evaluations = 0.0; ///< objective evaluations F(a) of (3.7) (= interpolations)
  double CellBuilds = 0.0;  ///< interpolator prepare() calls
  double evaluationsPerNode() const { return this->NodeUpdates > 0.0 ? this->Evaluations / this->NodeUpdates : 0.0; }
  double buildsPerNode() const { return this->NodeUpdates > 0.0 ? this->CellBuilds / this->NodeUpdates : 0.0; }
};

/// u^0_i = v_0(x_i) (max(v_0, g) with an obstacle) on the interior nodes.
template <class Problem>
void hjbInitialize(const Problem& problem, GridField<Problem::Dim, double>& u)
{
  const GridSpec<Problem::Dim>& spec = u.spec();
  for (Index k = 0; k < spec.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    u(i) = problem.initialValue(nodePoint(spec, i));
  }
}

namespace detail
{

/// One step of (3.7) with compile-time stage count S and cache size K; fills
/// `work` = {evaluations, builds, non-finite values}.
template <class Interp, int K, int S, class Problem>
void hjbKernel(const Context& ctx, const ButcherTableau<S>& tableau, const MinimizerOptions& minOptions,
  const Problem& problem, const GridField<Interp::Dim, double>& current, GridField<Interp::Dim, double>& next,
  double tNext, double dt, HjbArgmins* argmins, std::array<double, 3>& work)
{
  constexpr int D = Interp::Dim;
  constexpr int M = Problem::ControlDim;
  using Point = std::array<double, D>;
  using Sequence = ControlSequence<M, S>;
  const GridSpec<D>& spec = current.spec();
  const ControlMinimizer<M, S> minimizer(problem.Controls, minOptions);
  const Index n = spec.nodeCount();
  const bool feedback = problem.usesFeedback();
  const bool warm = argmins != nullptr && minimizer.warmStarts() && !feedback;
  if (warm && (argmins->count() != minimizer.parameterCount() || argmins->nodes() != n))
  {
    argmins->reset(n, minimizer.parameterCount());
  }
  const Index grain = std::max<Index>(16, (n + 63) / 64); // chunks independent of the thread count
  const Index chunks = (n + grain - 1) / grain;
  std::vector<std::array<double, 3>> partial(static_cast<size_t>(chunks), std::array<double, 3>{});
  const Interp prototype(current);
  using Stages = CharacteristicStages<D, S>;
  // The foot (3.8) of x under the controls a; false when it cannot be located.
  auto traceFoot = [&](const Point& x, const Sequence& a, Stages& stages) -> bool
  {
    traceCharacteristic(
      tableau, x, tNext, dt, [&](double t, const Point& X, int k) { return problem.Dynamics(t, X, a[k]); }, stages);
    for (int d = 0; d < D; ++d)
    {
      if (!std::isfinite(stages.Foot[d]))
      {
        return false;
      }
    }
    return true;
  };
  // F(a) of (3.7) from the interpolated value at the foot: + the cost quadrature (3.9).
  auto withCost = [&](double v, const Sequence& a, const Stages& stages) -> double
  {
    if constexpr (Problem::HasCost)
    {
      v += stageQuadrature(
        tableau, stages, dt, [&](double t, const Point& X, int k) { return problem.RunningCost(t, X, a[k]); });
    }
    return v;
  };
  // The node's new value: the obstacle (3.39), counted if not finite.
  auto store = [&](const std::array<Index, D>& i, const Point& x, double value, std::array<double, 3>& local)
  {
    if constexpr (Problem::HasObstacle)
    {
      value = std::max(value, problem.Obstacle(x)); // (3.39)
    }
    if (!std::isfinite(value))
    {
      local[2] += 1.0;
    }
    next(i) = value;
  };
  const Sequence* only = feedback ? nullptr : minimizer.onlyCandidate();
  auto body = [&](Index begin, Index end)
  {
    CellCache<Interp, K> cache(prototype, current); // per chunk: interpolators hold per-cell scratch
    Stages stages;
    std::array<double, 3> local{};
    std::array<Index, D> i = current.nodeIndex(begin);
    if (only != nullptr)
    {
      local[0] = oneFootNodes<CellCache<Interp, K>, Stages>(
        cache, spec, i, begin, end, [&](const Point& x, Stages& st) { return traceFoot(x, *only, st); },
        [&](const std::array<Index, D>& at, const Point& x, const Stages& st, double v, bool located)
        {
          // minimize()'s value of its one evaluation
          const double value = located ? ControlMinimizer<M, S>::candidateValue(withCost(v, *only, st)) : v;
          store(at, x, value, local);
        });
      end = begin; // done
    }
    for (Index node = begin; node < end; ++node, nextNode(spec, i))
    {
      const Point x = nodePoint(spec, i);
      // F(a) of (3.7): interpolation at the foot (3.8) + cost quadrature (3.9).
      auto objective = [&](const Sequence& a) -> double
      {
        if (!traceFoot(x, a, stages)) // cannot be located: not a candidate
        {
          return std::numeric_limits<double>::infinity();
        }
        return withCost(cache(stages.Foot.data()), a, stages);
      };
      double value = 0.0;
      if (feedback)
      {
        if constexpr (Problem::HasFeedback)
        {
          Sequence a{};
          const auto star = problem.Controls.project(problem.Feedback(tNext, x)); // kept inside A
          for (int k = 0; k < S; ++k)
          {
            a[k] = star;
          }
          value = objective(a);
          local[0] += 1.0;
        }
      }
      else
      {
        // Warm start from the node's previous argmin when it has one (HjbArgmins.h).
        MinimizerResult<M, S> r;
        if (warm && argmins->has(node))
        {
          typename ControlMinimizer<M, S>::Parameters start{};
          std::copy_n(argmins->at(node), minimizer.parameterCount(), start.begin());
          r = minimizer.minimizeFrom(objective, start);
        }
        else
        {
          r = minimizer.minimize(objective);
        }
        if (warm && std::isfinite(r.Value))
        {
          std::copy_n(r.Arguments.begin(), minimizer.parameterCount(), argmins->at(node));
        }
        value = r.Value;
        local[0] += static_cast<double>(r.Evaluations);
      }
      store(i, x, value, local);
    }
    local[1] = cache.builds();
    partial[static_cast<size_t>(begin / grain)] = local;
  };
  ctx.parallelFor(0, n, body, grain);
  work = {};
  for (const auto& p : partial) // chunk order: deterministic
  {
    for (int c = 0; c < 3; ++c)
    {
      work[c] += p[c];
    }
  }
}

/// Problems may fix the cell-cache size at compile time (static constexpr int
/// CellCacheSize; 0 = the automatic size), which instantiates one kernel
/// instead of four; -1: HjbOptions::CellCacheSize chooses at run time.
template <class Problem, class = void>
struct FixedCellCache : std::integral_constant<int, -1>
{
};
template <class Problem>
struct FixedCellCache<Problem, std::void_t<decltype(Problem::CellCacheSize)>>
  : std::integral_constant<int, Problem::CellCacheSize>
{
};

/// Problems may fix the RK order at compile time (static constexpr RkOrder
/// FixedOrder), which instantiates the kernels of one stage count instead of
/// three; HjbOptions::Order must then be that order. 0: any order (withTableau()).
template <class Problem, class = void>
struct FixedRkOrder : std::integral_constant<int, 0>
{
};
template <class Problem>
struct FixedRkOrder<Problem, std::void_t<decltype(Problem::FixedOrder)>>
  : std::integral_constant<int, static_cast<int>(Problem::FixedOrder)>
{
};

/// CellCacheSize 0: 4096 CWENO/CWENOZ polynomials (their builds are the
/// expensive part), 256 for the others (an interpolator object per entry).
template <class Interp>
struct AutomaticCellCache : std::integral_constant<int, IsCwenoInterpolator<Interp>::value ? CwenoCellCacheSize : 256>
{
};

template <class Interp, int S, class Problem>
Status hjbDispatchCache(const Context& ctx, const HjbOptions& options, const ButcherTableau<S>& tableau,
  const Problem& problem, const GridField<Interp::Dim, double>& current, GridField<Interp::Dim, double>& next,
  double tNext, double dt, HjbArgmins* argmins, std::array<double, 3>& work)
{
  auto run = [&](auto size)
  {
    hjbKernel<Interp, decltype(size)::value>(
      ctx, tableau, options.Minimizer, problem, current, next, tNext, dt, argmins, work);
    return Status::ok();
  };
  constexpr int fixed = FixedCellCache<Problem>::value;
  if constexpr (fixed >= 0)
  {
    constexpr int size = fixed == 0 ? AutomaticCellCache<Interp>::value : fixed;
    return run(std::integral_constant<int, size>{});
  }
  else
  {
    switch (options.CellCacheSize)
    {
      case 0:
        return run(AutomaticCellCache<Interp>{});
      case 1:
        return run(std::integral_constant<int, 1>{});
      case 8:
        return run(std::integral_constant<int, 8>{});
      case 256:
        return run(std::integral_constant<int, 256>{});
      case 4096:
        return run(std::integral_constant<int, 4096>{});
      default:
        return Status::invalidArgument(
          "CellCacheSize must be 0 (automatic), 1, 8, 256 or 4096, got " + std::to_string(options.CellCacheSize));
    }
  }
}

} // namespace detail

/// `Problem` compiled for one RK order (detail::FixedRkOrder) and, unless
/// CacheSize is -1, one cell-cache size (detail::FixedCellCache; 0: automatic):
/// the solver then instantiates one kernel of (3.7) per interpolator instead
/// of one per order and cache size. HjbOptions::Order must be O, and with a
/// fixed cache size HjbOptions::CellCacheSize is not read.
template <class Problem, RkOrder O, int CacheSize = 0>
struct FixedSchemeProblem : Problem
{
  static constexpr RkOrder FixedOrder = O;
  static constexpr int CellCacheSize = CacheSize;
};

/// The same problem as a FixedSchemeProblem, e.g. withFixedOrder<RkOrder::Euler>(p).
template <RkOrder O, int CacheSize = 0, class Problem>
FixedSchemeProblem<Problem, O, CacheSize> withFixedOrder(const Problem& problem)
{
  return { problem };
}

/// Checks the options of hjbStep()/hjbAdvance() and the problem's control set.
template <class Interp, class Problem>
Status hjbValidate(const HjbOptions& options, const Problem& problem, const GridField<Interp::Dim, double>& u)
{
  SLTK_RETURN_IF_ERROR(u.spec().validate());
  SLTK_RETURN_IF_ERROR(problem.Controls.validate());
  if (!isValidRkOrder(static_cast<int>(options.Order)))
  {
    return Status::invalidArgument(
      "RK order must be 1, 2 or 3, got " + std::to_string(static_cast<int>(options.Order)));
  }
  constexpr int fixedOrder = detail::FixedRkOrder<Problem>::value;
  if (fixedOrder > 0 && static_cast<int>(options.Order) != fixedOrder)
  {
    return Status::invalidArgument("this problem is compiled for RK order " + std::to_string(fixedOrder) +
      " only, got " + std::to_string(static_cast<int>(options.Order)));
  }
  if (u.ghost() < Interp::GhostWidth)
  {
    return Status::invalidArgument("the field has " + std::to_string(u.ghost()) +
      " ghost layers, the interpolator reads " + std::to_string(Interp::GhostWidth));
  }
  if (options.Minimizer.TabulationPoints < 1 || !(options.Minimizer.Tolerance >= 0.0) ||
    options.Minimizer.MaxIterations < 0 || options.Minimizer.WarmTabulationPoints < 0 ||
    options.Minimizer.WarmTabulationPoints > 15)
  {
    return Status::invalidArgument("minimiser options: TabulationPoints >= 1, Tolerance >= 0, MaxIterations >= 0 and "
                                   "WarmTabulationPoints in 0..15 are needed");
  }
  return Status::ok();
}

/// One step of (3.7) from t_n = tNext - dt to tNext. `current` holds U^n (its
/// ghosts are filled here), `next` receives U^{n+1} (resized if needed).
/// Returns numericalFailure when a value is NaN/Inf (the step is complete).
/// `argmins` (optional) carries the per-node argmins from step to step for the
/// warm start (MinimizerOptions::WarmTabulationPoints > 0; reset when its size
/// does not match).
template <class Interp, class Problem>
Status hjbStep(const Context& ctx, const HjbOptions& options, const Problem& problem,
  GridField<Interp::Dim, double>& current, GridField<Interp::Dim, double>& next, double tNext, double dt,
  HjbStats* stats = nullptr, HjbArgmins* argmins = nullptr)
{
  static_assert(Problem::Dim == Interp::Dim, "the problem and the interpolator must have the same dimension");
  SLTK_RETURN_IF_ERROR(hjbValidate<Interp>(options, problem, current));
  if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(tNext))
  {
    return Status::invalidArgument("the HJB time step must be a positive finite number, got " + std::to_string(dt));
  }
  bool sameLayout = next.ghost() == current.ghost() && next.storage().size() == current.storage().size();
  for (int a = 0; a < Interp::Dim && sameLayout; ++a)
  {
    const auto& have = next.spec();
    const auto& want = current.spec();
    sameLayout = have.Dims[a] == want.Dims[a] && have.Origin[a] == want.Origin[a] &&
      have.Spacing[a] == want.Spacing[a] && have.Bounds[a] == want.Bounds[a];
  }
  if (!sameLayout)
  {
    next.resize(current.spec(), current.ghost());
  }
  current.fillGhosts();
  std::array<double, 3> work{};
  auto run = [&](const auto& tableau)
  { return detail::hjbDispatchCache<Interp>(ctx, options, tableau, problem, current, next, tNext, dt, argmins, work); };
  constexpr int fixedOrder = detail::FixedRkOrder<Problem>::value;
  if constexpr (fixedOrder > 0)
  {
    SLTK_RETURN_IF_ERROR(run(rkTableau<static_cast<RkOrder>(fixedOrder)>()));
  }
  else
  {
    SLTK_RETURN_IF_ERROR(withTableau(options.Order, run));
  }
  if (stats)
  {
    stats->Steps += 1;
    stats->NodeUpdates += static_cast<double>(current.spec().nodeCount());
    stats->Evaluations += work[0];
    stats->CellBuilds += work[1];
  }
  if (work[2] > 0.0)
  {
    return Status::numericalFailure(std::to_string(static_cast<Index>(work[2])) +
      " non-finite values in the HJB step ending at t = " + std::to_string(tNext));
  }
  return Status::ok();
}

/// Value marking a node not (yet) in the reachable set (3.40).
constexpr double NotReached = std::numeric_limits<double>::infinity();

/// Adds the nodes with u_i <= 0 not reached before to the reachable set (3.40)
/// at time t. With the previous state `before` (u at tBefore) the first time is
/// refined by linear interpolation of u in time, t* in (tBefore, t]: the sets
/// R[0, t_k] = { reach <= t_k } of (3.40) are unchanged, and the level sets of
/// the field between step times are smooth instead of staircases of dt.
template <int D>
void hjbMarkReached(const GridField<D, double>* before, double tBefore, const GridField<D, double>& u,
  GridField<D, double>& reach, double t)
{
  for (Index k = 0; k < u.spec().nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    const double now = u(i);
    if (now <= 0.0 && reach(i) == NotReached)
    {
      const double was = before ? (*before)(i) : 0.0;
      reach(i) = was > 0.0 ? tBefore + (t - tBefore) * was / (was - now) : t;
    }
  }
}

/// Starts the reachable set (3.40) at t0 from u^0: `reach` gets u's grid
/// without ghosts, t0 where u_i^0 <= 0 and NotReached elsewhere.
template <int D>
void hjbStartReached(const GridField<D, double>& u, GridField<D, double>& reach, double t0)
{
  reach.resize(u.spec(), 0, NotReached);
  hjbMarkReached<D>(nullptr, t0, u, reach, t0);
}

/// The time steps of (3.7) from StartTime to FinalTime (planTimeSteps()):
/// dt = (T - t0) / ceil((T - t0) / MaxTimeStep). With `allowNoStep`, T <= t0
/// means no step (the initial datum) and dt = MaxTimeStep; otherwise it is an error.
inline Status hjbPlanTimeSteps(const HjbOptions& options, Index& steps, double& dt, bool allowNoStep = false)
{
  if (allowNoStep && !(options.FinalTime > options.StartTime))
  {
    steps = 0;
    dt = options.MaxTimeStep;
    return Status::ok();
  }
  return planTimeSteps("the HJB solver", options.StartTime, options.FinalTime, options.MaxTimeStep, steps, dt);
}

/// The time loop of (3.7), shared by hjbAdvance() and the run-time solvers
/// (HjbSolver.h): steps u from u^done to u^target, t_k = StartTime + k dt.
/// Asks ctx.interrupter() before every step and returns Status::aborted()
/// when told to stop. After every computed step (also one that returns
/// numericalFailure, which ends the loop) u holds the new state, `next` the
/// previous one, `done` counts it and, when `reach` is given (started by
/// hjbStartReached()), the nodes reached are added to (3.40). `argmins`
/// carries the warm starts from step to step (hjbStep()).
template <class Interp, class Problem>
Status hjbStepTo(const Context& ctx, const HjbOptions& options, const Problem& problem, double dt, Index target,
  GridField<Interp::Dim, double>& u, GridField<Interp::Dim, double>& next, Index& done, HjbStats* stats,
  HjbArgmins* argmins, GridField<Interp::Dim, double>* reach)
{
  if (target <= done)
  {
    return Status::ok();
  }
  Interrupter& progress = ctx.interrupter();
  progress.start("HJB semi-Lagrangian scheme (3.7)");
  const Index first = done;
  Status status;
  while (done < target)
  {
    if (progress.wasInterrupted(static_cast<double>(done - first) / static_cast<double>(target - first)))
    {
      status = Status::aborted();
      break;
    }
    // t_{k+1} = t_0 + (k + 1) dt, not an accumulated sum.
    const double tNext = options.StartTime + static_cast<double>(done + 1) * dt;
    status = hjbStep<Interp>(ctx, options, problem, u, next, tNext, dt, stats, argmins);
    if (status.isOk() || status.code() == StatusCode::NumericalFailure) // the step was computed
    {
      std::swap(u, next);
      ++done;
      if (reach)
      {
        hjbMarkReached<Interp::Dim>(&next, tNext - dt, u, *reach, tNext); // next: u^k after the swap
      }
    }
    if (!status.isOk())
    {
      break;
    }
  }
  progress.end();
  return status;
}

/// Advances u (holding u^0, e.g. from hjbInitialize()) from StartTime to
/// FinalTime with (3.7). When `reach` is given it receives (3.40): the first
/// t_k at which u_i^k <= 0, NotReached otherwise (same grid, no ghosts).
/// Asks ctx.interrupter() before every step; returns Status::aborted() when
/// told to stop, with u holding the last completed step (*stepsDone).
template <class Interp, class Problem>
Status hjbAdvance(const Context& ctx, const HjbOptions& options, const Problem& problem,
  GridField<Interp::Dim, double>& u, HjbStats* stats = nullptr, GridField<Interp::Dim, double>* reach = nullptr,
  Index* stepsDone = nullptr)
{
  if (stepsDone)
  {
    *stepsDone = 0;
  }
  SLTK_RETURN_IF_ERROR(hjbValidate<Interp>(options, problem, u));
  Index steps = 0;
  double dt = 0.0;
  SLTK_RETURN_IF_ERROR(hjbPlanTimeSteps(options, steps, dt));
  if (reach)
  {
    hjbStartReached<Interp::Dim>(u, *reach, options.StartTime);
  }
  GridField<Interp::Dim, double> next(u.spec(), u.ghost());
  HjbArgmins argmins; // warm starts (MinimizerOptions::WarmTabulationPoints)
  Index done = 0;
  const Status status = hjbStepTo<Interp>(ctx, options, problem, dt, steps, u, next, done, stats, &argmins, reach);
  if (stepsDone)
  {
    *stepsDone = done;
  }
  return status;
}

} // namespace sltk
