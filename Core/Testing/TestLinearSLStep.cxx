// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/ThreadPool.h"
#include "sltk/hjb/InitialData.h"
#include "sltk/interp/Cweno.h"
#include "sltk/interp/Q1.h"
#include "sltk/interp/Weno3.h"
#include "sltk/sl/LinearSLStep.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace
{
/// A manufactured solution that is linear in x, so that Q1 interpolates it
/// exactly and only the feet (3.8) and the source quadrature (3.9) make errors:
/// v = cos t + (1 + sin t) x0 [+ (0.5 - 0.3 t) x1], with a velocity that is
/// nonlinear in x and t and vanishes across the boundary (no clipped feet).
template <int D>
struct LinearManufactured
{
  static double value(double t, const std::array<double, D>& x)
  {
    double v = std::cos(t) + (1.0 + std::sin(t)) * x[0];
    if constexpr (D == 2)
    {
      v += (0.5 - 0.3 * t) * x[1];
    }
    return v;
  }
  static std::array<double, D> velocity(double t, const std::array<double, D>& x)
  {
    std::array<double, D> f{};
    const double pi = 3.141592653589793;
    f[0] = (1.0 + t) * std::sin(pi * x[0]);
    if constexpr (D == 2)
    {
      f[0] *= 1.0 + 0.5 * x[1];
      f[1] = 0.7 * std::cos(t) * std::sin(pi * x[1]) * (1.0 - 0.3 * x[0]);
    }
    return f;
  }
  /// g = v_t + f . grad v
  static double source(double t, const std::array<double, D>& x)
  {
    const auto f = velocity(t, x);
    double g = -std::sin(t) + std::cos(t) * x[0] + f[0] * (1.0 + std::sin(t));
    if constexpr (D == 2)
    {
      g += -0.3 * x[1] + f[1] * (0.5 - 0.3 * t);
    }
    return g;
  }
};

template <int D>
void expectTimeOrders()
{
  using M = LinearManufactured<D>;
  const auto g = sltk::uniformBox<D>(11, -1.0, 1.0);
  for (int order = 1; order <= 3; ++order)
  {
    double err[3];
    for (int level = 0; level < 3; ++level)
    {
      auto u = sltktest::sampleNodes(g, 1, [](const std::array<double, D>& x) { return M::value(0.0, x); });
      sltk::LinearSLOptions opt;
      opt.Order = static_cast<sltk::RkOrder>(order);
      opt.FinalTime = 1.0;
      opt.MaxTimeStep = 0.1 / (1 << level);
      sltk::Index steps = 0;
      const sltk::Status s =
        sltk::linearSLAdvance<sltk::Q1Interpolator<D>>(sltk::Context{}, opt, u, M::velocity, M::source, &steps);
      ASSERT_TRUE(s.isOk()) << s.toString();
      EXPECT_EQ(steps, 10 << level);
      err[level] = 0.0;
      for (sltk::Index k = 0; k < g.nodeCount(); ++k)
      {
        const auto i = u.nodeIndex(k);
        err[level] = std::max(err[level], std::fabs(u(i) - M::value(1.0, sltk::nodePoint(g, i))));
      }
    }
    for (int level = 1; level < 3; ++level)
    {
      EXPECT_GE(std::log2(err[level - 1] / err[level]), order - 0.2)
        << "D " << D << " RK order " << order << " level " << level << " max err " << err[level];
    }
  }
}

/// Rotation of thesis Test 1 (3.5.1): v_t - f_D . grad v = 0 with
/// f_D = (-2 pi (y - 0.5), 2 pi (x - 0.5)), so the PDE velocity is f = -f_D.
std::array<double, 2> test1Velocity(double, const std::array<double, 2>& x)
{
  const double twoPi = 6.283185307179586;
  return { twoPi * (x[1] - 0.5), -twoPi * (x[0] - 0.5) };
}

/// Test 1 on [0,1]^2 with N x N nodes, dt = 3 dx shortened to divide T = 1, RK3 feet:
/// L1 error dx^2 sum |u_i - v0(x_i)| after one revolution (thesis 3.5; Documentation/Numerics.md).
template <class Interp>
double test1Error(sltk::Index n, const sltk::Context& ctx = sltk::Context{})
{
  const auto g = sltk::uniformBox<2>(n, 0.0, 1.0);
  auto u = sltktest::sampleNodes(g, 2, [](const std::array<double, 2>& x) { return sltk::rotatingBump(x[0], x[1]); });
  sltk::LinearSLOptions opt;
  opt.Order = sltk::RkOrder::Kutta3;
  opt.FinalTime = 1.0;
  opt.MaxTimeStep = 3.0 * g.Spacing[0];
  const sltk::Status s = sltk::linearSLAdvance<Interp>(ctx, opt, u, test1Velocity);
  EXPECT_TRUE(s.isOk()) << s.toString();
  double sum = 0.0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    const auto x = sltk::nodePoint(g, i);
    sum += std::fabs(u(i) - sltk::rotatingBump(x[0], x[1]));
  }
  return sum * g.Spacing[0] * g.Spacing[1];
}

