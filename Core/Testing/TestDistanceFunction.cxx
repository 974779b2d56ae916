// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/FastSweeping.h"
#include "sltk/recon/DistanceFunction.h"

#include "sltk/cloud/SyntheticClouds.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

namespace
{
using sltk::circleCloud;
using sltk::sphereCloud;
constexpr double Pi = 3.14159265358979323846;

template <int D>
double bruteDistance(const sltk::PointCloud<D>& c, const double* x)
{
  double best = std::numeric_limits<double>::infinity();
  for (const auto& q : c.Points)
  {
    double d2 = 0.0;
    for (int a = 0; a < D; ++a)
    {
      d2 += (q[a] - x[a]) * (q[a] - x[a]);
    }
    best = std::min(best, std::sqrt(d2));
  }
  return best;
}

/// Max |d - exact| over all nodes, and the same on the 2^D corners of each point's cell.
template <int D>
void errors(const sltk::PointCloud<D>& cloud, const sltk::GridField<D, double>& d, double& swept, double& nearPoints)
{
  swept = 0.0;
  for (sltk::Index k = 0; k < d.spec().nodeCount(); ++k)
  {
    swept =
      std::max(swept, std::fabs(d(d.nodeIndex(k)) - bruteDistance(cloud, sltktest::nodeCoordinates(d, k).data())));
  }
  nearPoints = 0.0;
  for (const auto& q : cloud.Points)
  {
    const auto loc = sltk::locate(d.spec(), q.data());
    for (int c = 0; c < (1 << D); ++c)
    {
      std::array<sltk::Index, D> i;
      std::array<double, D> x;
      for (int a = 0; a < D; ++a)
      {
        i[a] = loc.Cell[a] + ((c >> a) & 1);
        x[a] = d.spec().coordinate(a, i[a]);
      }
      nearPoints = std::max(nearPoints, std::fabs(d(i) - bruteDistance(cloud, x.data())));
    }
  }
}
/// Fixed random data for the sweeps: about one node in `every` frozen at a value in
/// [0, 1), the others at infinity (a linear congruential sequence from `seed`).
template <int D>
std::vector<std::uint8_t> freezeRandomNodes(sltk::GridField<D, double>& u, std::uint64_t seed, std::uint64_t every)
{
  std::vector<std::uint8_t> frozen(static_cast<size_t>(u.spec().nodeCount()), 0);
  std::uint64_t state = seed;
  for (sltk::Index k = 0; k < u.spec().nodeCount(); ++k)
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    if ((state >> 33) % every == 0)
    {
      frozen[static_cast<size_t>(k)] = 1;
      u(u.nodeIndex(k)) = static_cast<double>((state >> 40) % 1000) * 1e-3;
    }
  }
  return frozen;
}

} // namespace

TEST(DistanceFunction, GodunovUpdateSolvesTheDiscreteEikonal)
{
  const double h[3] = { 1.0, 1.0, 1.0 };
  const double inf = std::numeric_limits<double>::infinity();
  const double one[3] = { 0.0, inf, inf };
  EXPECT_DOUBLE_EQ(sltk::godunovEikonal(one, h, 3), 1.0);
  const double two[2] = { 0.0, 0.0 };
  EXPECT_NEAR(sltk::godunovEikonal(two, h, 2), std::sqrt(0.5), 1e-15);
  const double three[3] = { 0.0, 0.0, 0.0 };
  EXPECT_NEAR(sltk::godunovEikonal(three, h, 3), std::sqrt(1.0 / 3.0), 1e-15);
  // A far neighbour does not enter: the one-axis solution is below it.
  const double far[2] = { 0.0, 5.0 };
  EXPECT_DOUBLE_EQ(sltk::godunovEikonal(far, h, 2), 1.0);
  // Anisotropic spacing: (u/2)^2 + (u/1)^2 = 1 with both axes active.
  const double h2[2] = { 2.0, 1.0 };
  EXPECT_NEAR(sltk::godunovEikonal(two, h2, 2), 1.0 / std::sqrt(1.25), 1e-15);
  const double none[2] = { inf, inf };
  EXPECT_EQ(sltk::godunovEikonal(none, h, 2), inf);
}

