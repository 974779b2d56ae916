// SPDX-License-Identifier: BSD-3-Clause
// HjbSolver.h: problems given as formulas reproduce the compiled presets of
// Tests 1, 4 and 5 (3.5.1, 3.5.4, 3.5.5), transport has the sign of (3.3),
// stepping is resumable, and bad problems are refused with clear messages.
#include "sltk/hjb/HjbSolver.h"
#include "sltk/hjb/InitialData.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace
{
using sltk::Index;

sltk::HjbRunResult solveToEnd(std::unique_ptr<sltk::HjbSolver>& solver)
{
  const sltk::Status s = solver->advanceTo(solver->finalTime(), sltk::Context{});
  EXPECT_TRUE(s.isOk()) << s.message();
  sltk::HjbRunResult r;
  solver->result(r);
  return r;
}

sltk::HjbRunResult preset(sltk::HjbPreset which, Index n, double finalTime = -1.0)
{
  sltk::PresetRunOptions o;
  o.Preset = which;
  o.Nodes = n;
  o.FinalTime = finalTime;
  std::unique_ptr<sltk::HjbSolver> solver;
  EXPECT_TRUE(sltk::makePresetSolver(o, solver).isOk());
  return solveToEnd(solver);
}

sltk::HjbRunResult expressions(const sltk::HjbExpressionSpec& spec)
{
  std::unique_ptr<sltk::HjbSolver> solver;
  const sltk::Status s = sltk::makeExpressionSolver(spec, solver);
  EXPECT_TRUE(s.isOk()) << s.message();
  if (!solver)
  {
    return {};
  }
  return solveToEnd(solver);
}

/// A problem of the given dimension on [0, upper] (upper 0 on the unused axes),
/// with `nodes` nodes per axis (1 on the unused ones), the dynamics f_D and the
/// initial datum v0; boundaries, controls and times are the caller's.
sltk::HjbExpressionSpec fromOrigin(int dimension, const std::array<Index, 3>& nodes, const std::array<double, 3>& upper,
  const std::array<std::string, 3>& dynamics, const std::string& initial)
{
  sltk::HjbExpressionSpec s;
  s.Dimension = dimension;
  s.Nodes = nodes;
  s.Lower = { 0.0, 0.0, 0.0 };
  s.Upper = upper;
  s.Dynamics = dynamics;
  s.Initial = initial;
  return s;
}

/// Test 1 (3.5.1) as formulas; v0 given as node values (the C2 bump).
sltk::HjbExpressionSpec rotation(Index n)
{
  sltk::HjbExpressionSpec s;
  s.Dimension = 2;
  s.Nodes = { n, n, 1 };
  s.Lower = { 0.0, 0.0, 0.0 };
  s.Upper = { 1.0, 1.0, 1.0 };
  s.Dynamics = { "-2*pi*(y - 0.5)", "2*pi*(x - 0.5)", "" };
  const double dx = 1.0 / static_cast<double>(n - 1);
  for (Index j = 0; j < n; ++j)
  {
    for (Index i = 0; i < n; ++i)
    {
      s.InitialValues.push_back(sltk::rotatingBump(static_cast<double>(i) * dx, static_cast<double>(j) * dx));
    }
  }
  s.Order = sltk::RkOrder::Kutta3;
  s.FinalTime = 1.0;
  s.CourantNumber = 3.0;
  return s;
}

void expectSameValues(const sltk::HjbRunResult& a, const sltk::HjbRunResult& b, double tolerance)
{
  ASSERT_EQ(a.Value.size(), b.Value.size());
  double worst = 0.0;
  for (size_t k = 0; k < a.Value.size(); ++k)
  {
    worst = std::max(worst, std::fabs(a.Value[k] - b.Value[k]));
  }
  EXPECT_LE(worst, tolerance);
}
} // namespace

TEST(HjbExpressionSolver, RotationMatchesTest1Preset)
{
  const sltk::HjbRunResult p = preset(sltk::HjbPreset::Test1Rotation, 41);
  const sltk::HjbRunResult e = expressions(rotation(41));
  EXPECT_EQ(e.Steps, p.Steps);
  expectSameValues(e, p, 1e-14);
  EXPECT_TRUE(std::isnan(e.L1Error)); // no exact solution given
}