/// Table 3.1 of the thesis: L1 errors of Test 1.
struct Table31Row
{
  sltk::Index N;
  double Weno, Cweno, Cwenoz;
};
const Table31Row* table31(sltk::Index n)
{
  static const Table31Row rows[] = { { 21, 2.97e-3, 2.98e-3, 2.98e-3 }, { 41, 5.46e-4, 4.88e-4, 4.84e-4 },
    { 81, 1.24e-4, 8.18e-5, 7.85e-5 }, { 161, 2.34e-5, 1.22e-5, 1.12e-5 }, { 321, 3.92e-6, 1.72e-6, 1.49e-6 },
    { 641, 6.11e-7, 2.27e-7, 1.79e-7 }, { 1281, 8.87e-8, 2.92e-8, 2.06e-8 } };
  for (const Table31Row& r : rows)
  {
    if (r.N == n)
    {
      return &r;
    }
  }
  return nullptr;
}

/// Observed order between levels l-1 and l (dx ~ 1 / (N - 1)).
double observedOrder(const std::vector<sltk::Index>& sizes, const std::vector<double>& err, size_t l)
{
  return std::log(err[l - 1] / err[l]) / std::log(double(sizes[l] - 1) / double(sizes[l - 1] - 1));
}

/// Runs Test 1 at the given sizes, prints our errors and orders beside Table 3.1
/// and returns the errors.
template <class Interp>
std::vector<double> reportTest1(const char* name, const std::vector<sltk::Index>& sizes)
{
  std::vector<double> err;
  std::printf("Test 1 (rotation, RK3, lambda = 3), %s vs Table 3.1\n", name);
  std::printf("%6s %12s %6s | %10s %10s %10s\n", "N", "L1 err", "order", "WENO", "CWENO", "CWENOZ");
  for (size_t l = 0; l < sizes.size(); ++l)
  {
    err.push_back(test1Error<Interp>(sizes[l]));
    char order[16] = "     -";
    if (l > 0)
    {
      std::snprintf(order, sizeof(order), "%6.2f", observedOrder(sizes, err, l));
    }
    const Table31Row* row = table31(sizes[l]);
    std::printf("%6lld %12.3e %s | %10.2e %10.2e %10.2e\n", static_cast<long long>(sizes[l]), err[l], order,
      row ? row->Weno : 0.0, row ? row->Cweno : 0.0, row ? row->Cwenoz : 0.0);
  }
  return err;
}

/// Test 1 with a high-order interpolator: our errors within 2% of the thesis's column.
template <class Interp>
void expectTable31(const char* name, const std::vector<sltk::Index>& sizes, double Table31Row::*column)
{
  const auto err = reportTest1<Interp>(name, sizes);
  for (size_t l = 0; l < sizes.size(); ++l)
  {
    const Table31Row* row = table31(sizes[l]);
    ASSERT_NE(row, nullptr);
    EXPECT_NEAR(err[l], row->*column, 0.02 * row->*column) << name << " N = " << sizes[l];
  }
}

/// Stops after a given number of wasInterrupted() calls, recording the fractions.
class StopAfter : public sltk::Interrupter
{
public:
  explicit StopAfter(int calls)
    : Allowed(calls)
  {
  }
  bool wasInterrupted(double fraction) override
  {
    this->Fractions.push_back(fraction);
    return static_cast<int>(this->Fractions.size()) > this->Allowed;
  }
  int Allowed;
  std::vector<double> Fractions;
};
} // namespace

