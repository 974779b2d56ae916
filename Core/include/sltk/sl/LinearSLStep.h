// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LinearSLStep.h
/// The semi-Lagrangian scheme (2.36) for the linear problem (2.7)
///     v_t + f(t, x) . grad v = g(t, x),
///     u_i^{n+1} = I[U^n](y_i^n) + G_i^n,
/// at any Courant number: y_i^n is the RK foot of (3.8) with dynamics
/// f_D = -f (see Characteristics.h for the sign), G_i^n the quadrature (3.9)
/// of g on the RK stage values, I any interpolator of Interpolator.h (Q1,
/// WENO3, CWENO, ...). Feet outside the domain are clipped onto it or wrapped
/// by sltk::locate (thesis 3.5.1).
///
/// linearSLStep() does one step; linearSLAdvance() runs t0 -> T with
/// dt = (T - t0) / ceil((T - t0) / maxDt) (thesis 3.2: dt = lambda dx, shortened
/// so that the span is a whole number of steps), asking the interrupter
/// between steps.

#include "sltk/core/Status.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/interp/CellCache.h"
#include "sltk/interp/Interpolator.h"
#include "sltk/sl/Characteristics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

namespace sltk
{

/// Source term g = 0: the step skips the quadrature.
struct NoSource
{
};

/// Coordinates of node i (each i[a] in [0, N)). D is deduced from the spec only
/// (std::array's size is a size_t).
template <int D>
inline std::array<double, D> nodePoint(const GridSpec<D>& spec, const std::array<Index, std::size_t(D)>& i)
{
  std::array<double, D> x{};
  for (int a = 0; a < D; ++a)
  {
    x[a] = spec.coordinate(a, i[a]);
  }
  return x;
}

/// Number of steps N_T = ceil(span / maxDt) (3.2), tolerant to the rounding of
/// span / maxDt just above an integer.
inline Index slStepCount(double span, double maxDt)
{
  const double r = span / maxDt;
  const Index n = static_cast<Index>(std::ceil(r * (1.0 - 1e-12)));
  return n < 1 ? 1 : n;
}

/// The most time steps a solver plans: every step is at least one pass over
/// the grid, so more is hours of work on any grid (and ParaView's animation
/// would list every t_k); a final time or a time step that asks for more is a
/// mistake to name, not a run to start.
constexpr double MaximumTimeSteps = 1e6;

/// The uniform time steps from `start` to `final` (3.2): checks the interval
/// and the largest step (at most MaximumTimeSteps steps), then dt = span /
/// slStepCount(span, maxDt). `solver`
/// names the caller in the messages (e.g. "SL advection").
inline Status planTimeSteps(const char* solver, double start, double final, double maxDt, Index& steps, double& dt)
{
  const double span = final - start;
  if (!(span > 0.0) || !std::isfinite(span))
  {
    return Status::invalidArgument(std::string(solver) + " needs FinalTime > StartTime, got [" + std::to_string(start) +
      ", " + std::to_string(final) + "]");
  }
  if (!(maxDt > 0.0) || !std::isfinite(maxDt))
  {
    return Status::invalidArgument(std::string(solver) + " needs a positive MaxTimeStep, got " + std::to_string(maxDt));
  }
  if (span / maxDt > MaximumTimeSteps)
  {
    std::ostringstream what;
    what << solver << ": a final time " << final << " with time steps of " << maxDt << " makes " << span / maxDt
         << " steps, more than " << MaximumTimeSteps
         << ": use a smaller final time or a larger Courant number (time step)";
    return Status::invalidArgument(what.str());
  }
  steps = slStepCount(span, maxDt);
  dt = span / static_cast<double>(steps);
  return Status::ok();
}

namespace detail
{

/// Advances a node multi-index in x-fastest order (the order of GridField::nodeIndex).
template <int D>
inline void nextNode(const GridSpec<D>& spec, std::array<Index, std::size_t(D)>& i)
{
  for (int a = 0; a < D; ++a)
  {
    if (++i[a] < spec.Dims[a] || a == D - 1)
    {
      return;
    }
    i[a] = 0;
  }
}

/// The nodes from index i (of `begin`) to `end`, each with one foot: the
/// linear SL step (2.36), and hjbKernel() when the minimisation has one
/// candidate (ControlMinimizer::onlyCandidate(), Test 1). trace(x, stages)
/// traces the node's foot (false: it cannot be located), finish(i, x, stages,
/// value, located) completes the node (value: I[U] at the foot if located,
/// else +infinity). The feet of CellCache::PointLanes nodes are interpolated
/// together (CellCache::evaluate(): the CWENO cells missing are built
/// together, Remarks 3.1-3.2), the same values and counts as node after node.
/// Returns the evaluations.
template <class Cache, class Stages, class Trace, class Finish>
double oneFootNodes(Cache& cache, const GridSpec<Cache::Dim>& spec, std::array<Index, Cache::Dim> i, Index begin,
  Index end, Trace&& trace, Finish&& finish)
{
  constexpr int D = Cache::Dim;
  constexpr int L = Cache::PointLanes;
  for (Index node = begin; node < end;)
  {
    const int count = static_cast<int>(std::min<Index>(L, end - node));
    std::array<std::array<Index, D>, L> at;
    std::array<std::array<double, D>, L> x;
    std::array<Stages, L> stages;
    std::array<double, L> value;
    std::array<bool, L> ok;
    const double* feet[L];
    int lane[L];
    int located = 0;
    for (int l = 0; l < count; ++l, nextNode(spec, i))
    {
      at[l] = i;
      x[l] = nodePoint(spec, i);
      value[l] = std::numeric_limits<double>::infinity(); // cannot be located: not a candidate
      ok[l] = trace(x[l], stages[l]);
      if (ok[l])
      {
        feet[located] = stages[l].Foot.data();
        lane[located++] = l;
      }
    }
    double found[L];
    cache.evaluate(located, feet, found);
    for (int m = 0; m < located; ++m)
    {
      value[lane[m]] = found[m];
    }
    for (int l = 0; l < count; ++l)
    {
      finish(at[l], x[l], stages[l], value[l], ok[l]);
    }
    node += count;
  }
  return static_cast<double>(end - begin);
}

/// One step (2.36) with a compile-time tableau; returns the number of
/// non-finite values written to `next`.
template <class Interp, int S, class Velocity, class Source>
double linearSLKernel(const Context& ctx, const ButcherTableau<S>& tableau,
  const GridField<Interp::Dim, double>& current, GridField<Interp::Dim, double>& next, double tNext, double dt,
  const Velocity& f, const Source& g)
{
  constexpr int D = Interp::Dim;
  const GridSpec<D>& spec = current.spec();
  // (3.8) with f_D = -f: the thesis's dynamics of the backward characteristic.
  auto dynamics = [&f](double t, const std::array<double, D>& x, int)
  {
    std::array<double, D> v = f(t, x);
    for (int a = 0; a < D; ++a)
    {
      v[a] = -v[a];
    }
    return v;
  };
  // The foot (3.8) of node x; false when it is not finite (it cannot be located).
  auto trace = [&](const std::array<double, D>& x, CharacteristicStages<D, S>& stages)
  {
    traceCharacteristic(tableau, x, tNext, dt, dynamics, stages);
    bool finiteFoot = true;
    for (int a = 0; a < D; ++a)
    {
      finiteFoot = finiteFoot && std::isfinite(stages.Foot[a]);
    }
    return finiteFoot;
  };
  // U^{n+1}_i of (2.36): I[U^n] at the foot (NaN, reported, where there is none) + G_i^n.
  auto finish =
    [&](const std::array<Index, D>& i, const CharacteristicStages<D, S>& stages, double value, double& nonFinite)
  {
    if constexpr (!std::is_same_v<Source, NoSource>)
    {
      value +=
        stageQuadrature(tableau, stages, dt, [&g](double t, const std::array<double, D>& x, int) { return g(t, x); });
    }
    if (!std::isfinite(value))
    {
      nonFinite += 1.0;
    }
    next(i) = value;
  };
  constexpr double noFoot = std::numeric_limits<double>::quiet_NaN();
  auto body = [&](Index begin, Index end) -> double
  {
    double nonFinite = 0.0;
    std::array<Index, D> i = current.nodeIndex(begin); // then advanced x fastest, without divisions
    if constexpr (IsCwenoInterpolator<Interp>::value)
    {
      // The cells' polynomials stored and built four at a time (Remarks 3.1-3.2): a
      // node's foot falls in the cells of its neighbours' feet.
      CellCache<Interp, CwenoCellCacheSize> cache(Interp(current), current);
      oneFootNodes<decltype(cache), CharacteristicStages<D, S>>(cache, spec, i, begin, end, trace,
        [&](const std::array<Index, D>& at, const std::array<double, D>&, const CharacteristicStages<D, S>& stages,
          double value, bool located) { finish(at, stages, located ? value : noFoot, nonFinite); });
    }
    else
    {
      Interp interp(current); // one per chunk: interpolators hold per-cell scratch
      CharacteristicStages<D, S> stages;
      for (Index k = begin; k < end; ++k, nextNode(spec, i))
      {
        const bool located = trace(nodePoint(spec, i), stages);
        finish(i, stages, located ? interpolate(interp, spec, stages.Foot.data()) : noFoot, nonFinite);
      }
    }
    return nonFinite;
  };
  return ctx.parallelSum(0, spec.nodeCount(), body);
}

} // namespace detail

/// One SL step (2.36) from t_n = tNext - dt to tNext for
/// v_t + f(t, x) . grad v = g(t, x).
///  - `current` holds U^n; its ghost layers are filled here (it needs at least
///    Interp::GhostWidth of them);
///  - `next` receives U^{n+1}; it is resized to current's layout if needed;
///  - f(double t, const std::array<double, D>& x) -> std::array<double, D>,
///    g(double t, const std::array<double, D>& x) -> double, or NoSource{}.
/// Both callables are called concurrently from the executor's threads; pass
/// lambdas or function objects (a plain function is called indirectly, which
/// made a Q1 step about 1.7x slower in BenchRotation).
/// Returns numericalFailure if a value is NaN/Inf (the step is complete).
template <class Interp, class Velocity, class Source = NoSource>
Status linearSLStep(const Context& ctx, RkOrder order, GridField<Interp::Dim, double>& current,
  GridField<Interp::Dim, double>& next, double tNext, double dt, const Velocity& f, const Source& g = Source{})
{
  constexpr int D = Interp::Dim;
  SLTK_RETURN_IF_ERROR(current.spec().validate());
  if (!isValidRkOrder(static_cast<int>(order)))
  {
    return Status::invalidArgument("RK order must be 1, 2 or 3, got " + std::to_string(static_cast<int>(order)));
  }
  if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(tNext))
  {
    return Status::invalidArgument("the SL time step must be a positive finite number, got " + std::to_string(dt));
  }
  if (current.ghost() < Interp::GhostWidth)
  {
    return Status::invalidArgument("the field has " + std::to_string(current.ghost()) +
      " ghost layers, the interpolator reads " + std::to_string(Interp::GhostWidth));
  }
  bool sameLayout = next.ghost() == current.ghost() && next.storage().size() == current.storage().size();
  for (int a = 0; a < D && sameLayout; ++a)
  {
    const GridSpec<D>& have = next.spec();
    const GridSpec<D>& want = current.spec();
    sameLayout = have.Dims[a] == want.Dims[a] && have.Origin[a] == want.Origin[a] &&
      have.Spacing[a] == want.Spacing[a] && have.Bounds[a] == want.Bounds[a];
  }
  if (!sameLayout)
  {
    next.resize(current.spec(), current.ghost());
  }
  current.fillGhosts();
  const double nonFinite = withTableau(order,
    [&](const auto& tableau) { return detail::linearSLKernel<Interp>(ctx, tableau, current, next, tNext, dt, f, g); });
  if (nonFinite > 0.0)
  {
    return Status::numericalFailure(std::to_string(static_cast<Index>(nonFinite)) +
      " non-finite values in the SL step ending at t = " + std::to_string(tNext));
  }
  return Status::ok();
}