/// H(p) = |p|^2 / 2 on a 21 x 21 grid: f_D = -a, f_C = |a|^2/2, A = a disc of
/// the given radius, RK1 feet, Nelder-Mead, T = 0.5 (Test 4 (3.37) and the
/// closed-form argmin test below).
sltk::HjbExpressionSpec quadraticHamiltonian(double radius)
{
  sltk::HjbExpressionSpec s;
  s.Nodes = { 21, 21, 1 };
  s.Dynamics = { "-a1", "-a2", "" };
  s.Cost = "(a1^2 + a2^2)/2";
  s.Controls = sltk::ControlKind::Ball;
  s.ControlDimension = 2;
  s.ControlRadius = radius;
  s.Order = sltk::RkOrder::Euler;
  s.FinalTime = 0.5;
  s.Minimizer.Search = sltk::LocalSearch::NelderMead;
  return s;
}

TEST(HjbExpressionSolver, QuadraticHamiltonianMatchesTest4Preset)
{
  sltk::HjbExpressionSpec s = quadraticHamiltonian(2.2);
  s.Lower = { -2.0, -2.0, 0.0 };
  s.Upper = { 2.0, 2.0, 0.0 };
  s.Initial = "max(1 - (x^2 + y^2), 0)";
  s.Exact = "hypot(x, y) <= 1 ? (hypot(x, y) - 1)^2 / (2*t) : 0";
  s.CourantNumber = 1.25;
  s.Minimizer.TabulationPoints = 33;
  s.Minimizer.Tolerance = 1e-8;
  s.Minimizer.WarmTabulationPoints = 5; // as the preset: the warm start also runs through the expression path
  const sltk::HjbRunResult p = preset(sltk::HjbPreset::Test4Quadratic, 21);
  const sltk::HjbRunResult e = expressions(s);
  expectSameValues(e, p, 1e-14);
  EXPECT_NEAR(e.L1Error, p.L1Error, 1e-12 * p.L1Error);
  EXPECT_NEAR(e.LinfError, p.LinfError, 1e-12);
  EXPECT_EQ(e.EvaluationsPerNode, p.EvaluationsPerNode);
}

/// f_D = -a, f_C = |a|^2/2 on a disc of radius 2, v0 = |x|^2/2 on [-1, 1]^2:
/// v(t, x) = |x|^2 / (2 (1 + t)) (Hopf-Lax), with the feedback a*(t, x) = x / (1 + t)
/// (feet y = x + dt f_D = x - dt a),
/// which is also the exact minimiser of the discrete step (3.7) for quadratic
/// data (the feet x (1 + t_n) / (1 + t_{n+1}) stay inside the domain).
sltk::HjbExpressionSpec quadraticValue()
{
  sltk::HjbExpressionSpec s = quadraticHamiltonian(2.0);
  s.Initial = "(x^2 + y^2)/2";
  s.Exact = "(x^2 + y^2) / (2*(1 + t))";
  s.Minimizer.TabulationPoints = 17;
  s.Minimizer.Tolerance = 1e-9;
  return s;
}

TEST(HjbExpressionSolver, ClosedFormArgminReplacesTheSearch)
{
  const sltk::HjbRunResult searched = expressions(quadraticValue());
  auto closed = quadraticValue();
  closed.Argmin = { "x/(1 + t)", "y/(1 + t)", "" };
  const sltk::HjbRunResult exact = expressions(closed);
  EXPECT_EQ(exact.EvaluationsPerNode, 1.0);
  EXPECT_GT(searched.EvaluationsPerNode, 50.0);
  std::cout << "closed form: Linf " << exact.LinfError << ", L1 " << exact.L1Error << "; searched: Linf "
            << searched.LinfError << ", L1 " << searched.L1Error << "\n";
  EXPECT_LT(exact.LinfError, 1.1 * searched.LinfError); // measured 1.22e-3 vs 1.19e-3 (21 x 21)
  EXPECT_NEAR(exact.L1Error, searched.L1Error, 0.05 * searched.L1Error);
  expectSameValues(exact, searched, 1e-4);
  // An argmin outside A is projected onto it: (5, 0) acts as (2, 0).
  auto outside = quadraticValue();
  outside.Argmin = { "5", "0", "" };
  auto boundary = quadraticValue();
  boundary.Argmin = { "2", "0", "" };
  const sltk::HjbRunResult a = expressions(outside);
  const sltk::HjbRunResult b = expressions(boundary);
  expectSameValues(a, b, 0.0);
  EXPECT_GT(a.LinfError, 0.1); // a wrong argmin gives a wrong (larger) value: the formula is used
}