TEST(DistanceFunction, TheUniformSpacingsUpdateIsTheGeneralOneBitForBit)
{
  // Random neighbour values around one spacing (every case of one, two and
  // three axes entering), with ties, infinities and zeros, in 1, 2 and 3 axes
  // (no NaN: the sweeps never hold one, and the two differ there).
  const double inf = std::numeric_limits<double>::infinity();
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(0.0, 2.5);
  std::uniform_int_distribution<int> kind(0, 9);
  int differing = 0;
  int twoAxes = 0, threeAxes = 0;
  for (const double h : { 1.0, 0.037, 3.1e-4 })
  {
    const double spacings[3] = { h, h, h };
    for (int trial = 0; trial < 200000; ++trial)
    {
      double a[3];
      for (double& v : a)
      {
        const int k = kind(random);
        v = k == 0 ? inf : k == 1 ? 0.0 : value(random) * h;
      }
      if (kind(random) == 0)
      {
        a[2] = a[0]; // a tie
      }
      for (int dims = 1; dims <= 3; ++dims)
      {
        const double general = sltk::godunovEikonal(a, spacings, dims);
        const double uniform = sltk::godunovEikonalUniform(a, h, dims);
        differing += std::memcmp(&general, &uniform, sizeof(double)) != 0 ? 1 : 0;
        double sorted[3] = { a[0], a[1], a[2] };
        std::sort(sorted, sorted + 3);
        // Axes that enter the three-axis solution: the second when the one-axis
        // solution passes it, the third when the result passes that one too.
        twoAxes += dims == 3 && sorted[0] + h > sorted[1] ? 1 : 0;
        threeAxes += dims == 3 && sorted[0] + h > sorted[1] && general > sorted[2] ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(twoAxes, 1000);
  EXPECT_GT(threeAxes, 1000);
}

TEST(DistanceFunction, CircleCloudExactNearPointsAndSweptErrorSmall)
{
  const auto cloud = circleCloud(64, 1.0); // the thesis's circle (4.5.3)
  for (sltk::Index n : { 65, 129 })
  {
    const auto g = sltk::uniformBox<2>(n, -1.6, 1.6);
    sltk::GridField<2, double> d;
    sltk::DistanceReport report;
    ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, d, {}, &report).isOk());
    double swept = 0.0;
    double near = 0.0;
    errors(cloud, d, swept, near);
    EXPECT_LT(near, 1e-14) << n;
    EXPECT_GT(report.ExactNodes, 64 * 4);
    EXPECT_LE(report.SweepCycles, 4);
    const double dx = g.Spacing[0];
    EXPECT_LT(swept, 1.0 * dx) << "n " << n << " error " << swept / dx << " dx";
    // Godunov updates mixing two sources undercut the true distance a little
    // near the medial axis; elsewhere the swept values are upper bounds.
    double undercut = 0.0;
    for (sltk::Index k = 0; k < g.nodeCount(); ++k)
    {
      undercut = std::max(undercut, bruteDistance(cloud, sltktest::nodeCoordinates(d, k).data()) - d(d.nodeIndex(k)));
    }
    // Outside the circle (farther from the central medial point) the sweep is closer.
    double outside = 0.0;
    for (sltk::Index k = 0; k < g.nodeCount(); ++k)
    {
      const auto x = sltktest::nodeCoordinates(d, k);
      if (std::hypot(x[0], x[1]) > 1.0)
      {
        outside = std::max(outside, std::fabs(bruteDistance(cloud, x.data()) - d(d.nodeIndex(k))));
      }
    }
    EXPECT_LT(outside, 0.6 * dx) << outside / dx << " dx";
    std::printf("circle n=%lld: max error %.3f dx (undercut %.3f dx), outside the circle %.3f dx\n",
      static_cast<long long>(n), swept / dx, undercut / dx, outside / dx);
  }
}

TEST(DistanceFunction, SphereCloudSweptErrorSmall)
{
  const auto cloud = sphereCloud(800, 1.0);
  const auto g = sltk::uniformBox<3>(41, -1.5, 1.5);
  sltk::GridField<3, double> d;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, d).isOk());
  double swept = 0.0;
  double near = 0.0;
  errors(cloud, d, swept, near);
  EXPECT_LT(near, 1e-14);
  EXPECT_LT(swept, 1.0 * g.Spacing[0]) << swept / g.Spacing[0] << " dx";
  std::printf("sphere 41^3: max error %.3f dx\n", swept / g.Spacing[0]);
}

