// SPDX-License-Identifier: BSD-3-Clause
// makeExpressionSolver(): checks an expression-defined HJB problem
// (ExpressionProblem.h), compiles its formulas and builds its grid.
#include "ExpressionDiagnosis.h"
#include "ExpressionSolverOf.h"
#include "HjbExtents.h"
#include "sltk/exec/Memory.h"

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

namespace sltk
{

std::vector<double> HjbSolver::stepTimes() const
{
  std::vector<double> times(static_cast<size_t>(this->stepCount() + 1));
  for (size_t k = 0; k < times.size(); ++k)
  {
    times[k] = this->startTime() + static_cast<double>(k) * this->timeStep();
  }
  return times;
}

void HjbSolver::resultBlock(const HjbExtent& extent, HjbRunResult& out) const
{
  this->result(out);
  const HjbExtent box = intersectExtents(extent, out.Block);
  if (box == out.Block)
  {
    return; // the whole grid: no copy
  }
  for (std::vector<double>* field : { &out.Value, &out.ReachTime })
  {
    if (!field->empty())
    {
      std::vector<double> cropped(static_cast<size_t>(extentNodes(box)));
      copyExtent(field->data(), out.Block, cropped.data(), box, box);
      *field = std::move(cropped);
    }
  }
  out.Block = box;
}

namespace
{
const char* const axisNames[3] = { "x", "y", "z" };

/// Names of the slots {x, y, z, t, a1, a2, a3} a formula may read ("" = refused).
std::vector<std::string> slotNames(int dimension, int controls, bool time)
{
  std::vector<std::string> names(SlotCount);
  for (int d = 0; d < dimension; ++d)
  {
    names[static_cast<size_t>(SlotX + d)] = axisNames[d];
  }
  if (time)
  {
    names[SlotT] = "t";
  }
  for (int m = 0; m < controls; ++m)
  {
    names[static_cast<size_t>(SlotA + m)] = "a" + std::to_string(m + 1);
  }
  return names;
}

/// The closed-form argmin: none, or one formula in x, y, z, t per control component.
Status compileArgmin(const HjbExpressionSpec& spec, int controls, CompiledHjbExpressions& out)
{
  int given = 0;
  for (const std::string& f : spec.Argmin)
  {
    given += f.empty() ? 0 : 1;
  }
  out.HasArgmin = given > 0;
  if (!out.HasArgmin)
  {
    return Status::ok();
  }
  if (controls == 0)
  {
    return Status::invalidArgument(
      "a closed-form argmin is given but there is no control set: choose one, or drop the argmin formulas");
  }
  const std::vector<std::string> stateAndTime = slotNames(spec.Dimension, 0, true);
  for (int m = 0; m < 3; ++m)
  {
    const std::string what = "the argmin component a" + std::to_string(m + 1);
    const std::string& formula = spec.Argmin[static_cast<size_t>(m)];
    if (m >= controls)
    {
      if (!formula.empty())
      {
        return Status::invalidArgument(what + " is given but the controls have " + std::to_string(controls) +
          " component(s): drop it or raise the control dimension");
      }
      continue;
    }
    if (formula.empty())
    {
      return Status::invalidArgument(what + " is empty: give one formula per control component (or none to search A)");
    }
    SLTK_RETURN_IF_ERROR(Expression::compile(what, formula, stateAndTime, out.Argmin[static_cast<size_t>(m)]));
  }
  return Status::ok();
}

} // namespace

Status compileHjbExpressions(const HjbExpressionSpec& spec, CompiledHjbExpressions& out)
{
  const int controls = spec.Controls == ControlKind::None ? 0 : spec.ControlDimension;
  const std::vector<std::string> all = slotNames(spec.Dimension, controls, true);
  const std::vector<std::string> state = slotNames(spec.Dimension, 0, false);
  for (int d = 0; d < spec.Dimension; ++d)
  {
    const std::string what = std::string("the dynamics f_D component ") + axisNames[d];
    if (spec.Dynamics[static_cast<size_t>(d)].empty())
    {
      return Status::invalidArgument(what + " is empty: give one formula per axis (\"0\" for none)");
    }
    SLTK_RETURN_IF_ERROR(
      Expression::compile(what, spec.Dynamics[static_cast<size_t>(d)], all, out.Dynamics[static_cast<size_t>(d)]));
  }
  SLTK_RETURN_IF_ERROR(Expression::compile("the running cost f_C", spec.Cost.empty() ? "0" : spec.Cost, all, out.Cost));
  if (spec.InitialValues.empty())
  {
    if (spec.Initial.empty())
    {
      return Status::invalidArgument("the initial datum v0 is empty: give a formula in x, y, z or an input field");
    }
    SLTK_RETURN_IF_ERROR(Expression::compile("the initial datum v0", spec.Initial, state, out.Initial));
  }
  out.HasObstacle = !spec.Obstacle.empty();
  if (out.HasObstacle)
  {
    SLTK_RETURN_IF_ERROR(Expression::compile("the obstacle g", spec.Obstacle, state, out.Obstacle));
  }
  SLTK_RETURN_IF_ERROR(compileArgmin(spec, controls, out));
  out.HasExact = !spec.Exact.empty();
  if (out.HasExact)
  {
    SLTK_RETURN_IF_ERROR(
      Expression::compile("the exact solution", spec.Exact, slotNames(spec.Dimension, 0, true), out.Exact));
  }
  return Status::ok();
}

namespace
{

template <int D>
Status buildGrid(const HjbExpressionSpec& spec, GridSpec<D>& grid)
{
  for (int a = 0; a < D; ++a)
  {
    const Index n = spec.Nodes[static_cast<size_t>(a)];
    const double lo = spec.Lower[static_cast<size_t>(a)];
    const double hi = spec.Upper[static_cast<size_t>(a)];
    if (n < 5 || n > 100000)
    {
      return Status::invalidArgument(
        std::string("the grid has ") + std::to_string(n) + " nodes along " + axisNames[a] + ": use 5 to 100000");
    }
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo))
    {
      return Status::invalidArgument(std::string("the domain along ") + axisNames[a] + " is [" + std::to_string(lo) +
        ", " + std::to_string(hi) + "]: give finite bounds with lower < upper");
    }
    const bool periodic = spec.Bounds[static_cast<size_t>(a)] == Boundary::Periodic;
    const Index first = spec.WindowFirst[static_cast<size_t>(a)];
    const Index window = spec.WindowNodes[static_cast<size_t>(a)];
    // A window of a periodic axis (a distributed solve's slab, Slabs.h) may run up to one period past
    // either end: its rows there are the other end's, at coordinates a period away.
    const Index low = periodic && window > 0 ? -n : 0, high = periodic ? 2 * n : n;
    if (window < 0 || first < low || (window > 0 && (first + window > high || window < 5)))
    {
      return Status::invalidArgument(std::string("the window along ") + axisNames[a] + " (nodes " +
        std::to_string(first) + " + " + std::to_string(window) + " of " + std::to_string(n) +
        ") is not inside the grid (a periodic axis: within a period of it) or shorter than 5 nodes");
    }
    grid.Dims[a] = window > 0 ? window : n;
    grid.Offset[a] = window > 0 ? first : 0;
    grid.Origin[a] = lo;
    grid.Spacing[a] = axisSpacing(spec, a);
    // A window's end rows are ghost rows, overwritten by the exchange: no wrap inside the window.
    grid.Bounds[a] = periodic && window > 0 ? Boundary::Extrapolate : spec.Bounds[static_cast<size_t>(a)];
  }
  return grid.validate();
}

