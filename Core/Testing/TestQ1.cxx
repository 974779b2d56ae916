// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/interp/Q1.h"

#include "sltk/grid/SampleField.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
template <int D>
sltk::GridSpec<D> grid(sltk::Index n)
{
  sltk::GridSpec<D> g;
  for (int a = 0; a < D; ++a)
  {
    g.Dims[a] = n + a;
    g.Origin[a] = -1.0;
    g.Spacing[a] = 2.0 / double(n - 1);
    g.Bounds[a] = sltk::Boundary::Extrapolate;
  }
  return g;
}

template <int D, class F>
sltk::GridField<D> sample(const sltk::GridSpec<D>& g, F f)
{
  return sltk::sampleField(g, 1, f);
}
} // namespace

TEST(Q1, ReproducesMultilinearFunctionsIn3D)
{
  auto g = grid<3>(7);
  auto f = [](const double* x) { return 1.0 + x[0] - 2.0 * x[1] + 0.5 * x[0] * x[1] * x[2] - x[1] * x[2]; };
  auto u = sample(g, f);
  sltk::Q1Interpolator<3> q(u);
  for (int s = 0; s < 200; ++s)
  {
    const double x[3] = { std::sin(s * 1.3), std::cos(s * 0.7), std::sin(s * 2.9 + 1.0) };
    EXPECT_NEAR(sltk::interpolate(q, g, x), f(x), 1e-13);
  }
}

TEST(Q1, InterpolatesNodalValuesExactly)
{
  auto g = grid<2>(9);
  auto f = [](const double* x) { return std::exp(x[0]) * std::sin(3 * x[1]); };
  auto u = sample(g, f);
  sltk::Q1Interpolator<2> q(u);
  sltktest::expectNodalValuesExactly<2>(q, g, u);
}

TEST(Q1, SecondOrderIn1D)
{
  double err[3];
  for (int level = 0; level < 3; ++level)
  {
    auto g = grid<1>(11 << level);
    auto f = [](const double* x) { return std::sin(2.0 * x[0]); };
    auto u = sample(g, f);
    sltk::Q1Interpolator<1> q(u);
    err[level] = 0.0;
    for (int s = 0; s < 1000; ++s)
    {
      const double x[1] = { -1.0 + 2.0 * (s + 0.5) / 1000.0 };
      err[level] = std::max(err[level], std::fabs(sltk::interpolate(q, g, x) - f(x)));
    }
  }
  for (int level = 1; level < 3; ++level)
  {
    // n = 11, 22, 44 nodes: spacing ratio (n-1) 10, 21, 43
    const double ratio =
      std::log(err[level - 1] / err[level]) / std::log(double((11 << level) - 1) / double((11 << (level - 1)) - 1));
    EXPECT_GE(ratio, 1.8) << "level " << level;
  }
}

TEST(Q1, ResampleIsInterpolateBitForBit)
{
  // A coarse field on a finer, shifted grid reaching past it (clipped), as
  // between runs: q1Resample's tabulated axes give interpolate()'s values.
  auto from = grid<3>(7);
  auto u = sample(from, [](const double* x) { return std::sin(3 * x[0]) * std::exp(x[1]) + x[2] * x[2]; });
  sltk::GridSpec<3> g = grid<3>(12);
  g.Origin = { -1.13, -0.97, -1.0 };
  sltk::GridField<3> to(g, 2);
  sltk::ThreadPool pool(2);
  sltk::Context ctx;
  ctx.Executor = &pool;
  const sltk::Index lines = g.nodeCount() / g.Dims[0];
  sltk::q1Resample(u, 1, lines, ctx, to);
  sltk::Q1Interpolator<3> q(u);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = to.nodeIndex(k);
    const double x[3] = { g.coordinate(0, i[0]), g.coordinate(1, i[1]), g.coordinate(2, i[2]) };
    const double expected = k < g.Dims[0] ? 0.0 : sltk::interpolate(q, from, x); // line 0 not resampled
    ASSERT_EQ(to(i), expected) << "node " << k;
  }
}

TEST(Q1, SubcellCentresAreEvalBitForBit)
{
  // The energy's subcell centres (4.30), R a compile-time constant or a variable, against eval() at each centre.
  auto g = grid<3>(6);
  auto u = sample(g, [](const double* x) { return std::sin(3 * x[0]) * std::exp(x[1]) + x[2] * x[2]; });
  sltk::Q1Interpolator<3> q(u);
  const std::array<sltk::Index, 3> cell = { 2, 1, 3 };
  q.prepare(cell);
  double corner[8];
  sltk::cellCorners<3>(u, cell, corner);
  auto expectEval = [&](const double* values, int R)
  {
    for (int k = 0; k < R * R * R; ++k)
    {
      const double inv = 1.0 / R; // the centres (m + 1/2) / R as the energy computes them
      const std::array<double, 3> t = { (k % R + 0.5) * inv, (k / R % R + 0.5) * inv, (k / (R * R) + 0.5) * inv };
      ASSERT_EQ(values[k], q.eval(t)) << "R " << R << ", centre " << k;
    }
  };
  std::vector<double> buffers(4 * sltk::q1SubcellBuffer<3>(5));
  expectEval(
    sltk::q1AtSubcellCentres<3>(corner, std::integral_constant<int, 5>{}, buffers.data(), buffers.data() + 125), 5);
  expectEval(sltk::q1AtSubcellCentres<3>(corner, 5, buffers.data() + 250, buffers.data() + 375), 5);
  expectEval(sltk::q1AtSubcellCentres<3>(corner, 1, buffers.data(), buffers.data() + 8), 1);
  expectEval(sltk::q1AtSubcellCentres<3>(corner, 3, buffers.data(), buffers.data() + 27), 3);
}