TEST(DistanceFunction, MonotoneAndLipschitz)
{
  const auto cloud = circleCloud(64, 1.0);
  const auto g = sltk::uniformBox<2>(81, -1.6, 1.6);
  sltk::GridField<2, double> d;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, d).isOk());
  const double dx = g.Spacing[0];
  // Along the positive x axis, outwards from the cloud point (1, 0): increasing.
  const sltk::Index j = 40;
  const sltk::Index i0 = static_cast<sltk::Index>(std::ceil((1.0 + 1.6) / dx));
  for (sltk::Index i = i0; i + 1 < g.Dims[0]; ++i)
  {
    EXPECT_LT(d({ i, j }), d({ i + 1, j }));
  }
  // Discrete 1-Lipschitz along the axes, nonnegative everywhere.
  for (sltk::Index j2 = 0; j2 < g.Dims[1]; ++j2)
  {
    for (sltk::Index i = 0; i < g.Dims[0]; ++i)
    {
      EXPECT_GE(d({ i, j2 }), 0.0);
      if (i + 1 < g.Dims[0])
      {
        EXPECT_LE(std::fabs(d({ i + 1, j2 }) - d({ i, j2 })), dx * (1.0 + 1e-12));
      }
      if (j2 + 1 < g.Dims[1])
      {
        EXPECT_LE(std::fabs(d({ i, j2 + 1 }) - d({ i, j2 })), dx * (1.0 + 1e-12));
      }
    }
  }
}

TEST(DistanceFunction, IdenticalWithThreadsAndGhostsFilled)
{
  const auto cloud = sphereCloud(500, 0.8);
  const auto g = sltk::uniformBox<3>(33, -1.2, 1.2);
  sltk::GridField<3, double> serial;
  sltk::GridField<3, double> threaded;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, serial).isOk());
  sltk::ThreadPool pool(3);
  sltk::Context ctx;
  ctx.Executor = &pool;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, g, ctx, threaded).isOk());
  EXPECT_EQ(serial.storage(), threaded.storage());
  EXPECT_EQ(serial.ghost(), 2);
  // Ghosts are the linear extrapolation of the boundary values.
  EXPECT_DOUBLE_EQ(serial({ -1, 5, 5 }), 2.0 * serial({ 0, 5, 5 }) - serial({ 1, 5, 5 }));
}

TEST(DistanceFunction, PointsOutsideTheGridAndBadInput)
{
  sltk::PointCloud<2> cloud;
  cloud.Points.push_back({ 3.0, 0.0 }); // outside [-1, 1]^2
  const auto g = sltk::uniformBox<2>(21, -1.0, 1.0);
  sltk::GridField<2, double> d;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, d).isOk());
  // The clipped box gives exact values on the right boundary column.
  EXPECT_NEAR(d({ 20, 10 }), 2.0, 1e-14);
  EXPECT_NEAR(d({ 20, 11 }), std::sqrt(4.0 + 0.01), 1e-14);
  EXPECT_NEAR(d({ 19, 9 }), std::sqrt(2.1 * 2.1 + 0.01), 1e-14);
  // Beyond the box: swept along the boundary column only, an upper bound.
  EXPECT_GT(d({ 20, 0 }), std::sqrt(5.0) - 1e-12);
  EXPECT_NEAR(d({ 20, 0 }), std::sqrt(4.01) + 0.9, 1e-12);
  sltk::PointCloud<2> empty;
  EXPECT_EQ(sltk::distanceToCloud(empty, g, sltk::Context{}, d).code(), sltk::StatusCode::InvalidArgument);
  cloud.Points.push_back({ std::nan(""), 0.0 });
  EXPECT_EQ(sltk::distanceToCloud(cloud, g, sltk::Context{}, d).code(), sltk::StatusCode::InvalidArgument);
}

