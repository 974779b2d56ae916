// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Presets.h
/// The HJB tests of thesis 3.5 as ready problems (HjbProblem.h) and setups
/// (grid + solver options), with the readings of Documentation/Numerics.md where the text is
/// ambiguous:
///  - Test 1 (3.5.1) rotation: A = {} , f_C = 0, f_D = (-2 pi (y - 1/2), 2 pi (x - 1/2)),
///    [0, 1]^2, extrapolation, RK3, dt = 3 dx, T = 1, exact = v0;
///  - Test 2 (3.5.2) (3.32): A = [-pi/2, pi/2], f_D = -a, f_C = a^2/2, [-2, 2],
///    RK1, dt = 10 dx, T = 1, 64 tabulated controls + golden section, exact (3.33);
///  - Test 3 (3.5.3) (3.36): A = [-2, 2], f_D = -a, f_C = a^2/2 + f(t, x), periodic
///    [0, 2 pi) with N distinct nodes, RK3 with one control per stage (A^3), dt = dx,
///    T = 1 (Table 3.5's caption; the text says 0.5: both are selectable);
///  - Test 4 (3.5.4) (3.37): A = disc of radius 2.2 (>= max |grad v0| = 2), f_D = -a,
///    f_C = |a|^2/2, [-2, 2]^2, RK1, dt = 5/4 dx, T = 0.5 (exact (3.38) has range
///    [0, 1] there, as Table 3.9 says), 33 x 33 tabulation + Nelder-Mead at the
///    first step, then warm starts from each node's previous argmin (5 x 5);
///  - Test 5 (3.5.5) Zermelo with obstacles (3.39)-(3.40): A = unit circle,
///    f_D = (2 - x2^2 / 2 + a1, a2), f_C = 0, [-3, 2] x [-2, 2], RK3 with one control
///    per stage, dt = dx, T = 3.

#include "sltk/hjb/HjbProblem.h"
#include "sltk/hjb/HjbScheme.h"
#include "sltk/hjb/InitialData.h"

#include <array>

