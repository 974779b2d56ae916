// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
template <int D>
sltk::GridSpec<D> unitGrid(sltk::Index n, sltk::Boundary b)
{
  sltk::GridSpec<D> g;
  for (int a = 0; a < D; ++a)
  {
    g.Dims[a] = n + a; // different sizes per axis catch stride mix-ups
    g.Origin[a] = 0.5 * a;
    g.Spacing[a] = 0.1 * (a + 1);
    g.Bounds[a] = b;
  }
  return g;
}
} // namespace

TEST(GridField, OffsetsAreXFastest)
{
  sltk::GridField<3> f(unitGrid<3>(4, sltk::Boundary::Extrapolate), 2);
  EXPECT_EQ(f.strides()[0], 1);
  EXPECT_EQ(f.strides()[1], 4 + 4);
  EXPECT_EQ(f.strides()[2], (4 + 4) * (5 + 4));
  EXPECT_EQ(f.offset({ 1, 0, 0 }) - f.offset({ 0, 0, 0 }), 1);
  auto i = f.nodeIndex(1 + 2 * 4 + 3 * 4 * 5);
  EXPECT_EQ(i[0], 1);
  EXPECT_EQ(i[1], 2);
  EXPECT_EQ(i[2], 3);
}

TEST(GridField, ExtrapolationReproducesLinearFunctionsIncludingCorners)
{
  auto spec = unitGrid<3>(5, sltk::Boundary::Extrapolate);
  sltk::GridField<3> f(spec, 2);
  auto lin = [&](sltk::Index i, sltk::Index j, sltk::Index k)
  { return 1.0 + 2.0 * spec.coordinate(0, i) - 3.0 * spec.coordinate(1, j) + 0.5 * spec.coordinate(2, k); };
  for (sltk::Index n = 0; n < spec.nodeCount(); ++n)
  {
    auto i = f.nodeIndex(n);
    f(i) = lin(i[0], i[1], i[2]);
  }
  f.fillGhosts();
  for (sltk::Index k = -2; k < spec.Dims[2] + 2; ++k)
    for (sltk::Index j = -2; j < spec.Dims[1] + 2; ++j)
      for (sltk::Index i = -2; i < spec.Dims[0] + 2; ++i)
      {
        ASSERT_NEAR(f({ i, j, k }), lin(i, j, k), 1e-12) << i << " " << j << " " << k;
      }
}

TEST(GridField, PeriodicGhostsWrap)
{
  auto spec = unitGrid<2>(6, sltk::Boundary::Periodic);
  sltk::GridField<2> f(spec, 2);
  for (sltk::Index n = 0; n < spec.nodeCount(); ++n)
  {
    auto i = f.nodeIndex(n);
    f(i) = double(i[0] + 100 * i[1]);
  }
  f.fillGhosts();
  auto wrap = [](sltk::Index i, sltk::Index n) { return ((i % n) + n) % n; };
  for (sltk::Index j = -2; j < spec.Dims[1] + 2; ++j)
    for (sltk::Index i = -2; i < spec.Dims[0] + 2; ++i)
    {
      ASSERT_EQ(f({ i, j }), double(wrap(i, 6) + 100 * wrap(j, 7))) << i << " " << j;
    }
}

TEST(GridField, MixedBoundariesPerAxis)
{
  auto spec = unitGrid<2>(5, sltk::Boundary::Periodic);
  spec.Bounds[1] = sltk::Boundary::Extrapolate;
  sltk::GridField<2> f(spec, 1);
  for (sltk::Index n = 0; n < spec.nodeCount(); ++n)
  {
    auto i = f.nodeIndex(n);
    f(i) = double(i[0] % 5) + 10.0 * double(i[1]);
  }
  f.fillGhosts();
  EXPECT_EQ(f({ -1, 2 }), 4.0 + 20.0);
  EXPECT_EQ(f({ 5, 2 }), 0.0 + 20.0);
  EXPECT_EQ(f({ 1, -1 }), 1.0 - 10.0);
  EXPECT_EQ(f({ 1, 6 }), 1.0 + 60.0);
  EXPECT_EQ(f({ -1, -1 }), 4.0 - 10.0);
}

TEST(GridField, GhostsFilledOnThreadsAsOnOne)
{
  // Mixed boundaries and a non-linear function, so that the corners depend on
  // the axes' order; the lines of each axis in chunks of 16 on two threads.
  auto spec = unitGrid<3>(20, sltk::Boundary::Extrapolate);
  spec.Bounds[1] = sltk::Boundary::Periodic;
  sltk::GridField<3> serial(spec, 2);
  for (sltk::Index n = 0; n < spec.nodeCount(); ++n)
  {
    const auto i = serial.nodeIndex(n);
    serial(i) = std::sin(0.3 * double(i[0])) * double(i[1] * i[1]) + 0.01 * double(i[2] * i[2] * i[2]);
  }
  sltk::GridField<3> threaded = serial;
  serial.fillGhosts();
  sltk::ThreadPool pool(2);
  sltk::Context ctx;
  ctx.Executor = &pool;
  threaded.fillGhosts(ctx);
  EXPECT_EQ(serial.storage(), threaded.storage());
  threaded.fillGhosts(sltk::Context{});
  EXPECT_EQ(serial.storage(), threaded.storage());
}