TEST(HjbExpressionSolver, ZermeloMatchesTest5PresetWithObstaclesAndReachableSet)
{
  sltk::HjbExpressionSpec s;
  s.Nodes = { 51, 41, 1 };
  s.Lower = { -3.0, -2.0, 0.0 };
  s.Upper = { 2.0, 2.0, 0.0 };
  s.Dynamics = { "2 - y^2/2 + a1", "a2", "" };
  s.Initial = "20 * min(hypot(x - 1, y) - 0.25, 0.25)";
  s.Obstacle = "max(-0.2, max(20*(0.2 - max(abs(x - 0.3), abs(y - 0.4))), 20*(0.2 - max(abs(x + 1), abs(y + 1.5)))))";
  s.Controls = sltk::ControlKind::Sphere;
  s.ControlDimension = 2;
  s.ControlRadius = 1.0;
  s.Order = sltk::RkOrder::Kutta3;
  s.FinalTime = 0.5;
  s.CourantNumber = 1.0;
  s.Minimizer.TabulationPoints = 32;
  s.Minimizer.PerStageControls = true;
  s.Minimizer.Search = sltk::LocalSearch::NelderMead;
  s.Minimizer.Tolerance = 1e-8;
  const sltk::HjbRunResult p = preset(sltk::HjbPreset::Test5Zermelo, 51, 0.5);
  const sltk::HjbRunResult e = expressions(s);
  expectSameValues(e, p, 1e-12);
  ASSERT_EQ(e.ReachTime.size(), p.ReachTime.size());
  int reached = 0;
  for (size_t k = 0; k < e.ReachTime.size(); ++k)
  {
    EXPECT_EQ(e.ReachTime[k], p.ReachTime[k]);
    reached += std::isfinite(e.ReachTime[k]) ? 1 : 0;
  }
  EXPECT_GT(reached, 20); // the target plus what the swimmer reaches by t = 0.5
}

TEST(HjbExpressionSolver, TransportFollowsTheSignOfTheHamiltonian)
{
  // f_D = 1: H = -p, v_t - v_x = 0, v = v0(x + t) (1D, periodic).
  sltk::HjbExpressionSpec s = fromOrigin(1, { 64, 1, 1 }, { 2.0 * M_PI, 0.0, 0.0 }, { "1", "", "" }, "sin(x)");
  s.Bounds[0] = sltk::Boundary::Periodic;
  s.Exact = "sin(x + t)";
  s.FinalTime = 1.0;
  s.CourantNumber = 2.5;
  const sltk::HjbRunResult r = expressions(s);
  EXPECT_LT(r.LinfError, 1e-5);
  EXPECT_GT(r.Steps, 0);
}

TEST(HjbExpressionSolver, ThreeDimensionalTransportWithControls)
{
  // f_D = a in the box [0, 1] x [0, 0] x [0, 0], f_C = 0: v = min over a1 of v0(x + a1 t) on a
  // periodic cube; with v0 = cos(x) the minimiser walks towards x = pi (exact for x + t <= pi).
  sltk::HjbExpressionSpec s = fromOrigin(3, { 24, 8, 8 }, { 2.0 * M_PI, 1.0, 1.0 }, { "a1", "a2", "a3" }, "cos(x)");
  s.Bounds = { sltk::Boundary::Periodic, sltk::Boundary::Periodic, sltk::Boundary::Periodic };
  s.Exact = "x <= pi - t ? cos(x + t) : (x <= pi ? -1 : cos(x))";
  s.Controls = sltk::ControlKind::Box;
  s.ControlDimension = 3;
  s.ControlLower = { 0.0, 0.0, 0.0 };
  s.ControlUpper = { 1.0, 0.0, 0.0 };
  s.Order = sltk::RkOrder::Euler;
  s.FinalTime = 0.5;
  s.CourantNumber = 1.0;
  s.Minimizer.TabulationPoints = 9;
  const sltk::HjbRunResult r = expressions(s);
  EXPECT_LT(r.LinfError, 2e-2) << "L1 " << r.L1Error;
}