/// u^n, u^{n+1} with ghost layers, the reachable set and the output copies: about 48 bytes a node.
Status checkMemory(Index nodes)
{
  const double bytes = 48.0 * static_cast<double>(nodes);
  const double available = static_cast<double>(availableMemoryBytes());
  if (available > 0.0 && bytes > available)
  {
    return Status::outOfMemory("the grid has " + std::to_string(nodes) + " nodes and needs about " +
      std::to_string(bytes / 1e9) + " GB, more than the " + std::to_string(available / 1e9) +
      " GB available: use fewer nodes");
  }
  return Status::ok();
}

/// The most controls a tabulation of A may hold (checkSizesAndTimes).
constexpr double MaxTabulatedControls = 1e6;

Status checkSizesAndTimes(const HjbExpressionSpec& spec, Index nodes)
{
  if (!spec.InitialValues.empty())
  {
    if (static_cast<Index>(spec.InitialValues.size()) != nodes)
    {
      return Status::invalidArgument("the initial field has " + std::to_string(spec.InitialValues.size()) +
        " values for a grid of " + std::to_string(nodes) + " nodes");
    }
    for (size_t k = 0; k < spec.InitialValues.size(); ++k)
    {
      if (!std::isfinite(spec.InitialValues[k]))
      {
        return Status::invalidArgument(
          "the initial field is not finite at node " + std::to_string(k) + ": fill or crop the NaN/Inf values first");
      }
    }
  }
  if (!std::isfinite(spec.FinalTime) || spec.FinalTime < 0.0)
  {
    return Status::invalidArgument(
      "the final time must be a finite number >= 0, got " + std::to_string(spec.FinalTime));
  }
  if (!std::isfinite(spec.CourantNumber) || !(spec.CourantNumber > 0.0))
  {
    return Status::invalidArgument("the Courant number (dt = lambda dx) must be a positive finite number, got " +
      std::to_string(spec.CourantNumber));
  }
  if (!isValidRkOrder(static_cast<int>(spec.Order)))
  {
    return Status::invalidArgument(
      "the RK order must be 1, 2 or 3, got " + std::to_string(static_cast<int>(spec.Order)));
  }
  const MinimizerOptions& m = spec.Minimizer;
  if (m.TabulationPoints < 1 || !(m.Tolerance >= 0.0) || m.MaxIterations < 0 || m.WarmTabulationPoints < 0 ||
    m.WarmTabulationPoints > 15)
  {
    return Status::invalidArgument("minimiser options: tabulation points >= 1, tolerance >= 0, iterations >= 0 and "
                                   "warm-start points in 0..15 are needed");
  }
  // The tabulation of A (Minimizer.h: TabulationPoints per parameter of A, ControlSet::parameterCount),
  // scanned whole at every node and stage: beyond MaxTabulatedControls the table alone takes
  // gigabytes and the scan hours. Refused before anything is allocated, naming the tabulation.
  const int parameters = controlParameterCount(spec.Controls, spec.ControlDimension);
  const double tabulated = std::pow(static_cast<double>(m.TabulationPoints), parameters);
  if (tabulated > MaxTabulatedControls)
  {
    const int most = static_cast<int>(std::floor(std::pow(MaxTabulatedControls, 1.0 / parameters) + 1e-9));
    std::ostringstream message;
    message << "the control tabulation has " << m.TabulationPoints << " points per parameter of A over " << parameters
            << " parameters, " << tabulated << " controls, more than the " << MaxTabulatedControls
            << " a node's search scans: tabulate at most " << most
            << " points per parameter (the local search refines between them)";
    return Status::invalidArgument(message.str());
  }
  return Status::ok();
}