TEST(LinearSLStep, TimeOrdersWithExactInterpolation1D)
{
  expectTimeOrders<1>();
}

TEST(LinearSLStep, TimeOrdersWithExactInterpolation2D)
{
  expectTimeOrders<2>();
}

TEST(LinearSLStep, ConstantAdvectionAtIntegerCourantIsExact)
{
  // (2.6) with lambda' = 0: feet on nodes, periodic wrap, any interpolator copies values.
  sltk::GridSpec<1> g;
  g.Dims[0] = 20;
  g.Origin[0] = 0.0;
  g.Spacing[0] = 0.05;
  g.Bounds[0] = sltk::Boundary::Periodic;
  auto u = sltktest::sampleNodes(
    g, 1, [](const std::array<double, 1>& x) { return std::sin(6.283185307179586 * x[0]) + x[0]; });
  const auto u0 = u;
  sltk::GridField<1> next;
  // c = 1, dt = 0.15: lambda = 3, feet 3 nodes upwind.
  auto c = [](double, const std::array<double, 1>&) { return std::array<double, 1>{ 1.0 }; };
  const sltk::Status s =
    sltk::linearSLStep<sltk::Q1Interpolator<1>>(sltk::Context{}, sltk::RkOrder::Kutta3, u, next, 0.15, 0.15, c);
  ASSERT_TRUE(s.isOk()) << s.toString();
  for (sltk::Index i = 0; i < 20; ++i)
  {
    EXPECT_EQ(next({ i }), u0({ (i + 17) % 20 })) << "node " << i;
  }
}

TEST(LinearSLStep, PeriodicSmoothProblemIsThirdOrderWithCubicInterpolation)
{
  // v = sin(2 pi x) cos t + 0.5 sin t, f = 1 + 0.5 sin(2 pi x) cos t on a periodic [0, 1),
  // g = v_t + f v_x; RK3 + Simpson (2.45) and the cubic (CWENO's optimal polynomial, d = 1):
  // error Delta t^3 + Delta x^4 / Delta t (2.38) = O(Delta x^3) at lambda = 2.5.
  const double twoPi = 6.283185307179586;
  auto exact = [twoPi](double t, const std::array<double, 1>& x)
  { return std::sin(twoPi * x[0]) * std::cos(t) + 0.5 * std::sin(t); };
  auto f = [twoPi](double t, const std::array<double, 1>& x)
  { return std::array<double, 1>{ 1.0 + 0.5 * std::sin(twoPi * x[0]) * std::cos(t) }; };
  auto g = [&](double t, const std::array<double, 1>& x)
  {
    const double vt = -std::sin(twoPi * x[0]) * std::sin(t) + 0.5 * std::cos(t);
    const double vx = twoPi * std::cos(twoPi * x[0]) * std::cos(t);
    return vt + f(t, x)[0] * vx;
  };
  double err[3];
  for (int level = 0; level < 3; ++level)
  {
    sltk::GridSpec<1> grid;
    grid.Dims[0] = 40 << level;
    grid.Origin[0] = 0.0;
    grid.Spacing[0] = 1.0 / double(grid.Dims[0]);
    grid.Bounds[0] = sltk::Boundary::Periodic;
    auto u = sltktest::sampleNodes(grid, 2, [&](const std::array<double, 1>& x) { return exact(0.0, x); });
    sltk::LinearSLOptions opt;
    opt.FinalTime = 1.0;
    opt.MaxTimeStep = 2.5 * grid.Spacing[0];
    const sltk::Status s =
      sltk::linearSLAdvance<sltk::CwenoInterpolator<1, sltk::CwenoVariant::Optimal>>(sltk::Context{}, opt, u, f, g);
    ASSERT_TRUE(s.isOk()) << s.toString();
    err[level] = 0.0;
    for (sltk::Index i = 0; i < grid.Dims[0]; ++i)
    {
      err[level] += grid.Spacing[0] * std::fabs(u({ i }) - exact(1.0, sltk::nodePoint(grid, { i })));
    }
  }
  std::printf("periodic 1D, RK3 + cubic, lambda = 2.5: N = 40, 80, 160: L1 err %.3e %.3e %.3e, orders %.2f %.2f\n",
    err[0], err[1], err[2], std::log2(err[0] / err[1]), std::log2(err[1] / err[2]));
  for (int level = 1; level < 3; ++level)
  {
    EXPECT_GE(std::log2(err[level - 1] / err[level]), 2.8) << "level " << level << " L1 err " << err[level];
  }
}

