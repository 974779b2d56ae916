// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbSolverOf.h (private)
/// HjbSolver for one compile-time problem type and interpolator: holds u^k,
/// the reachable set (3.40) and the work counters, and steps (3.7) with
/// hjbStepTo() (the time loop of hjbAdvance()) from u^k to the requested time.

#include "sltk/hjb/HjbError.h"
#include "sltk/hjb/HjbScheme.h"
#include "sltk/hjb/HjbSolver.h"
#include "sltk/interp/Interpolators.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace sltk
{

template <int D>
HjbGrid toHjbGrid(const GridSpec<D>& g)
{
  HjbGrid p;
  p.Dimension = D;
  for (int a = 0; a < D; ++a)
  {
    p.Dims[a] = g.Dims[a];
    p.Origin[a] = g.coordinate(a, 0); // node 0 (a window's first node, GridSpec::Offset)
    p.Spacing[a] = g.Spacing[a];
  }
  for (int a = D; a < 3; ++a)
  {
    p.Spacing[a] = g.Spacing[0];
  }
  return p;
}

template <class Interp, class Problem>
class HjbSolverOf final : public HjbSolver
{
public:
  static constexpr int D = Problem::Dim;

  /// `initialValues` (x fastest) replaces v_0 when not empty; `exactKnown`
  /// says whether Problem::Exact may be called.
  HjbSolverOf(Problem problem, const GridSpec<D>& spec, const HjbOptions& options, Index steps, double dt,
    bool reachable, bool exactKnown, std::vector<double> initialValues = {})
    : P(std::move(problem))
    , Spec(spec)
    , Options(options)
    , Grid(toHjbGrid(spec))
    , Dt(dt)
    , Steps(steps)
    , Reachable(reachable)
    , ExactKnown(exactKnown)
    , InitialValues(std::move(initialValues))
  {
  }

  const HjbGrid& grid() const override { return this->Grid; }
  double timeStep() const override { return this->Dt; }
  Index stepCount() const override { return this->Steps; }
  double startTime() const override { return this->Options.StartTime; }
  Index stepsDone() const override { return std::max<Index>(this->Done, 0); }

  Status advanceTo(double t, const Context& ctx) override
  {
    if (this->Done < 0 || t < this->time() - 1e-9 * this->Dt)
    {
      this->reset();
    }
    Index target = this->Done;
    while (
      target < this->Steps && this->startTime() + static_cast<double>(target + 1) * this->Dt <= t + 1e-9 * this->Dt)
    {
      ++target;
    }
    return hjbStepTo<Interp>(ctx, this->Options, this->P, this->Dt, target, this->U, this->Next, this->Done,
      &this->Stats, &this->Argmins, this->Reachable ? &this->Reach : nullptr);
  }

  void readValues(Index first, Index count, double* out) override
  {
    if (this->Done < 0)
    {
      this->reset();
    }
    for (Index k = 0; k < count; ++k)
    {
      out[k] = this->U(this->U.nodeIndex(first + k));
    }
  }
  void writeValues(Index first, Index count, const double* values) override
  {
    if (this->Done < 0)
    {
      this->reset();
    }
    for (Index k = 0; k < count; ++k)
    {
      this->U(this->U.nodeIndex(first + k)) = values[k];
    }
  }

  double evaluationsPerNode() const override { return this->Stats.evaluationsPerNode(); }

  void result(HjbRunResult& out) const override
  {
    out = HjbRunResult{};
    out.Grid = this->Grid;
    out.Block = wholeExtent(this->Grid);
    out.FinalTime = this->time();
    out.Steps = this->stepsDone();
    out.EvaluationsPerNode = this->Stats.evaluationsPerNode();
    const Index n = this->Spec.nodeCount();
    out.Value.resize(static_cast<size_t>(n));
    for (Index k = 0; k < n; ++k)
    {
      out.Value[static_cast<size_t>(k)] = this->U(this->U.nodeIndex(k));
    }
    if (this->Reachable)
    {
      out.ReachTime.resize(static_cast<size_t>(n));
      for (Index k = 0; k < n; ++k)
      {
        out.ReachTime[static_cast<size_t>(k)] = this->Reach(this->Reach.nodeIndex(k));
      }
    }
    if constexpr (Problem::HasExact)
    {
      // At t_0 the state is v_0 itself, and exact solutions such as Test 4's
      // (r - 1)^2 / (2 t) are singular there: errors from the first step on.
      if (this->ExactKnown && this->stepsDone() > 0)
      {
        this->errors(out);
      }
    }
  }

private:
  void reset()
  {
    this->U.resize(this->Spec, Interp::GhostWidth);
    if (this->InitialValues.empty())
    {
      hjbInitialize(this->P, this->U);
    }
    else
    {
      for (Index k = 0; k < this->Spec.nodeCount(); ++k)
      {
        const auto i = this->U.nodeIndex(k);
        double v = this->InitialValues[static_cast<size_t>(k)];
        if constexpr (Problem::HasObstacle)
        {
          v = std::max(v, this->P.Obstacle(nodePoint(this->Spec, i))); // (3.39) at t = 0
        }
        this->U(i) = v;
      }
    }
    this->Stats = HjbStats{};
    this->Argmins = HjbArgmins{};
    this->Done = 0;
    if (this->Reachable)
    {
      hjbStartReached<D>(this->U, this->Reach, this->startTime());
    }
  }

  /// L1 (sum |e| dx^D) and max errors against Problem::Exact at the current time.
  void errors(HjbRunResult& out) const
  {
    const double t = this->time();
    out.L1Error = l1Error(this->U, [&](const std::array<double, D>& x) { return this->P.Exact(t, x); });
    double worst = 0.0;
    out.ExactNotFiniteAt.clear();
    for (Index k = 0; k < this->Spec.nodeCount(); ++k)
    {
      const auto i = this->U.nodeIndex(k);
      const auto x = nodePoint(this->Spec, i);
      const double exact = this->P.Exact(t, x);
      if (!std::isfinite(exact) && out.ExactNotFiniteAt.empty())
      {
        out.ExactNotFiniteAt.assign(x.begin(), x.end());
        out.ExactNotFiniteAt.push_back(exact);
      }
      worst = std::max(worst, std::fabs(this->U(i) - exact));
    }
    out.LinfError = worst;
  }

  Problem P;
  GridSpec<D> Spec;
  HjbOptions Options;
  HjbGrid Grid;
  double Dt;
  Index Steps;
  bool Reachable;
  bool ExactKnown;
  std::vector<double> InitialValues;
  Index Done = -1; ///< -1: u^0 not built yet
  GridField<D, double> U;
  GridField<D, double> Next;
  GridField<D, double> Reach;
  HjbStats Stats;
  HjbArgmins Argmins; ///< warm starts of the minimiser (MinimizerOptions::WarmTabulationPoints)
};

/// Builds the solver for the interpolator chosen at run time; null for a kind
/// the HJB solver does not offer (offeredByHjb).
template <class Problem, class... Args>
std::unique_ptr<HjbSolver> makeHjbSolverOf(InterpolatorKind kind, Args&&... args)
{
  if (!offeredByHjb(kind))
  {
    return nullptr;
  }
  return withInterpolator<Problem::Dim>(kind,
    [&](auto tag) -> std::unique_ptr<HjbSolver>
    { return std::make_unique<HjbSolverOf<typename decltype(tag)::type, Problem>>(std::forward<Args>(args)...); });
}

/// The status of a makeHjbSolverOf call: a null solver is a kind the HJB solver does not offer.
inline Status madeHjbSolver(const std::unique_ptr<HjbSolver>& solver, InterpolatorKind kind)
{
  InterpolatorKind checked = kind;
  return solver ? Status::ok() : hjbInterpolatorOfCode(static_cast<int>(kind), checked);
}

} // namespace sltk