/// Every check that needs no allocation, and the grid and time steps (no memory check).
template <int D>
Status planForDimension(const HjbExpressionSpec& spec, ExpressionSolverInput<D>& in)
{
  SLTK_RETURN_IF_ERROR(buildGrid<D>(spec, in.Grid));
  SLTK_RETURN_IF_ERROR(checkSizesAndTimes(spec, in.Grid.nodeCount()));
  double dx = in.Grid.Spacing[0];
  for (int a = 1; a < D; ++a)
  {
    dx = std::min(dx, in.Grid.Spacing[a]);
  }
  in.Options.Order = spec.Order;
  in.Options.StartTime = 0.0;
  in.Options.FinalTime = spec.FinalTime;
  in.Options.MaxTimeStep = spec.CourantNumber * dx;
  in.Options.Minimizer = spec.Minimizer;
  return hjbPlanTimeSteps(in.Options, in.Steps, in.Dt, true); // T = 0: the initial datum, no step
}

template <int D>
Status makeForDimension(
  const HjbExpressionSpec& spec, SharedHjbExpressions expressions, std::unique_ptr<HjbSolver>& solver)
{
  ExpressionSolverInput<D> in;
  SLTK_RETURN_IF_ERROR(planForDimension<D>(spec, in));
  SLTK_RETURN_IF_ERROR(checkMemory(in.Grid.nodeCount()));
  in.Reachable = spec.ReachableSet || expressions->HasObstacle;
  // Pure transport: no minimisation, one unused control slot.
  in.ControlDimension = spec.Controls == ControlKind::None ? 1 : spec.ControlDimension;
  in.Expressions = expressions;
  SLTK_RETURN_IF_ERROR(makeExpressionSolverOf<D>(spec, in, solver));
  // v_0 and g are read at every node: a formula that is not finite there is refused before any step.
  const std::string cause = findNonFiniteFormula(spec, *expressions, wholeGrid(spec), 0.0, FormulaScope::StateFormulas);
  if (!cause.empty())
  {
    solver.reset();
    return Status::invalidArgument(cause + "; " + NonFiniteFix);
  }
  solver = withNonFiniteDiagnosis(std::move(solver), spec, std::move(expressions));
  return Status::ok();
}
} // namespace