TEST(LinearSLStep, RotationTest1WithQ1)
{
  const std::vector<sltk::Index> sizes = { 41, 81 };
  const auto err = reportTest1<sltk::Q1Interpolator<2>>("Q1", sizes);
  // Q1 at a fixed Courant number: the interpolation error Delta x^2 / Delta t of (2.38)
  // (the numerical viscosity (2.28)) dominates, so the scheme is first order.
  EXPECT_GE(observedOrder(sizes, err, 1), 0.8);
  // The bump's L1 norm is ~ 3e-3: a lost or misplaced bump gives errors of that size.
  EXPECT_LT(err[0], 2e-3);
}

TEST(LinearSLStep, RotationTest1WithQ1_Long)
{
  const std::vector<sltk::Index> sizes = { 41, 81, 161, 321 };
  const auto err = reportTest1<sltk::Q1Interpolator<2>>("Q1", sizes);
  for (size_t l = 1; l < sizes.size(); ++l)
  {
    EXPECT_GE(observedOrder(sizes, err, l), 0.8);
  }
}

TEST(LinearSLStep, RotationTest1MatchesTable31)
{
  const std::vector<sltk::Index> sizes = { 41, 81 };
  expectTable31<sltk::Weno3Interpolator<2>>("WENO3", sizes, &Table31Row::Weno);
  expectTable31<sltk::CwenoInterpolator<2, sltk::CwenoVariant::Cweno>>("CWENO", sizes, &Table31Row::Cweno);
  expectTable31<sltk::CwenoInterpolator<2, sltk::CwenoVariant::CwenoZ>>("CWENOZ", sizes, &Table31Row::Cwenoz);
}

TEST(LinearSLStep, RotationTest1MatchesTable31_Long)
{
  const std::vector<sltk::Index> sizes = { 21, 41, 81, 161, 321 };
  expectTable31<sltk::Weno3Interpolator<2>>("WENO3", sizes, &Table31Row::Weno);
  expectTable31<sltk::CwenoInterpolator<2, sltk::CwenoVariant::Cweno>>("CWENO", sizes, &Table31Row::Cweno);
  expectTable31<sltk::CwenoInterpolator<2, sltk::CwenoVariant::CwenoZ>>("CWENOZ", sizes, &Table31Row::Cwenoz);
}

template <class Interp>
void expectSerialEqualsThreaded()
{
  sltk::ThreadPool one(1), two(2);
  sltk::Context serial, threaded;
  serial.Executor = &one;
  threaded.Executor = &two;
  const auto g = sltk::uniformBox<2>(61, 0.0, 1.0);
  auto init = [](const std::array<double, 2>& x) { return sltk::rotatingBump(x[0], x[1]); };
  auto a = sltktest::sampleNodes(g, 2, init);
  auto b = sltktest::sampleNodes(g, 2, init);
  sltk::LinearSLOptions opt;
  opt.FinalTime = 0.3;
  opt.MaxTimeStep = 3.0 * g.Spacing[0];
  ASSERT_TRUE(sltk::linearSLAdvance<Interp>(serial, opt, a, test1Velocity).isOk());
  ASSERT_TRUE(sltk::linearSLAdvance<Interp>(threaded, opt, b, test1Velocity).isOk());
  ASSERT_EQ(a.storage().size(), b.storage().size());
  size_t differing = 0;
  for (size_t k = 0; k < a.storage().size(); ++k)
  {
    differing += a.storage()[k] != b.storage()[k] ? 1 : 0;
  }
  EXPECT_EQ(differing, 0u);
  // and the run did move the data
  auto c = sltktest::sampleNodes(g, 2, init);
  EXPECT_NE(a.storage(), c.storage());
}

