// SPDX-License-Identifier: BSD-3-Clause
// The HJB scheme (3.7) with obstacles (3.39) and reachable sets (3.40), and
// the thesis's Tests 1-5 (3.5) against Tables 3.1, 3.3, 3.5, 3.7 and 3.9.
// Every problem is compiled for the one RK order it is run with and the
// automatic cell cache (withFixedOrder(), as makePresetSolver() does): the
// same kernels, a fraction of the compile time. The cache-size tests keep the
// run-time cache choice; the run-time order is tested by the expression
// solvers (TestHjbExpressionSolver.cxx), which compile every order.
#include "sltk/hjb/HjbError.h"
#include "sltk/hjb/HjbScheme.h"
#include "sltk/hjb/Presets.h"
#include "sltk/interp/Cweno.h"
#include "sltk/interp/Q1.h"
#include "sltk/interp/Weno3.h"
#include "sltk/sl/LinearSLStep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

namespace
{
using sltk::Index;
using Weno1 = sltk::Weno3Interpolator<1>;
using Cweno1 = sltk::CwenoInterpolator<1>;
using CwenoZ1 = sltk::CwenoZInterpolator<1>;
using Weno2 = sltk::Weno3Interpolator<2>;
using Cweno2 = sltk::CwenoInterpolator<2>;
using CwenoZ2 = sltk::CwenoZInterpolator<2>;

struct HjbRun
{
  double Error = 0.0;
  double Min = 0.0;
  double Max = 0.0;
  sltk::HjbStats Stats;
};

/// Solves a preset from v0 to its final time and measures against its exact solution.
template <class Interp, class Problem, int D>
HjbRun solve(const Problem& problem, const sltk::HjbSetup<D>& setup, const sltk::Context& ctx = sltk::Context{})
{
  sltk::GridField<D> u(setup.Grid, 2);
  sltk::hjbInitialize(problem, u);
  HjbRun r;
  const sltk::Status s = sltk::hjbAdvance<Interp>(ctx, setup.Options, problem, u, &r.Stats);
  EXPECT_TRUE(s.isOk()) << s.toString();
  const double t = setup.Options.FinalTime;
  r.Error = sltk::l1Error(u, [&](const std::array<double, D>& x) { return problem.Exact(t, x); });
  const auto range = sltk::valueRange(u);
  r.Min = range.first;
  r.Max = range.second;
  return r;
}

void expectWithin(double ours, double thesis, double tolerance, const char* what)
{
  EXPECT_LT(std::fabs(ours / thesis - 1.0), tolerance) << what << ": ours " << ours << ", thesis " << thesis;
}

double order(double coarse, double fine, Index nCoarse, Index nFine)
{
  return std::log(coarse / fine) / std::log(double(nFine - 1) / double(nCoarse - 1));
}

/// What a thesis table gives for one reconstruction on N nodes per axis: the L1
/// error (Tables 3.1-3.7) and, where not NaN, the minimum and maximum (Table 3.9).
struct Thesis
{
  Index N;
  double Error;
  double Min = std::nan("");
  double Max = std::nan("");
};

/// Solves the problem with Interp on setup(N) for each entry, in order, and expects
/// the L1 error and the minimum within 20% of the thesis's, the maximum within 1%;
/// `name` (e.g. "Test 4 WENO") and N name a failure. Returns the runs.
template <class Interp, class Problem, class Setup>
std::vector<HjbRun> expectThesis(
  const Problem& problem, Setup setup, const std::string& name, std::initializer_list<Thesis> entries)
{
  std::vector<HjbRun> runs;
  for (const Thesis& e : entries)
  {
    runs.push_back(solve<Interp>(problem, setup(e.N)));
    const HjbRun& r = runs.back();
    const std::string n = " N=" + std::to_string(e.N);
    expectWithin(r.Error, e.Error, 0.2, (name + n).c_str());
    if (!std::isnan(e.Min))
    {
      expectWithin(r.Min, e.Min, 0.2, (name + " min" + n).c_str());
    }
    if (!std::isnan(e.Max))
    {
      expectWithin(r.Max, e.Max, 0.01, (name + " max" + n).c_str());
    }
  }
  return runs;
}

// --- Test 1: pure transport (A = {}) -------------------------------------------------------------

TEST(HjbScheme, PureTransportEqualsTheLinearSLStep)
{
  const auto problem = sltk::withFixedOrder<sltk::Test1Order>(sltk::test1Problem());
  const auto setup = sltk::test1Setup(31);
  sltk::GridField<2> u(setup.Grid, 2);
  sltk::hjbInitialize(problem, u);
  sltk::GridField<2> v = u;
  sltk::HjbStats stats;
  ASSERT_TRUE(sltk::hjbAdvance<Cweno2>(sltk::Context{}, setup.Options, problem, u, &stats).isOk());
  // The linear step takes the PDE velocity f = -f_D (Characteristics.h).
  auto velocity = [](double t, const std::array<double, 2>& x)
  {
    const auto fD = sltk::test1Problem().Dynamics(t, x, std::array<double, 1>{});
    return std::array<double, 2>{ -fD[0], -fD[1] };
  };
  sltk::LinearSLOptions lin;
  lin.Order = setup.Options.Order;
  lin.FinalTime = setup.Options.FinalTime;
  lin.MaxTimeStep = setup.Options.MaxTimeStep;
  ASSERT_TRUE(sltk::linearSLAdvance<Cweno2>(sltk::Context{}, lin, v, velocity).isOk());
  double maxDiff = 0.0;
  for (Index k = 0; k < setup.Grid.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    maxDiff = std::max(maxDiff, std::fabs(u(i) - v(i)));
  }
  EXPECT_LT(maxDiff, 1e-15);
  EXPECT_DOUBLE_EQ(stats.evaluationsPerNode(), 1.0); // no minimisation
}

TEST(HjbScheme, Test1MatchesTable31)
{
  // Table 3.1, N = 41 and 81 (WENO, CWENO, CWENOZ).
  const auto problem = sltk::withFixedOrder<sltk::Test1Order>(sltk::test1Problem());
  expectThesis<Weno2>(problem, sltk::test1Setup, "Test 1 WENO", { { 41, 5.46e-4 } });
  expectThesis<Cweno2>(problem, sltk::test1Setup, "Test 1 CWENO", { { 41, 4.88e-4 } });
  const auto z =
    expectThesis<CwenoZ2>(problem, sltk::test1Setup, "Test 1 CWENOZ", { { 41, 4.84e-4 }, { 81, 7.85e-5 } });
  EXPECT_NEAR(order(z[0].Error, z[1].Error, 41, 81), 2.62, 0.3);
}

// --- Test 2: 1D semi-concave data, A = [-pi/2, pi/2] ---------------------------------------------

TEST(HjbScheme, Test2MatchesTable33)
{
  const auto problem = sltk::withFixedOrder<sltk::Test2Order>(sltk::test2Problem());
  const double thesis[3][2] = { { 3.56e-6, 2.83e-7 }, { 2.24e-6, 1.80e-7 }, { 1.78e-6, 1.44e-7 } };
  HjbRun r[3][2];
  const Index n[2] = { 81, 161 };
  for (int l = 0; l < 2; ++l)
  {
    r[0][l] = solve<Weno1>(problem, sltk::test2Setup(n[l]));
    r[1][l] = solve<Cweno1>(problem, sltk::test2Setup(n[l]));
    r[2][l] = solve<CwenoZ1>(problem, sltk::test2Setup(n[l]));
  }
  for (int m = 0; m < 3; ++m)
  {
    for (int l = 0; l < 2; ++l)
    {
      expectWithin(r[m][l].Error, thesis[m][l], 0.2, "Test 2");
    }
    EXPECT_NEAR(order(r[m][0].Error, r[m][1].Error, 81, 161), 3.64, 0.3);
  }
  // Central reconstructions are more accurate (3.5.2): about 2/3 of WENO's error.
  EXPECT_LT(r[1][1].Error, 0.8 * r[0][1].Error);
  EXPECT_LT(r[2][1].Error, r[1][1].Error);
  // 64 tabulated controls + the golden section.
  EXPECT_GT(r[0][0].Stats.evaluationsPerNode(), 64.0);
  EXPECT_LT(r[0][0].Stats.evaluationsPerNode(), 140.0);
}

TEST(HjbScheme, Test2MatchesTable33_Long)
{
  const auto problem = sltk::withFixedOrder<sltk::Test2Order>(sltk::test2Problem());
  expectThesis<Weno1>(problem, sltk::test2Setup, "Test 2 WENO", { { 321, 2.45e-8 }, { 641, 2.61e-9 } });
  expectThesis<CwenoZ1>(problem, sltk::test2Setup, "Test 2 CWENOZ", { { 641, 1.75e-9 } });
}

// --- Test 3: 1D eikonal, periodic, per-stage controls ---------------------------------------------

TEST(HjbScheme, Test3MatchesTable35)
{
  const auto problem = sltk::withFixedOrder<sltk::Test3Order>(sltk::test3Problem());
  const auto setup = [](Index n) { return sltk::test3Setup(n); };
  const auto w = expectThesis<Weno1>(problem, setup, "Test 3 WENO", { { 126, 1.28e-5 } });
  expectThesis<Cweno1>(problem, setup, "Test 3 CWENO", { { 126, 1.38e-5 } });
  // One control per step instead of one per RK stage loses third order (Documentation/Numerics.md, "HJB").
  auto single = sltk::test3Setup(126);
  single.Options.Minimizer.PerStageControls = false;
  const HjbRun s = solve<Weno1>(problem, single);
  EXPECT_GT(s.Error, 5.0 * w[0].Error);
}

TEST(HjbScheme, Test3MatchesTable35_Long)
{
  const auto problem = sltk::withFixedOrder<sltk::Test3Order>(sltk::test3Problem());
  const auto z = expectThesis<CwenoZ1>(
    problem, [](Index n) { return sltk::test3Setup(n); }, "Test 3 CWENOZ", { { 252, 1.70e-6 }, { 503, 2.10e-7 } });
  EXPECT_NEAR(std::log(z[0].Error / z[1].Error) / std::log(503.0 / 252.0), 3.02, 0.3);
}

// --- Test 4: 2D semi-convex data, A = disc ------------------------------------------------------

TEST(HjbScheme, Test4MatchesTables37And39)
{
  const auto problem = sltk::withFixedOrder<sltk::Test4Order>(sltk::test4Problem());
  // Tables 3.7 (error) and 3.9 (min, max): CWENO undershoots more in the flat region, both stay below 1.
  expectThesis<Weno2>(problem, sltk::test4Setup, "Test 4 WENO", { { 41, 4.02e-2, -4.62e-5, 0.989 } });
  expectThesis<Cweno2>(problem, sltk::test4Setup, "Test 4 CWENO", { { 41, 3.38e-2, -5.19e-3, 0.992 } });
}

TEST(HjbScheme, Test4WarmStartMatchesTheFullTabulation)
{
  // The preset warm-starts each node's minimisation from its previous argmin;
  // the thesis's procedure tabulates A (33 x 33) at every node and step.
  const auto problem = sltk::withFixedOrder<sltk::Test4Order>(sltk::test4Problem());
  auto cold = sltk::test4Setup(41);
  cold.Options.Minimizer.WarmTabulationPoints = 0;
  const HjbRun full = solve<Cweno2>(problem, cold);
  const HjbRun warm = solve<Cweno2>(problem, sltk::test4Setup(41));
  EXPECT_NEAR(warm.Error, full.Error, 0.01 * full.Error);
  EXPECT_NEAR(warm.Min, full.Min, 0.05 * std::fabs(full.Min));
  EXPECT_NEAR(warm.Max, full.Max, 1e-3);
  // Step 1 has no previous argmin and tabulates A in both runs: compare the
  // evaluations of the later steps.
  sltk::GridField<2> u(cold.Grid, 2), next(cold.Grid, 2);
  sltk::hjbInitialize(problem, u);
  sltk::HjbStats first;
  const double dt = cold.Options.MaxTimeStep;
  ASSERT_TRUE(sltk::hjbStep<Cweno2>(sltk::Context{}, cold.Options, problem, u, next, dt, dt, &first).isOk());
  auto laterSteps = [&](const sltk::HjbStats& s)
  { return (s.Evaluations - first.Evaluations) / (s.NodeUpdates - first.NodeUpdates); };
  ASSERT_GT(full.Stats.Steps, 2);
  EXPECT_GT(laterSteps(full.Stats), 5.0 * laterSteps(warm.Stats))
    << "evaluations per node and step after the first: cold " << laterSteps(full.Stats) << ", warm "
    << laterSteps(warm.Stats);
}

TEST(HjbScheme, Test4MatchesTables37And39_Long)
{
  const auto problem = sltk::withFixedOrder<sltk::Test4Order>(sltk::test4Problem());
  expectThesis<Weno2>(problem, sltk::test4Setup, "Test 4 WENO", { { 81, 2.25e-2, -1.21e-5 } });
  expectThesis<CwenoZ2>(problem, sltk::test4Setup, "Test 4 CWENOZ", { { 81, 1.81e-2, -3.39e-3 } });
}

// --- Test 5: obstacles (3.39) and reachable sets (3.40) ------------------------------------------

TEST(HjbScheme, ObstacleIsRespectedAndReachableSetGrows)
{
  const auto problem = sltk::withFixedOrder<sltk::Test5Order>(sltk::test5Problem());
  auto setup = sltk::test5Setup(51, 1.0); // dx = 0.1, 10 steps
  setup.Options.Minimizer.TabulationPoints = 16;
  sltk::GridField<2> u(setup.Grid, 2);
  sltk::hjbInitialize(problem, u);
  sltk::GridField<2> reach;
  ASSERT_TRUE(sltk::hjbAdvance<Cweno2>(sltk::Context{}, setup.Options, problem, u, nullptr, &reach).isOk());
  // A shorter run: its reachable set is contained in the longer one's, with the same times.
  auto shortSetup = setup;
  shortSetup.Options.FinalTime = 0.5;
  sltk::GridField<2> w(setup.Grid, 2);
  sltk::hjbInitialize(problem, w);
  sltk::GridField<2> reachShort;
  ASSERT_TRUE(sltk::hjbAdvance<Cweno2>(sltk::Context{}, shortSetup.Options, problem, w, nullptr, &reachShort).isOk());
  Index inTarget = 0, reachedLater = 0, inObstacle = 0;
  for (Index k = 0; k < setup.Grid.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    const auto x = sltk::nodePoint(setup.Grid, i);
    const double g = sltk::zermeloObstacles(x[0], x[1]);
    EXPECT_GE(u(i), g); // (3.39)
    if (g > 0.0)
    {
      ++inObstacle;
      EXPECT_EQ(reach(i), sltk::NotReached); // inside an obstacle: never in K
    }
    if (sltk::zermeloTarget(x[0], x[1]) <= 0.0)
    {
      ++inTarget;
      EXPECT_EQ(reach(i), 0.0);
    }
    else if (reach(i) != sltk::NotReached)
    {
      ++reachedLater;
      EXPECT_GT(reach(i), 0.0);
      EXPECT_LE(reach(i), 1.0 + 1e-12);
      // first hitting times interpolated in (t_{k-1}, t_k]: u^k <= 0 < u^{k-1}
    }
    if (reachShort(i) != sltk::NotReached)
    {
      EXPECT_EQ(reachShort(i), reach(i));
    }
    else if (reach(i) != sltk::NotReached)
    {
      EXPECT_GT(reach(i), 0.5);
    }
  }
  EXPECT_GT(inTarget, 0);
  EXPECT_GT(inObstacle, 0);
  EXPECT_GT(reachedLater, 5 * inTarget); // the swimmer gets there from far upstream
  // Upstream (left, where the current pushes towards the target) is reached, downstream is not.
  const sltk::GridSpec<2>& g = setup.Grid;
  auto at = [&](double x, double y)
  {
    const std::array<Index, 2> i{ Index(std::lround((x - g.Origin[0]) / g.Spacing[0])),
      Index(std::lround((y - g.Origin[1]) / g.Spacing[1])) };
    return reach(i);
  };
  EXPECT_NE(at(-0.5, 0.0), sltk::NotReached);
  EXPECT_EQ(at(1.9, 0.0), sltk::NotReached);
}

// --- Scheme mechanics ---------------------------------------------------------------------------

/// f_D = -a, f_C = |a|^2/2 on a disc, linear v0 = p . x: with Q1 the objective is
/// v0(x) - dt p . a + dt |a|^2 / 2, minimal at a = p (|p| < R) -- a closed form.
auto linearProblem()
{
  auto dynamics = [](double, const std::array<double, 2>&, const std::array<double, 2>& a) {
    return std::array<double, 2>{ -a[0], -a[1] };
  };
  auto cost = [](double, const std::array<double, 2>&, const std::array<double, 2>& a)
  { return 0.5 * (a[0] * a[0] + a[1] * a[1]); };
  auto initial = [](const std::array<double, 2>& x) { return 0.6 * x[0] - 0.9 * x[1]; };
  return sltk::makeHjbProblem<2, 2>(sltk::ControlSet<2>::ball({ 0.0, 0.0 }, 2.0), dynamics, cost, initial);
}

TEST(HjbScheme, ClosedFormFeedbackAgreesWithTheSearch)
{
  const auto searched = sltk::withFixedOrder<sltk::RkOrder::Euler>(linearProblem());
  const auto closed = sltk::withFixedOrder<sltk::RkOrder::Euler>(sltk::withFeedback(linearProblem(),
    [](double, const std::array<double, 2>&) {
      return std::array<double, 2>{ 0.6, -0.9 };
    }));
  const auto grid = sltk::hjbpreset::boxGrid<2>(21, -1.0, 1.0);
  sltk::HjbOptions opt;
  opt.Order = sltk::RkOrder::Euler;
  opt.FinalTime = 0.05;
  opt.MaxTimeStep = 0.05;
  opt.Minimizer.TabulationPoints = 17;
  opt.Minimizer.Tolerance = 1e-10;
  sltk::GridField<2> a(grid, 2), b(grid, 2);
  sltk::hjbInitialize(searched, a);
  sltk::hjbInitialize(closed, b);
  sltk::HjbStats sa, sb;
  ASSERT_TRUE(sltk::hjbAdvance<sltk::Q1Interpolator<2>>(sltk::Context{}, opt, searched, a, &sa).isOk());
  ASSERT_TRUE(sltk::hjbAdvance<sltk::Q1Interpolator<2>>(sltk::Context{}, opt, closed, b, &sb).isOk());
  EXPECT_DOUBLE_EQ(sb.evaluationsPerNode(), 1.0);
  EXPECT_GT(sa.evaluationsPerNode(), 100.0);
  // Exact solution v(t, x) = p . x - t |p|^2 / 2 away from the clipped boundary.
  for (Index k = 0; k < grid.nodeCount(); ++k)
  {
    const auto i = a.nodeIndex(k);
    const auto x = sltk::nodePoint(grid, i);
    if (std::fabs(x[0]) > 0.85 || std::fabs(x[1]) > 0.85)
    {
      continue;
    }
    const double v = 0.6 * x[0] - 0.9 * x[1] - 0.05 * 0.5 * (0.36 + 0.81);
    EXPECT_NEAR(b(i), v, 1e-14);
    EXPECT_NEAR(a(i), v, 1e-12);
  }
}

class StopAfter : public sltk::Interrupter
{
public:
  explicit StopAfter(int n)
    : Allowed(n)
  {
  }
  bool wasInterrupted(double) override { return this->Calls++ >= this->Allowed; }
  int Allowed;
  int Calls = 0;
};

TEST(HjbScheme, SerialAndThreadedAreBitIdenticalAndCacheSizeIsInvisible)
{
  const auto problem = sltk::withFixedOrder<sltk::Test4Order, -1>(sltk::test4Problem()); // cache size: run time
  auto setup = sltk::test4Setup(21);
  setup.Options.Minimizer.TabulationPoints = 9;
  sltk::GridField<2> serial(setup.Grid, 2);
  sltk::hjbInitialize(problem, serial);
  sltk::GridField<2> threaded = serial, cache1 = serial;
  sltk::HjbStats hashed, plain;
  ASSERT_TRUE(sltk::hjbAdvance<CwenoZ2>(sltk::Context{}, setup.Options, problem, serial, &hashed).isOk());
  sltk::ThreadPool pool(2);
  sltk::Context ctx;
  ctx.Executor = &pool;
  ASSERT_TRUE(sltk::hjbAdvance<CwenoZ2>(ctx, setup.Options, problem, threaded).isOk());
  auto one = setup;
  one.Options.CellCacheSize = 1;
  ASSERT_TRUE(sltk::hjbAdvance<CwenoZ2>(ctx, one.Options, problem, cache1, &plain).isOk());
  // Same evaluations, far fewer CWENO polynomials built (Remarks 3.1-3.2).
  EXPECT_EQ(hashed.Evaluations, plain.Evaluations);
  EXPECT_LT(hashed.CellBuilds, 0.5 * plain.CellBuilds);
  sltk::GridField<2> cache8(setup.Grid, 2), weno1(setup.Grid, 2), weno256(setup.Grid, 2);
  sltk::hjbInitialize(problem, cache8);
  sltk::hjbInitialize(problem, weno1);
  sltk::hjbInitialize(problem, weno256);
  auto eight = setup;
  eight.Options.CellCacheSize = 8;
  ASSERT_TRUE(sltk::hjbAdvance<CwenoZ2>(ctx, eight.Options, problem, cache8).isOk());
  ASSERT_TRUE(sltk::hjbAdvance<Weno2>(ctx, one.Options, problem, weno1).isOk());
  ASSERT_TRUE(sltk::hjbAdvance<Weno2>(ctx, setup.Options, problem, weno256).isOk());
  EXPECT_EQ(setup.Options.CellCacheSize, 0); // the default: automatic (4096 CWENO polynomials, 256 WENO interpolators)
  EXPECT_EQ(serial.storage(), threaded.storage());
  EXPECT_EQ(serial.storage(), cache1.storage());
  EXPECT_EQ(serial.storage(), cache8.storage());
  EXPECT_EQ(weno1.storage(), weno256.storage());
  sltk::GridField<2> initial(setup.Grid, 2);
  sltk::hjbInitialize(problem, initial);
  EXPECT_NE(serial.storage(), initial.storage());
}

TEST(HjbScheme, InterrupterAbortsBetweenSteps)
{
  const auto problem = sltk::withFixedOrder<sltk::Test2Order>(sltk::test2Problem());
  const auto setup = sltk::test2Setup(81); // 2 steps
  auto opt = setup.Options;
  opt.MaxTimeStep = 0.1; // 10 steps
  sltk::GridField<1> u(setup.Grid, 2);
  sltk::hjbInitialize(problem, u);
  StopAfter stop(3);
  sltk::Context ctx;
  ctx.Progress = &stop;
  Index steps = -1;
  const sltk::Status s = sltk::hjbAdvance<Cweno1>(ctx, opt, problem, u, nullptr, nullptr, &steps);
  EXPECT_EQ(s.code(), sltk::StatusCode::Aborted);
  EXPECT_EQ(steps, 3);
  // u holds step 3: the same as three single steps.
  sltk::GridField<1> ref(setup.Grid, 2), next;
  sltk::hjbInitialize(problem, ref);
  for (int n = 0; n < 3; ++n)
  {
    ASSERT_TRUE(sltk::hjbStep<Cweno1>(sltk::Context{}, opt, problem, ref, next, 0.1 * (n + 1), 0.1).isOk());
    std::swap(ref, next);
  }
  for (Index k = 0; k < setup.Grid.nodeCount(); ++k)
  {
    EXPECT_EQ(u(u.nodeIndex(k)), ref(ref.nodeIndex(k)));
  }
}

TEST(HjbScheme, RejectsBadArguments)
{
  const auto problem = sltk::withFixedOrder<sltk::Test2Order, -1>(sltk::test2Problem()); // cache size: run time
  auto setup = sltk::test2Setup(41);
  sltk::GridField<1> u(setup.Grid, 2);
  sltk::hjbInitialize(problem, u);
  auto opt = setup.Options;
  opt.CellCacheSize = 3;
  EXPECT_EQ(sltk::hjbAdvance<Weno1>(sltk::Context{}, opt, problem, u).code(), sltk::StatusCode::InvalidArgument);
  opt = setup.Options;
  opt.MaxTimeStep = 0.0;
  EXPECT_EQ(sltk::hjbAdvance<Weno1>(sltk::Context{}, opt, problem, u).code(), sltk::StatusCode::InvalidArgument);
  sltk::GridField<1> thin(setup.Grid, 1);
  EXPECT_EQ(
    sltk::hjbAdvance<Weno1>(sltk::Context{}, setup.Options, problem, thin).code(), sltk::StatusCode::InvalidArgument);
  auto bad = problem;
  bad.Controls = sltk::ControlSet<1>::box({ 1.0 }, { -1.0 });
  EXPECT_EQ(sltk::hjbAdvance<Weno1>(sltk::Context{}, setup.Options, bad, u).code(), sltk::StatusCode::InvalidArgument);
  // A problem compiled for one RK order refuses the others.
  const auto euler = sltk::withFixedOrder<sltk::RkOrder::Euler>(problem);
  opt = setup.Options;
  EXPECT_TRUE(sltk::hjbAdvance<Weno1>(sltk::Context{}, opt, euler, u).isOk());
  opt.Order = sltk::RkOrder::Heun;
  EXPECT_EQ(sltk::hjbAdvance<Weno1>(sltk::Context{}, opt, euler, u).code(), sltk::StatusCode::InvalidArgument);
}

} // namespace