namespace sltk
{

/// Grid and solver options of a preset.
template <int D>
struct HjbSetup
{
  GridSpec<D> Grid{};
  HjbOptions Options{};
};

namespace hjbpreset
{

/// Uniform extrapolated grid of n nodes per axis on [lo, hi]^D.
template <int D>
inline GridSpec<D> boxGrid(Index n, double lo, double hi)
{
  return uniformBox<D>(n, lo, hi);
}

} // namespace hjbpreset

// --- Test 1 ---------------------------------------------------------------------------------------

inline auto test1Problem()
{
  auto dynamics = [](double, const std::array<double, 2>& x, const std::array<double, 1>&)
  {
    constexpr double twoPi = 6.283185307179586;
    return std::array<double, 2>{ -twoPi * (x[1] - 0.5), twoPi * (x[0] - 0.5) };
  };
  auto initial = [](const std::array<double, 2>& x) { return rotatingBump(x[0], x[1]); };
  // Rigid rotation of period 1: v(t, x) = v0(x) at integer t (the only times the tests use).
  auto exact = [](double, const std::array<double, 2>& x) { return rotatingBump(x[0], x[1]); };
  return withExact(makeHjbProblem<2, 1>(ControlSet<1>::none(), dynamics, NoCost{}, initial), exact);
}

/// The RK order of test1Setup(), a compile-time constant so that the run-time
/// solver (makePresetSolver()) compiles the kernel of (3.7) for it only.
inline constexpr RkOrder Test1Order = RkOrder::Kutta3;

inline HjbSetup<2> test1Setup(Index n)
{
  HjbSetup<2> s;
  s.Grid = hjbpreset::boxGrid<2>(n, 0.0, 1.0);
  s.Options.Order = Test1Order;
  s.Options.FinalTime = 1.0;
  s.Options.MaxTimeStep = 3.0 * s.Grid.Spacing[0];
  return s;
}

// --- Test 2 ---------------------------------------------------------------------------------------

inline auto test2Problem()
{
  constexpr double halfPi = 1.5707963267948966;
  auto dynamics = [](double, const std::array<double, 1>&, const std::array<double, 1>& a)
  { return std::array<double, 1>{ -a[0] }; };
  auto cost = [](double, const std::array<double, 1>&, const std::array<double, 1>& a) { return 0.5 * a[0] * a[0]; };
  auto initial = [](const std::array<double, 1>& x) { return semiConcaveCosine(x[0]); };
  auto exact = [](double t, const std::array<double, 1>& x) { return semiConcaveCosineExact(t, x[0]); };
  return withExact(makeHjbProblem<1, 1>(ControlSet<1>::box({ -halfPi }, { halfPi }), dynamics, cost, initial), exact);
}

inline constexpr RkOrder Test2Order = RkOrder::Euler; ///< the RK order of test2Setup()

inline HjbSetup<1> test2Setup(Index n)
{
  HjbSetup<1> s;
  s.Grid = hjbpreset::boxGrid<1>(n, -2.0, 2.0);
  s.Options.Order = Test2Order; // affine characteristics: RK1 is exact (3.5.2)
  s.Options.FinalTime = 1.0;
  s.Options.MaxTimeStep = 10.0 * s.Grid.Spacing[0];
  s.Options.Minimizer.TabulationPoints = 64;
  s.Options.Minimizer.Search = LocalSearch::Golden;
  s.Options.Minimizer.Tolerance = 1e-12;
  return s;
}

// --- Test 3 ---------------------------------------------------------------------------------------

inline auto test3Problem()
{
  auto dynamics = [](double, const std::array<double, 1>&, const std::array<double, 1>& a)
  { return std::array<double, 1>{ -a[0] }; };
  // f_C = a^2/2 + f(t, x): H = max_a { a p - a^2/2 } - f = p^2/2 - f, (3.36).
  auto cost = [](double t, const std::array<double, 1>& x, const std::array<double, 1>& a)
  { return 0.5 * a[0] * a[0] + eikonalSource(t, x[0]); };
  auto initial = [](const std::array<double, 1>& x) { return eikonalExact(0.0, x[0]); };
  auto exact = [](double t, const std::array<double, 1>& x) { return eikonalExact(t, x[0]); };
  return withExact(makeHjbProblem<1, 1>(ControlSet<1>::box({ -2.0 }, { 2.0 }), dynamics, cost, initial), exact);
}

inline constexpr RkOrder Test3Order = RkOrder::Kutta3; ///< the RK order of test3Setup()

inline HjbSetup<1> test3Setup(Index n, double finalTime = 1.0)
{
  HjbSetup<1> s;
  s.Grid.Dims[0] = n;
  s.Grid.Origin[0] = 0.0;
  s.Grid.Spacing[0] = 6.283185307179586 / static_cast<double>(n);
  s.Grid.Bounds[0] = Boundary::Periodic;
  s.Options.Order = Test3Order;
  s.Options.FinalTime = finalTime;
  s.Options.MaxTimeStep = s.Grid.Spacing[0];
  s.Options.Minimizer.TabulationPoints = 64;
  s.Options.Minimizer.PerStageControls = true; // essential for third order (3.5.3)
  s.Options.Minimizer.Search = LocalSearch::NelderMead;
  s.Options.Minimizer.Tolerance = 1e-10;
  return s;
}

// --- Test 4 ---------------------------------------------------------------------------------------

inline auto test4Problem()
{
  auto dynamics = [](double, const std::array<double, 2>&, const std::array<double, 2>& a) {
    return std::array<double, 2>{ -a[0], -a[1] };
  };
  auto cost = [](double, const std::array<double, 2>&, const std::array<double, 2>& a)
  { return 0.5 * (a[0] * a[0] + a[1] * a[1]); };
  auto initial = [](const std::array<double, 2>& x) { return semiConvexCap(x[0], x[1]); };
  auto exact = [](double t, const std::array<double, 2>& x) { return semiConvexCapExact(t, x[0], x[1]); };
  return withExact(makeHjbProblem<2, 2>(ControlSet<2>::ball({ 0.0, 0.0 }, 2.2), dynamics, cost, initial), exact);
}

inline constexpr RkOrder Test4Order = RkOrder::Euler; ///< the RK order of test4Setup()

inline HjbSetup<2> test4Setup(Index n)
{
  HjbSetup<2> s;
  s.Grid = hjbpreset::boxGrid<2>(n, -2.0, 2.0);
  s.Options.Order = Test4Order; // H independent of (t, x): affine characteristics
  s.Options.FinalTime = 0.5;
  s.Options.MaxTimeStep = 1.25 * s.Grid.Spacing[0];
  s.Options.Minimizer.TabulationPoints = 33;
  s.Options.Minimizer.Search = LocalSearch::NelderMead;
  s.Options.Minimizer.Tolerance = 1e-8;
  // The argmin moves continuously in time here: warm starts (a coarse 5 x 5
  // tabulation of A plus 5 x 5 points around the node's previous argmin, then
  // Nelder-Mead) find the thesis's minima -- L1 1.000-1.010x Table 3.7 at
  // N = 81-641, Table 3.9 to 3 digits -- with about 125 evaluations per node
  // and step after the first (N = 641) against 880 for the 33 x 33 tabulation
  // (N = 81, 161; sltkBenchHjb --warm 0).
  s.Options.Minimizer.WarmTabulationPoints = 5;
  return s;
}

// --- Test 5 ---------------------------------------------------------------------------------------

inline auto test5Problem()
{
  auto dynamics = [](double, const std::array<double, 2>& x, const std::array<double, 2>& a) {
    return std::array<double, 2>{ 2.0 - 0.5 * x[1] * x[1] + a[0], a[1] };
  };
  auto initial = [](const std::array<double, 2>& x) { return zermeloTarget(x[0], x[1]); };
  auto obstacle = [](const std::array<double, 2>& x) { return zermeloObstacles(x[0], x[1]); };
  return withObstacle(
    makeHjbProblem<2, 2>(ControlSet<2>::sphere({ 0.0, 0.0 }, 1.0), dynamics, NoCost{}, initial), obstacle);
}

inline constexpr RkOrder Test5Order = RkOrder::Kutta3; ///< the RK order of test5Setup()

/// nx nodes along x on [-3, 2], ny = 4 (nx - 1) / 5 + 1 along y on [-2, 2] (126 x 101, ...).
inline HjbSetup<2> test5Setup(Index nx, double finalTime = 3.0)
{
  HjbSetup<2> s;
  const Index ny = 4 * (nx - 1) / 5 + 1;
  s.Grid.Dims = { nx, ny };
  s.Grid.Origin = { -3.0, -2.0 };
  s.Grid.Spacing = { 5.0 / static_cast<double>(nx - 1), 4.0 / static_cast<double>(ny - 1) };
  s.Grid.Bounds = { Boundary::Extrapolate, Boundary::Extrapolate };
  s.Options.Order = Test5Order;
  s.Options.FinalTime = finalTime;
  s.Options.MaxTimeStep = s.Grid.Spacing[0];
  s.Options.Minimizer.TabulationPoints = 32;
  s.Options.Minimizer.PerStageControls = true;
  s.Options.Minimizer.Search = LocalSearch::NelderMead;
  s.Options.Minimizer.Tolerance = 1e-8;
  return s;
}

} // namespace sltk