TEST(LinearSLStep, SerialAndThreadedResultsAreBitIdentical)
{
  expectSerialEqualsThreaded<sltk::Q1Interpolator<2>>();
  expectSerialEqualsThreaded<sltk::CwenoInterpolator<2, sltk::CwenoVariant::CwenoZ>>();
}

/// One CWENO step (its feet interpolated through the cell cache, four nodes at
/// a time, on two threads) against the same step node by node with
/// sltk::interpolate(): the same finite values bit for bit, NaN where a foot is
/// not finite (the velocity is NaN beyond x_0 = 0.8), and the same count of
/// non-finite values in the status.
template <class Interp>
void expectCachedFeetAsNodeByNode(sltk::Index n, double courant)
{
  constexpr int D = Interp::Dim;
  using Point = std::array<double, D>;
  const auto g = sltk::uniformBox<D>(n, 0.0, 1.0);
  auto init = [](const Point& x) { return sltk::rotatingBump(x[0], x[1]) + (D == 3 ? 0.3 * x[D - 1] : 0.0); };
  auto u = sltktest::sampleNodes(g, 2, init);
  auto velocity = [](double t, const Point& x)
  {
    Point v{};
    const std::array<double, 2> r = test1Velocity(t, { x[0], x[1] });
    v[0] = x[0] > 0.8 ? std::numeric_limits<double>::quiet_NaN() : r[0];
    v[1] = r[1];
    return v;
  };
  auto source = [](double t, const Point& x) { return t * x[0] - x[1]; };
  sltk::ThreadPool two(2);
  sltk::Context threaded;
  threaded.Executor = &two;
  sltk::GridField<D> next;
  const double dt = courant * g.Spacing[0];
  const double tNext = 0.25 + dt;
  const sltk::Status status =
    sltk::linearSLStep<Interp>(threaded, sltk::RkOrder::Kutta3, u, next, tNext, dt, velocity, source);
  Interp interp(u);
  sltk::CharacteristicStages<D, 3> stages;
  const auto tableau = sltk::kutta3Tableau();
  auto backward = [&](double t, const Point& x, int)
  {
    Point v = velocity(t, x);
    for (double& c : v)
    {
      c = -c;
    }
    return v;
  };
  size_t differing = 0;
  sltk::Index nonFinite = 0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    sltk::traceCharacteristic(tableau, sltk::nodePoint(g, i), tNext, dt, backward, stages);
    bool located = true;
    for (double c : stages.Foot)
    {
      located = located && std::isfinite(c);
    }
    const double expected = located ? sltk::interpolate(interp, g, stages.Foot.data()) +
        sltk::stageQuadrature(tableau, stages, dt, [&](double t, const Point& x, int) { return source(t, x); })
                                    : std::numeric_limits<double>::quiet_NaN();
    nonFinite += std::isfinite(expected) ? 0 : 1;
    const bool same = std::isnan(expected) ? std::isnan(next(i)) : next(i) == expected;
    differing += same ? 0 : 1;
  }
  EXPECT_EQ(differing, 0u);
  ASSERT_GT(nonFinite, 0);
  ASSERT_LT(nonFinite, g.nodeCount() / 2);
  EXPECT_EQ(status.code(), sltk::StatusCode::NumericalFailure);
  EXPECT_EQ(status.message().rfind(std::to_string(nonFinite) + " non-finite values", 0), 0u) << status.message();
}

TEST(LinearSLStep, CwenoFeetThroughTheCellCacheAreTheNodeByNodeValuesBitForBit)
{
  expectCachedFeetAsNodeByNode<sltk::CwenoInterpolator<2, sltk::CwenoVariant::Cweno>>(41, 0.7);
  expectCachedFeetAsNodeByNode<sltk::CwenoInterpolator<2, sltk::CwenoVariant::CwenoZ>>(41, 3.0);
  expectCachedFeetAsNodeByNode<sltk::CwenoInterpolator<3, sltk::CwenoVariant::Cweno>>(13, 1.5);
}