struct LinearSLOptions
{
  RkOrder Order = RkOrder::Kutta3; ///< RK for the feet, and its quadrature (2.43)-(2.45)
  double StartTime = 0.0;          ///< t_0
  double FinalTime = 1.0;          ///< T
  double MaxTimeStep = 0.0;        ///< dt before shortening, e.g. lambda * dx
};

/// Advances u from StartTime to FinalTime by slStepCount() steps of (2.36).
/// u must have at least Interp::GhostWidth ghost layers; on return it holds
/// U^{N_T} (or the last completed step when aborted: *stepsDone tells how many).
/// Asks ctx.interrupter() before every step (fraction done) and returns
/// Status::aborted() when it says so.
template <class Interp, class Velocity, class Source = NoSource>
Status linearSLAdvance(const Context& ctx, const LinearSLOptions& options, GridField<Interp::Dim, double>& u,
  const Velocity& f, const Source& g = Source{}, Index* stepsDone = nullptr)
{
  if (stepsDone)
  {
    *stepsDone = 0;
  }
  Index steps = 0;
  double dt = 0.0;
  SLTK_RETURN_IF_ERROR(
    planTimeSteps("SL advection", options.StartTime, options.FinalTime, options.MaxTimeStep, steps, dt));
  GridField<Interp::Dim, double> next(u.spec(), u.ghost());
  Interrupter& progress = ctx.interrupter();
  progress.start("semi-Lagrangian advection");
  Status status;
  for (Index n = 0; n < steps; ++n)
  {
    if (progress.wasInterrupted(static_cast<double>(n) / static_cast<double>(steps)))
    {
      status = Status::aborted();
      break;
    }
    // t_{n+1} = t_0 + (n + 1) dt, not an accumulated sum.
    const double tNext = options.StartTime + static_cast<double>(n + 1) * dt;
    status = linearSLStep<Interp>(ctx, options.Order, u, next, tNext, dt, f, g);
    if (status.isOk() || status.code() == StatusCode::NumericalFailure) // the step was computed
    {
      std::swap(u, next);
      if (stepsDone)
      {
        *stepsDone = n + 1;
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

} // namespace sltk
