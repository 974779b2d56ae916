// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbSolver.h
/// The HJB scheme (3.7) behind a run-time interface, for the VTK filter, the
/// CLI and scripts: the problem (a thesis preset or user formulas), the
/// dimension, the control set and the interpolator are chosen at run time; the
/// solver keeps its state so that it can be advanced step by step (ParaView's
/// animation asks for t_1, t_2, ... in turn) and restarted when asked for an
/// earlier time.

#include "sltk/exec/Context.h"
#include "sltk/hjb/ExpressionProblem.h"
#include "sltk/hjb/HjbResult.h"
#include "sltk/hjb/PresetRun.h"

#include <memory>
#include <vector>

namespace sltk
{

class HjbSolver
{
public:
  virtual ~HjbSolver() = default;

  /// The grid (unused axes: one node).
  virtual const HjbGrid& grid() const = 0;
  /// dt of (3.7) and the number of steps to the final time: t_k = t_0 + k dt.
  virtual double timeStep() const = 0;
  virtual Index stepCount() const = 0;
  virtual double startTime() const = 0;
  /// Steps done so far (the state is u^k, k = stepsDone()).
  virtual Index stepsDone() const = 0;
  /// Objective evaluations per node update so far (this process's nodes).
  virtual double evaluationsPerNode() const = 0;
  /// The ranks the grid is split over (DistributedHjbSolver.h); 1: whole here.
  virtual int ranks() const { return 1; }

  /// Advances to the last t_k <= t (k <= stepCount()), starting again from u^0
  /// when t is before the current time. Asks ctx.interrupter() before every
  /// step; returns Status::aborted() when told to stop (the state stays u^k of
  /// the last completed step).
  virtual Status advanceTo(double t, const Context& ctx) = 0;

  /// The state u^k at t_k (value, reachable set, errors against the exact
  /// solution when one is known, work counters).
  virtual void result(HjbRunResult& out) const = 0;
  /// The same on the nodes of `extent` only (out.Block = extent): what a
  /// VTK pipeline asks of one piece. A distributed solver
  /// (DistributedHjbSolver.h) sends every rank the nodes of its extent from
  /// the ranks that own them: a collective call, each rank with its own
  /// extent (the whole grid, a piece, or none). This default crops result().
  virtual void resultBlock(const HjbExtent& extent, HjbRunResult& out) const;

  /// Values of u^k at `count` nodes from node `first` (nodes numbered x
  /// fastest), and their replacement: the halo exchange of a distributed solve
  /// (DistributedHjbSolver.h) between steps. u^0 is built first when needed.
  virtual void readValues(Index first, Index count, double* out) = 0;
  virtual void writeValues(Index first, Index count, const double* values) = 0;

  double time() const { return this->startTime() + static_cast<double>(this->stepsDone()) * this->timeStep(); }
  double finalTime() const { return this->startTime() + static_cast<double>(this->stepCount()) * this->timeStep(); }
  /// t_0, ..., t_K (what the VTK filter advertises as TIME_STEPS).
  std::vector<double> stepTimes() const;
};

/// A solver of one of the thesis's tests (Presets.h).
Status makePresetSolver(const PresetRunOptions& options, std::unique_ptr<HjbSolver>& solver);

/// A solver of a problem given by formulas (ExpressionProblem.h): compiles and
/// checks every expression (errors name the expression and the column), the
/// grid, the control set, the times and the memory the grid needs.
Status makeExpressionSolver(const HjbExpressionSpec& spec, std::unique_ptr<HjbSolver>& solver);

} // namespace sltk