TEST(LinearSLStep, InterrupterAbortsBetweenSteps)
{
  const auto g = sltk::uniformBox<2>(21, 0.0, 1.0);
  auto init = [](const std::array<double, 2>& x) { return sltk::rotatingBump(x[0], x[1]); };
  auto u = sltktest::sampleNodes(g, 2, init);
  StopAfter stop(4);
  sltk::Context ctx;
  ctx.Progress = &stop;
  sltk::LinearSLOptions opt;
  opt.FinalTime = 1.0;
  opt.MaxTimeStep = 0.1;
  sltk::Index steps = -1;
  const sltk::Status s =
    sltk::linearSLAdvance<sltk::Q1Interpolator<2>>(ctx, opt, u, test1Velocity, sltk::NoSource{}, &steps);
  EXPECT_EQ(s.code(), sltk::StatusCode::Aborted);
  EXPECT_EQ(steps, 4);
  ASSERT_EQ(stop.Fractions.size(), 5u);
  for (size_t k = 0; k < stop.Fractions.size(); ++k)
  {
    EXPECT_DOUBLE_EQ(stop.Fractions[k], 0.1 * double(k));
  }
  // u holds the last completed step: the same as four single steps.
  auto ref = sltktest::sampleNodes(g, 2, init);
  sltk::GridField<2> next;
  for (int n = 0; n < 4; ++n)
  {
    ASSERT_TRUE(sltk::linearSLStep<sltk::Q1Interpolator<2>>(
      sltk::Context{}, opt.Order, ref, next, 0.1 * (n + 1), 0.1, test1Velocity)
                  .isOk());
    std::swap(ref, next);
  }
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    EXPECT_EQ(u(i), ref(i));
  }
}

TEST(LinearSLStep, ReportsNonFiniteValuesAndBadArguments)
{
  const auto g = sltk::uniformBox<2>(11, 0.0, 1.0);
  auto u = sltktest::sampleNodes(g, 1, [](const std::array<double, 2>& x) { return x[0]; });
  sltk::GridField<2> next;
  auto nanAtCorner = [](double, const std::array<double, 2>& x) {
    return std::array<double, 2>{ x[0] > 0.95 && x[1] > 0.95 ? std::nan("") : 0.1, 0.0 };
  };
  sltk::Status s =
    sltk::linearSLStep<sltk::Q1Interpolator<2>>(sltk::Context{}, sltk::RkOrder::Heun, u, next, 0.1, 0.1, nanAtCorner);
  EXPECT_EQ(s.code(), sltk::StatusCode::NumericalFailure) << s.toString();
  auto nanSource = [](double, const std::array<double, 2>& x) { return x[1] < 0.05 ? std::nan("") : 0.0; };
  auto still = [](double, const std::array<double, 2>&) { return std::array<double, 2>{ 0.0, 0.0 }; };
  s = sltk::linearSLStep<sltk::Q1Interpolator<2>>(
    sltk::Context{}, sltk::RkOrder::Euler, u, next, 0.1, 0.1, still, nanSource);
  EXPECT_EQ(s.code(), sltk::StatusCode::NumericalFailure) << s.toString();
  s = sltk::linearSLStep<sltk::Q1Interpolator<2>>(sltk::Context{}, sltk::RkOrder::Euler, u, next, 0.1, 0.1, still);
  EXPECT_TRUE(s.isOk()) << s.toString();

  s = sltk::linearSLStep<sltk::Q1Interpolator<2>>(sltk::Context{}, sltk::RkOrder::Euler, u, next, 0.1, -0.1, still);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  s = sltk::linearSLStep<sltk::Q1Interpolator<2>>(
    sltk::Context{}, static_cast<sltk::RkOrder>(4), u, next, 0.1, 0.1, still);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  auto noGhosts = sltktest::sampleNodes(g, 0, [](const std::array<double, 2>& x) { return x[0]; });
  s =
    sltk::linearSLStep<sltk::Q1Interpolator<2>>(sltk::Context{}, sltk::RkOrder::Euler, noGhosts, next, 0.1, 0.1, still);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  sltk::LinearSLOptions opt;
  opt.MaxTimeStep = 0.0;
  s = sltk::linearSLAdvance<sltk::Q1Interpolator<2>>(sltk::Context{}, opt, u, still);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
}
