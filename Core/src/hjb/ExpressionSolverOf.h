// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ExpressionSolverOf.h (private)
/// The callables of HjbProblem (HjbProblem.h) evaluated from compiled user
/// formulas (ExpressionProblem.h). Every formula reads the same slots
/// {x, y, z, t, a1, a2, a3}; slots a formula may not use were refused when it
/// was compiled. The callables share the compiled formulas (read-only, so
/// every thread evaluates them at once).

#include "HjbSolverOf.h"
#include "sltk/expr/Expression.h"
#include "sltk/hjb/ExpressionProblem.h"

#include <array>
#include <limits>
#include <memory>

namespace sltk
{

/// Slot of each variable in the value array every formula reads.
enum ExpressionSlot : int
{
  SlotX = 0,
  SlotT = 3,
  SlotA = 4,
  SlotCount = 7
};

struct CompiledHjbExpressions
{
  std::array<Expression, 3> Dynamics;
  Expression Cost;                  ///< "0" when the user gave none
  Expression Initial;               ///< unused when initial values are given
  Expression Obstacle;              ///< compiled only when HasObstacle
  Expression Exact;                 ///< compiled only when HasExact
  std::array<Expression, 3> Argmin; ///< compiled only when HasArgmin
  bool HasObstacle = false;
  bool HasExact = false;
  bool HasArgmin = false;
};
using SharedHjbExpressions = std::shared_ptr<const CompiledHjbExpressions>;

/// Compiles every formula of `spec` (errors name the formula and the column).
Status compileHjbExpressions(const HjbExpressionSpec& spec, CompiledHjbExpressions& out);

/// Every check of makeExpressionSolver() but the memory one, without allocating the grid's state:
/// the compiled formulas, the grid (its window, if any) and the time step.
Status planExpressionSolve(const HjbExpressionSpec& spec, CompiledHjbExpressions& compiled, HjbGrid& grid, double& dt);

template <int D, int M>
void fillSlots(double (&v)[SlotCount], double t, const std::array<double, D>& x, const std::array<double, M>& a)
{
  for (int k = 0; k < SlotCount; ++k)
  {
    v[k] = 0.0;
  }
  for (int d = 0; d < D; ++d)
  {
    v[SlotX + d] = x[d];
  }
  v[SlotT] = t;
  for (int m = 0; m < M; ++m)
  {
    v[SlotA + m] = a[m];
  }
}

template <int D, int M>
struct ExpressionDynamics
{
  SharedHjbExpressions E;
  std::array<double, D> operator()(double t, const std::array<double, D>& x, const std::array<double, M>& a) const
  {
    double v[SlotCount];
    fillSlots<D, M>(v, t, x, a);
    std::array<double, D> f;
    for (int d = 0; d < D; ++d)
    {
      f[d] = this->E->Dynamics[d].evaluate(v);
    }
    return f;
  }
};

template <int D, int M>
struct ExpressionCost
{
  SharedHjbExpressions E;
  double operator()(double t, const std::array<double, D>& x, const std::array<double, M>& a) const
  {
    double v[SlotCount];
    fillSlots<D, M>(v, t, x, a);
    return this->E->Cost.evaluate(v);
  }
};

/// v_0(x), g(x) (-inf when there is no obstacle, so that max(u, g) = u) and v(t, x).
template <int D>
struct ExpressionOfState
{
  SharedHjbExpressions E;
  const Expression CompiledHjbExpressions::*Which;
  double operator()(const std::array<double, D>& x) const { return this->at(0.0, x); }
  double operator()(double t, const std::array<double, D>& x) const { return this->at(t, x); }
  double at(double t, const std::array<double, D>& x) const
  {
    const Expression& e = (*this->E).*(this->Which);
    if (!e.isCompiled())
    {
      return -std::numeric_limits<double>::infinity();
    }
    double v[SlotCount];
    fillSlots<D, 1>(v, t, x, std::array<double, 1>{ 0.0 });
    return e.evaluate(v);
  }
};

/// The closed-form argmin a*(t, x) (enabled only when the user gave it).
template <int D, int M>
struct ExpressionArgmin
{
  SharedHjbExpressions E;
  bool enabled() const { return this->E->HasArgmin; }
  std::array<double, M> operator()(double t, const std::array<double, D>& x) const
  {
    double v[SlotCount];
    fillSlots<D, 1>(v, t, x, std::array<double, 1>{ 0.0 });
    std::array<double, M> a;
    for (int m = 0; m < M; ++m)
    {
      a[m] = this->E->Argmin[m].evaluate(v);
    }
    return a;
  }
};

/// One problem type per (D, M): cost, obstacle, exact solution and argmin are
/// always present (constant or disabled at run time), and the cell cache is
/// chosen automatically, so that each (D, M, interpolator) compiles one kernel
/// per RK order.
template <int D, int M>
struct ExpressionHjbProblem
  : HjbProblem<D, M, ExpressionDynamics<D, M>, ExpressionCost<D, M>, ExpressionOfState<D>, ExpressionOfState<D>,
      ExpressionOfState<D>, ExpressionArgmin<D, M>>
{
  static constexpr int CellCacheSize = 0; // automatic only (HjbScheme.h FixedCellCache)
};

/// Everything makeExpressionSolver() checked and built, for the per-dimension part.
template <int D>
struct ExpressionSolverInput
{
  SharedHjbExpressions Expressions;
  GridSpec<D> Grid;
  HjbOptions Options;
  Index Steps = 0;
  double Dt = 0.0;
  bool Reachable = false;
  int ControlDimension = 1;
};

/// The solver for spec.Interpolator of ExpressionHjbProblem<D, M>. Each (D, M)
/// is instantiated in its own translation unit, generated by Core/CMakeLists.txt
/// from ExpressionSolverInstance.cxx.in, so that the kernels of (3.7) compile
/// in parallel; the others see only the declarations below.
template <int D, int M>
Status makeExpressionSolverOfControls(
  const HjbExpressionSpec& spec, const ExpressionSolverInput<D>& in, std::unique_ptr<HjbSolver>& solver)
{
  using Problem = ExpressionHjbProblem<D, M>;
  Problem problem;
  ControlSet<M> controls;
  controls.Kind = spec.Controls;
  controls.Radius = spec.ControlRadius;
  for (int m = 0; m < M; ++m)
  {
    controls.Lower[m] = spec.ControlLower[m];
    controls.Upper[m] = spec.ControlUpper[m];
    controls.Center[m] = spec.ControlCenter[m];
  }
  for (const auto& p : spec.ControlPoints)
  {
    std::array<double, M> a;
    for (int m = 0; m < M; ++m)
    {
      a[m] = p[m];
    }
    controls.Points.push_back(a);
  }
  SLTK_RETURN_IF_ERROR(controls.validate());
  problem.Controls = controls;
  problem.Dynamics = ExpressionDynamics<D, M>{ in.Expressions };
  problem.RunningCost = ExpressionCost<D, M>{ in.Expressions };
  problem.Initial = ExpressionOfState<D>{ in.Expressions, &CompiledHjbExpressions::Initial };
  problem.Obstacle = ExpressionOfState<D>{ in.Expressions, &CompiledHjbExpressions::Obstacle };
  problem.Exact = ExpressionOfState<D>{ in.Expressions, &CompiledHjbExpressions::Exact };
  problem.Feedback = ExpressionArgmin<D, M>{ in.Expressions };
  solver = makeHjbSolverOf<Problem>(spec.Interpolator, problem, in.Grid, in.Options, in.Steps, in.Dt, in.Reachable,
    in.Expressions->HasExact, spec.InitialValues);
  return madeHjbSolver(solver, spec.Interpolator);
}

/// Declares (extern) or defines (in its translation unit) the instantiation for (D, M).
#define SLTK_EXPRESSION_SOLVER_INSTANCE(Prefix, D, M)                                                                  \
  Prefix template Status makeExpressionSolverOfControls<D, M>(                                                         \
    const HjbExpressionSpec& spec, const ExpressionSolverInput<D>& in, std::unique_ptr<HjbSolver>& solver);

SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 1, 1)
SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 1, 2)
SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 1, 3)
SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 2, 1)
SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 2, 2)
SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 2, 3)
SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 3, 1)
SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 3, 2)
SLTK_EXPRESSION_SOLVER_INSTANCE(extern, 3, 3)

/// The solver of dimension D for spec.ControlDimension (1 for pure transport) and spec.Interpolator.
template <int D>
Status makeExpressionSolverOf(
  const HjbExpressionSpec& spec, const ExpressionSolverInput<D>& in, std::unique_ptr<HjbSolver>& solver)
{
  switch (in.ControlDimension)
  {
    case 1:
      return makeExpressionSolverOfControls<D, 1>(spec, in, solver);
    case 2:
      return makeExpressionSolverOfControls<D, 2>(spec, in, solver);
    case 3:
      return makeExpressionSolverOfControls<D, 3>(spec, in, solver);
    default:
      return Status::invalidArgument(
        "the control dimension must be 1, 2 or 3, got " + std::to_string(in.ControlDimension));
  }
}

} // namespace sltk