namespace
{
Status checkDimensions(const HjbExpressionSpec& spec)
{
  if (spec.Dimension < 1 || spec.Dimension > 3)
  {
    return Status::invalidArgument("the dimension must be 1, 2 or 3, got " + std::to_string(spec.Dimension));
  }
  if (spec.Controls != ControlKind::None && (spec.ControlDimension < 1 || spec.ControlDimension > 3))
  {
    return Status::invalidArgument(
      "the control dimension must be 1, 2 or 3, got " + std::to_string(spec.ControlDimension));
  }
  return Status::ok();
}

template <int D>
Status planGrid(const HjbExpressionSpec& spec, HjbGrid& grid, double& dt)
{
  ExpressionSolverInput<D> in;
  SLTK_RETURN_IF_ERROR(planForDimension<D>(spec, in));
  grid = toHjbGrid(in.Grid);
  dt = in.Dt;
  return Status::ok();
}
} // namespace

Status planExpressionSolve(const HjbExpressionSpec& spec, CompiledHjbExpressions& compiled, HjbGrid& grid, double& dt)
{
  SLTK_RETURN_IF_ERROR(checkDimensions(spec));
  SLTK_RETURN_IF_ERROR(compileHjbExpressions(spec, compiled));
  switch (spec.Dimension)
  {
    case 1:
      return planGrid<1>(spec, grid, dt);
    case 2:
      return planGrid<2>(spec, grid, dt);
    default:
      return planGrid<3>(spec, grid, dt);
  }
}

Status makeExpressionSolver(const HjbExpressionSpec& spec, std::unique_ptr<HjbSolver>& solver)
{
  solver.reset();
  SLTK_RETURN_IF_ERROR(checkDimensions(spec));
  auto compiled = std::make_shared<CompiledHjbExpressions>();
  SLTK_RETURN_IF_ERROR(compileHjbExpressions(spec, *compiled));
  switch (spec.Dimension)
  {
    case 1:
      return makeForDimension<1>(spec, std::move(compiled), solver);
    case 2:
      return makeForDimension<2>(spec, std::move(compiled), solver);
    default:
      return makeForDimension<3>(spec, std::move(compiled), solver);
  }
}

} // namespace sltk