TEST(HjbPresetSolver, PresetSolverRefusesTheReconstructionsOwnInterpolator)
{
  sltk::PresetRunOptions o;
  o.Preset = sltk::HjbPreset::Test1Rotation;
  o.Nodes = 11;
  o.Interpolator = sltk::InterpolatorKind::LeastSquaresQ1;
  std::unique_ptr<sltk::HjbSolver> solver;
  const sltk::Status s = sltk::makePresetSolver(o, solver);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_NE(s.message().find("the reconstruction's only"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("CWENOZ"), std::string::npos) << "names the ones it offers: " << s.message();
}

TEST(HjbPresetSolver, EveryPresetStepsWithEveryInterpolator)
{
  // Each preset is compiled for its setup's RK order only (PresetRun.cxx): all
  // of them build and step, with the values staying finite.
  for (int p = 1; p <= 5; ++p)
  {
    for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
    {
      sltk::PresetRunOptions o;
      o.Preset = static_cast<sltk::HjbPreset>(p);
      o.Nodes = 11;
      o.Interpolator = info.Kind;
      std::unique_ptr<sltk::HjbSolver> solver;
      ASSERT_TRUE(sltk::makePresetSolver(o, solver).isOk()) << "Test " << p << " " << info.Name;
      const sltk::Status s = solver->advanceTo(solver->startTime() + solver->timeStep(), sltk::Context{});
      EXPECT_TRUE(s.isOk()) << "Test " << p << " " << info.Name << ": " << s.message();
      EXPECT_EQ(solver->stepsDone(), 1);
    }
  }
}

TEST(HjbExpressionSolver, AdvancesStepByStepAndRestartsForEarlierTimes)
{
  sltk::HjbExpressionSpec s = rotation(21);
  s.FinalTime = 0.5;
  std::unique_ptr<sltk::HjbSolver> stepping;
  ASSERT_TRUE(sltk::makeExpressionSolver(s, stepping).isOk());
  const std::vector<double> times = stepping->stepTimes();
  ASSERT_EQ(static_cast<Index>(times.size()), stepping->stepCount() + 1);
  EXPECT_NEAR(times.back(), 0.5, 1e-15);
  for (double t : times)
  {
    ASSERT_TRUE(stepping->advanceTo(t, sltk::Context{}).isOk());
  }
  EXPECT_EQ(stepping->stepsDone(), stepping->stepCount());
  sltk::HjbRunResult a;
  stepping->result(a);
  std::unique_ptr<sltk::HjbSolver> direct;
  ASSERT_TRUE(sltk::makeExpressionSolver(s, direct).isOk());
  const sltk::HjbRunResult b = solveToEnd(direct);
  EXPECT_EQ(a.Value, b.Value);

  ASSERT_TRUE(stepping->advanceTo(times[1] + 0.1 * stepping->timeStep(), sltk::Context{}).isOk()); // between steps
  EXPECT_EQ(stepping->stepsDone(), 1);
  ASSERT_TRUE(stepping->advanceTo(0.0, sltk::Context{}).isOk());
  sltk::HjbRunResult initial;
  stepping->result(initial);
  EXPECT_EQ(initial.Value, s.InitialValues);
}

TEST(HjbExpressionSolver, RefusesBadProblemsWithClearMessages)
{
  auto message = [](const sltk::HjbExpressionSpec& s)
  {
    std::unique_ptr<sltk::HjbSolver> solver;
    const sltk::Status st = sltk::makeExpressionSolver(s, solver);
    EXPECT_FALSE(st.isOk());
    EXPECT_FALSE(solver);
    return st.message();
  };
  sltk::HjbExpressionSpec good;
  good.Nodes = { 11, 11, 1 };
  good.Dynamics = { "y", "-x", "" };
  good.Initial = "x^2 + y^2";

  auto s = good;
  s.Dynamics[1] = "-x +* 2";
  std::string m = message(s);
  EXPECT_NE(m.find("the dynamics f_D component y"), std::string::npos) << m;
  EXPECT_NE(m.find("column"), std::string::npos) << m;

  s = good;
  s.Dynamics[0] = "y + a1"; // no control set: no a1
  EXPECT_NE(message(s).find("unknown variable 'a1'"), std::string::npos);
  s = good;
  s.Initial = "x + z"; // 2D: no z
  EXPECT_NE(message(s).find("unknown variable 'z'"), std::string::npos);
  s = good;
  s.Initial = "x + t"; // v0 has no t
  EXPECT_NE(message(s).find("the initial datum v0"), std::string::npos);
  s = good;
  s.Initial.clear();
  EXPECT_NE(message(s).find("v0 is empty"), std::string::npos);
  s = good;
  s.Dynamics[1].clear();
  EXPECT_NE(message(s).find("component y is empty"), std::string::npos);
  s = good;
  s.Dimension = 4;
  EXPECT_NE(message(s).find("dimension must be 1, 2 or 3"), std::string::npos);
  s = good;
  s.Nodes[0] = 2;
  EXPECT_NE(message(s).find("use 5 to 100000"), std::string::npos);
  s = good;
  s.Lower[1] = 3.0;
  EXPECT_NE(message(s).find("lower < upper"), std::string::npos);
  s = good;
  s.FinalTime = -1.0;
  EXPECT_NE(message(s).find("final time"), std::string::npos);
  s = good;
  s.CourantNumber = 0.0;
  EXPECT_NE(message(s).find("Courant number"), std::string::npos);
  s = good;
  s.Controls = sltk::ControlKind::Finite;
  s.Cost = "1";
  EXPECT_NE(message(s).find("at least one control"), std::string::npos);
  s = good;
  s.Controls = sltk::ControlKind::Ball;
  s.ControlRadius = -1.0;
  EXPECT_NE(message(s).find("radius must be positive"), std::string::npos);
  s = good;
  s.Initial.clear();
  s.InitialValues.assign(121, 0.0);
  s.InitialValues[7] = std::nan("");
  EXPECT_NE(message(s).find("not finite at node 7"), std::string::npos);
  s.InitialValues.resize(5);
  EXPECT_NE(message(s).find("5 values for a grid of 121 nodes"), std::string::npos);
  s = good;
  s.Argmin[0] = "x";
  EXPECT_NE(message(s).find("no control set"), std::string::npos);
  s = quadraticValue();
  s.Argmin[0] = "x";
  EXPECT_NE(message(s).find("the argmin component a2 is empty"), std::string::npos);
  s.Argmin[1] = "a1";
  m = message(s);
  EXPECT_NE(m.find("the argmin component a2"), std::string::npos) << m;
  EXPECT_NE(m.find("unknown variable 'a1'"), std::string::npos) << m;
  s.Argmin[1] = "y";
  s.Argmin[2] = "0";
  EXPECT_NE(message(s).find("the controls have 2 component(s)"), std::string::npos);
  s = good;
  s.Dimension = 3;
  s.Dynamics[2] = "0";
  s.Nodes = { 100000, 100000, 100000 };
  std::unique_ptr<sltk::HjbSolver> solver;
  const sltk::Status huge = sltk::makeExpressionSolver(s, solver);
  EXPECT_EQ(huge.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_NE(huge.message().find("use fewer nodes"), std::string::npos) << huge.message();
}

TEST(HjbExpressionSolver, NamesTheFormulaAndThePointThatAreNotFinite)
{
  sltk::HjbExpressionSpec good;
  good.Nodes = { 11, 11, 1 }; // x = -1, -0.8, ..., 1: a node at x = 0
  good.Dynamics = { "y", "-x", "" };
  good.Initial = "x^2 + y^2";
  good.FinalTime = 0.2;

  // v_0 and g are known at every node before the first step: refused when the solver is made.
  auto s = good;
  s.Initial = "log(x)";
  std::unique_ptr<sltk::HjbSolver> solver;
  sltk::Status st = sltk::makeExpressionSolver(s, solver);
  EXPECT_FALSE(solver);
  EXPECT_NE(st.message().find("the initial datum v0 'log(x)' is NaN at x = -1"), std::string::npos) << st.message();
  EXPECT_NE(st.message().find("finite on the whole domain"), std::string::npos) << st.message();

  // f_D and f_C depend on the control: a step that goes non-finite names the formula, the node and the control.
  auto stepError = [](const sltk::HjbExpressionSpec& spec)
  {
    std::unique_ptr<sltk::HjbSolver> stepper;
    const sltk::Status made = sltk::makeExpressionSolver(spec, stepper);
    EXPECT_TRUE(made.isOk()) << made.message();
    const sltk::Status run = stepper ? stepper->advanceTo(stepper->finalTime(), sltk::Context{}) : made;
    EXPECT_EQ(run.code(), sltk::StatusCode::NumericalFailure);
    return run.message();
  };
  s = good;
  s.Dynamics[0] = "1/x";
  std::string m = stepError(s);
  EXPECT_NE(m.find("non-finite values in the HJB step"), std::string::npos) << m;
  EXPECT_NE(m.find("the dynamics f_D component x '1/x' is +Inf at x = 0"), std::string::npos) << m;
  s = good;
  s.Controls = sltk::ControlKind::Box;
  s.ControlDimension = 1;
  s.ControlLower = { -1.0, 0.0, 0.0 };
  s.ControlUpper = { 2.0, 0.0, 0.0 };
  s.Cost = "log(a1 - 5)"; // NaN for every admissible control (the minimiser passes over controls where it is NaN)
  m = stepError(s);
  EXPECT_NE(m.find("the running cost f_C 'log(a1 - 5)' is NaN at a1 = -1"), std::string::npos) << m;
}

TEST(HjbExpressionSolver, ReachTimesAreInterpolatedBetweenSteps)
{
  // v0 = 0.5 - x, f_D = 1: v(t, x) = 0.5 - x - t, so x is reached at T(x) = max(0.5 - x, 0), which
  // the linear interpolation of u in time (3.40) recovers exactly between the steps.
  sltk::HjbExpressionSpec s = fromOrigin(1, { 41, 1, 1 }, { 1.0, 0.0, 0.0 }, { "1", "", "" }, "0.5 - x");
  s.ReachableSet = true;
  s.FinalTime = 0.3;
  s.CourantNumber = 2.3; // dt = 0.0575 is not a multiple of dx
  s.Interpolator = sltk::InterpolatorKind::Q1;
  const sltk::HjbRunResult r = expressions(s);
  ASSERT_EQ(r.ReachTime.size(), 41u);
  for (size_t i = 0; i < 41; ++i)
  {
    const double x = static_cast<double>(i) / 40.0;
    const double expected = std::max(0.5 - x, 0.0);
    if (expected <= r.FinalTime)
    {
      EXPECT_NEAR(r.ReachTime[i], expected, 1e-12) << "x = " << x;
    }
    else
    {
      EXPECT_TRUE(std::isinf(r.ReachTime[i])) << "x = " << x;
    }
  }
}

TEST(HjbExpressionSolver, ResultBlockIsTheGridsNodesInTheExtent)
{
  // What a VTK pipeline asks of one piece (HjbSolver::resultBlock): the nodes of the extent only, clipped to
  // the grid, x fastest; the whole grid as result().
  std::unique_ptr<sltk::HjbSolver> solver;
  ASSERT_TRUE(sltk::makeExpressionSolver(rotation(21), solver).isOk());
  const sltk::HjbRunResult whole = solveToEnd(solver);
  EXPECT_EQ(whole.Block, sltk::wholeExtent(whole.Grid));
  sltk::HjbRunResult block;
  solver->resultBlock({ 3, 7, 10, 30, 0, 0 }, block); // rows 21..30 lie outside the grid
  const sltk::HjbExtent clipped{ 3, 7, 10, 20, 0, 0 };
  EXPECT_EQ(block.Block, clipped);
  ASSERT_EQ(block.Value.size(), 5u * 11u);
  for (Index j = 10; j <= 20; ++j)
  {
    for (Index i = 3; i <= 7; ++i)
    {
      EXPECT_EQ(block.Value[static_cast<size_t>((i - 3) + 5 * (j - 10))], whole.Value[static_cast<size_t>(i + 21 * j)]);
    }
  }
  EXPECT_EQ(block.Steps, whole.Steps);
  solver->resultBlock({ 0, -1, 0, -1, 0, -1 }, block);
  EXPECT_TRUE(block.Value.empty()) << "an empty extent asks for no node";
}