TEST(DistanceFunction, LockedSweepingEqualsPlainGaussSeidel)
{
  // Random data on an anisotropic grid: the locks must not change a single bit.
  sltk::GridSpec<2> g;
  g.Dims = { 37, 29 };
  g.Spacing = { 0.1, 0.07 };
  sltk::GridField<2, double> u(g, 1, std::numeric_limits<double>::infinity());
  const std::vector<std::uint8_t> frozen = freezeRandomNodes(u, 12345, 23);
  sltk::GridField<2, double> plain = u;
  sltk::FastSweepingOptions options;
  options.Tolerance = 0.0;
  sltk::FastSweepingReport report;
  ASSERT_TRUE(sltk::fastSweep(u, frozen, sltk::Context{}, options, &report).isOk());
  EXPECT_TRUE(report.Converged);
  const double inf = std::numeric_limits<double>::infinity();
  bool changed = true;
  int cycles = 0;
  while (changed)
  {
    changed = false;
    ++cycles;
    for (int order = 0; order < 4; ++order)
    {
      for (sltk::Index jj = 0; jj < g.Dims[1]; ++jj)
      {
        const sltk::Index j = (order & 2) ? g.Dims[1] - 1 - jj : jj;
        for (sltk::Index ii = 0; ii < g.Dims[0]; ++ii)
        {
          const sltk::Index i = (order & 1) ? g.Dims[0] - 1 - ii : ii;
          if (frozen[static_cast<size_t>(i + g.Dims[0] * j)])
          {
            continue;
          }
          const double ax = std::min(i > 0 ? plain({ i - 1, j }) : inf, i + 1 < g.Dims[0] ? plain({ i + 1, j }) : inf);
          const double ay = std::min(j > 0 ? plain({ i, j - 1 }) : inf, j + 1 < g.Dims[1] ? plain({ i, j + 1 }) : inf);
          const double a[2] = { ax, ay };
          const double v = sltk::godunovEikonal(a, g.Spacing.data(), 2);
          if (v < plain({ i, j }))
          {
            plain({ i, j }) = v;
            changed = true;
          }
        }
      }
    }
  }
  EXPECT_EQ(u.storage(), plain.storage());
  EXPECT_EQ(report.Cycles, cycles);
}

TEST(DistanceFunction, TwoThreadSweepsEqualTheSerialOnesBitForBit)
{
  // Random data on an anisotropic 3D grid: the pipelined planes (two threads) must
  // give the serial Gauss-Seidel's values and cycle count, in every sweep order.
  sltk::GridSpec<3> g;
  g.Dims = { 23, 17, 29 };
  g.Spacing = { 0.1, 0.07, 0.13 };
  sltk::GridField<3, double> serial(g, 1, std::numeric_limits<double>::infinity());
  const std::vector<std::uint8_t> frozen = freezeRandomNodes(serial, 987654321, 97);
  sltk::GridField<3, double> threaded = serial;
  sltk::FastSweepingOptions options;
  options.Tolerance = 0.0;
  sltk::FastSweepingReport one, two;
  ASSERT_TRUE(sltk::fastSweep(serial, frozen, sltk::Context{}, options, &one).isOk());
  for (int threads : { 2, 3 })
  {
    sltk::ThreadPool pool(threads);
    sltk::Context ctx;
    ctx.Executor = &pool;
    sltk::GridField<3, double> u = threaded;
    ASSERT_TRUE(sltk::fastSweep(u, frozen, ctx, options, &two).isOk());
    EXPECT_EQ(u.storage(), serial.storage()) << threads;
    EXPECT_EQ(two.Cycles, one.Cycles) << threads;
    EXPECT_GT(one.Cycles, 1);
  }
}
