// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/interp/Q1.h"
#include "sltk/recon/CloudInitialData.h"
#include "sltk/recon/DistanceFunction.h"

#include "sltk/cloud/SyntheticClouds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <random>

namespace
{
using sltk::circleCloud;
using sltk::sphereCloud;
constexpr double Pi = 3.14159265358979323846;

/// Points every `step` along the segment from a to b.
void segment(sltk::PointCloud<2>& c, double ax, double ay, double bx, double by, double step)
{
  const double len = std::hypot(bx - ax, by - ay);
  const int n = static_cast<int>(std::ceil(len / step));
  for (int k = 0; k <= n; ++k)
  {
    const double t = static_cast<double>(k) / n;
    c.Points.push_back({ ax + t * (bx - ax), ay + t * (by - ay) });
  }
}

/// Reference marking: breadth-first flood fill from the boundary through nodes with d >= gamma.
std::vector<std::uint8_t> floodFill(const sltk::GridField<2, double>& d, double gamma)
{
  const auto& g = d.spec();
  std::vector<std::uint8_t> ext(static_cast<size_t>(g.nodeCount()), 0);
  std::deque<sltk::Index> queue;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = d.nodeIndex(k);
    if (i[0] == 0 || i[1] == 0 || i[0] == g.Dims[0] - 1 || i[1] == g.Dims[1] - 1)
    {
      ext[static_cast<size_t>(k)] = 1;
      queue.push_back(k);
    }
  }
  while (!queue.empty())
  {
    const sltk::Index k = queue.front();
    queue.pop_front();
    const auto i = d.nodeIndex(k);
    const sltk::Index steps[4][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } };
    for (const auto& s : steps)
    {
      const std::array<sltk::Index, 2> j{ i[0] + s[0], i[1] + s[1] };
      if (j[0] < 0 || j[1] < 0 || j[0] >= g.Dims[0] || j[1] >= g.Dims[1])
      {
        continue;
      }
      const sltk::Index m = j[0] + g.Dims[0] * j[1];
      if (!ext[static_cast<size_t>(m)] && d(j) >= gamma)
      {
        ext[static_cast<size_t>(m)] = 1;
        queue.push_back(m);
      }
    }
  }
  return ext;
}
} // namespace

TEST(InitialData, CircleCloudEnclosedAtGammaP)
{
  const auto cloud = circleCloud(64, 1.0);
  double hP = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(cloud, sltk::Context{}, hP).isOk());
  EXPECT_NEAR(hP, 0.0981, 1e-4);  // 4.5.3
  const double gammaP = 2.0 * hP; // K_P = 2 (4.5.2)
  const auto g = sltk::uniformBox<2>(81, -1.6, 1.6);
  const double dx = g.Spacing[0];
  sltk::GridField<2, double> d;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, d).isOk());
  sltk::GridField<2, double> phi0;
  sltk::InitialDataReport report;
  ASSERT_TRUE(sltk::cloudInitialData(d, gammaP, sltk::Context{}, phi0, {}, &report).isOk());
  EXPECT_EQ(report.BoundaryBelowThreshold, 0);
  EXPECT_GT(report.ExternalNodes, 0);
  // The zero level set along rays: between the arcs of radius gamma_P around the points
  // (sag gamma_P - sqrt(gamma_P^2 - (h/2)^2) between points) and the circle 1 + gamma_P.
  const double chord = 2.0 * std::sin(Pi / 64.0);
  const double sag = gammaP - std::sqrt(gammaP * gammaP - 0.25 * chord * chord);
  sltk::Q1Interpolator<2> q1(phi0);
  double worst = 0.0;
  for (int k = 0; k < 200; ++k)
  {
    const double t = 2.0 * Pi * (k + 0.37) / 200.0;
    double lo = 0.5;
    double hi = 1.58;
    for (int it = 0; it < 60; ++it)
    {
      const double r = 0.5 * (lo + hi);
      const double x[2] = { r * std::cos(t), r * std::sin(t) };
      (sltk::interpolate(q1, g, x) < 0.0 ? lo : hi) = r;
    }
    const double r0 = 0.5 * (lo + hi);
    EXPECT_GT(r0, 1.0 + gammaP - sag - 0.5 * dx) << t;
    EXPECT_LT(r0, 1.0 + gammaP + 0.5 * dx) << t;
    worst = std::max(worst, std::fabs(r0 - (1.0 + gammaP - 0.5 * sag)));
  }
  std::printf("circle: zero level at 1 + gamma_P within %.3f dx (sag %.3f dx)\n", worst / dx, sag / dx);
  // Sign and slope: negative inside (also in the unreachable centre), |grad phi0| ~ 1.
  int good = 0;
  int counted = 0;
  for (sltk::Index j = 1; j + 1 < g.Dims[1]; ++j)
  {
    for (sltk::Index i = 1; i + 1 < g.Dims[0]; ++i)
    {
      const double r = std::hypot(g.coordinate(0, i), g.coordinate(1, j));
      if (r < 1.0 + gammaP - sag - dx)
      {
        EXPECT_LT(phi0({ i, j }), 0.0);
      }
      if (r > 1.0 + gammaP + dx)
      {
        EXPECT_GT(phi0({ i, j }), 0.0);
      }
      if (r > 0.3 && r < 1.5)
      {
        const double gx = (phi0({ i + 1, j }) - phi0({ i - 1, j })) / (2.0 * dx);
        const double gy = (phi0({ i, j + 1 }) - phi0({ i, j - 1 })) / (2.0 * dx);
        good += std::fabs(std::hypot(gx, gy) - 1.0) < 0.1 ? 1 : 0;
        ++counted;
      }
    }
  }
  std::printf("circle: ||grad phi0| - 1| < 0.1 on %.1f%% of the annulus 0.3 < r < 1.5\n", 100.0 * good / counted);
  EXPECT_GT(good, 0.9 * counted);
  // The centre is internal: about -(1 + gamma_P) (the distance to the zero level).
  EXPECT_NEAR(phi0({ 40, 40 }), -(1.0 + gammaP), 2.0 * dx);
}

TEST(InitialData, MarkingFindsAxisAlignedPathsThroughABaffledBox)
{
  // A box open on the lower right with an inner baffle: its upper-right chamber is
  // reached only after two turns, i.e. in the second round of passes.
  sltk::PointCloud<2> cloud;
  const double h = 0.02;
  segment(cloud, -0.6, 0.6, 0.6, 0.6, h);
  segment(cloud, -0.6, -0.6, -0.6, 0.6, h);
  segment(cloud, -0.6, -0.6, 0.6, -0.6, h);
  segment(cloud, 0.6, -0.2, 0.6, 0.6, h);
  segment(cloud, -0.2, -0.1, 0.6, -0.1, h);
  const auto g = sltk::uniformBox<2>(101, -1.0, 1.0);
  sltk::GridField<2, double> d;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, d).isOk());
  const double gamma = 0.05;
  std::vector<std::uint8_t> ext;
  int rounds = 0;
  ASSERT_TRUE(sltk::markExternal(d, gamma, sltk::Context{}, ext, &rounds).isOk());
  EXPECT_EQ(ext, floodFill(d, gamma));
  EXPECT_GE(rounds, 3); // two rounds with changes, one to confirm
  // The upper-right chamber, e.g. (0.2, 0.25), is external; the walls are not.
  EXPECT_EQ(ext[static_cast<size_t>(60 + 101 * 62)], 1);
  EXPECT_EQ(ext[static_cast<size_t>(80 + 101 * 50)], 0); // on the wall x = 0.6
  sltk::GridField<2, double> phi0;
  ASSERT_TRUE(sltk::cloudInitialData(d, gamma, sltk::Context{}, phi0).isOk());
  EXPECT_GT(phi0({ 60, 62 }), 0.0);
  EXPECT_LT(phi0({ 80, 50 }), 0.0);
  // Threads give the same marking and phi0.
  sltk::ThreadPool pool(3);
  sltk::Context ctx;
  ctx.Executor = &pool;
  std::vector<std::uint8_t> ext2;
  ASSERT_TRUE(sltk::markExternal(d, gamma, ctx, ext2).isOk());
  EXPECT_EQ(ext, ext2);
  sltk::GridField<2, double> phi1;
  ASSERT_TRUE(sltk::cloudInitialData(d, gamma, ctx, phi1).isOk());
  EXPECT_EQ(phi0.storage(), phi1.storage());
  EXPECT_EQ(sltk::markExternal(d, 0.0, ctx, ext2).code(), sltk::StatusCode::InvalidArgument);
}

TEST(InitialData, RandomCloudsMarkingEqualsFloodFill)
{
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  for (int trial = 0; trial < 5; ++trial)
  {
    sltk::PointCloud<2> cloud;
    for (int k = 0; k < 300; ++k)
    {
      cloud.Points.push_back({ u(rng), u(rng) });
    }
    const auto g = sltk::uniformBox<2>(61, -1.0, 1.0);
    sltk::GridField<2, double> d;
    ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, d).isOk());
    std::vector<std::uint8_t> ext;
    ASSERT_TRUE(sltk::markExternal(d, 0.06, sltk::Context{}, ext).isOk());
    EXPECT_EQ(ext, floodFill(d, 0.06)) << trial;
  }
}

TEST(InitialData, SphereCloud3D)
{
  const auto cloud = sphereCloud(1500, 1.0);
  double hP = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(cloud, sltk::Context{}, hP).isOk());
  const double gammaP = 2.0 * hP;
  const auto g = sltk::uniformBox<3>(49, -1.6, 1.6);
  const double dx = g.Spacing[0];
  sltk::GridField<3, double> d;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, g, sltk::Context{}, d).isOk());
  sltk::GridField<3, double> phi0;
  ASSERT_TRUE(sltk::cloudInitialData(d, gammaP, sltk::Context{}, phi0).isOk());
  int good = 0;
  int counted = 0;
  double worst = 0.0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = phi0.nodeIndex(k);
    const double r = std::sqrt(
      std::pow(g.coordinate(0, i[0]), 2) + std::pow(g.coordinate(1, i[1]), 2) + std::pow(g.coordinate(2, i[2]), 2));
    if (r < 1.0 + gammaP - 2.0 * dx)
    {
      EXPECT_LT(phi0(i), 0.0);
    }
    if (r > 1.0 + gammaP + dx)
    {
      EXPECT_GT(phi0(i), 0.0);
    }
    // Close to the zero level phi0 ~ r - (1 + gamma_P).
    if (std::fabs(r - 1.0 - gammaP) < 2.0 * dx)
    {
      worst = std::max(worst, std::fabs(phi0(i) - (r - 1.0 - gammaP)));
    }
    bool interior = true;
    for (int a = 0; a < 3; ++a)
    {
      interior = interior && i[a] > 0 && i[a] + 1 < g.Dims[a];
    }
    if (interior && r > 0.4 && r < 1.5)
    {
      double g2 = 0.0;
      for (int a = 0; a < 3; ++a)
      {
        auto ip = i;
        auto im = i;
        ++ip[a];
        --im[a];
        g2 += std::pow((phi0(ip) - phi0(im)) / (2.0 * dx), 2);
      }
      good += std::fabs(std::sqrt(g2) - 1.0) < 0.1 ? 1 : 0;
      ++counted;
    }
  }
  std::printf("sphere: |phi0 - (r - 1 - gamma_P)| <= %.3f dx near the zero level; |grad| ok on %.1f%%\n", worst / dx,
    100.0 * good / counted);
  EXPECT_LT(worst, 0.5 * dx);
  EXPECT_GT(good, 0.85 * counted);
  // Identical with threads.
  sltk::ThreadPool pool(2);
  sltk::Context ctx;
  ctx.Executor = &pool;
  sltk::GridField<3, double> phiThreads;
  ASSERT_TRUE(sltk::cloudInitialData(d, gammaP, ctx, phiThreads).isOk());
  EXPECT_EQ(phi0.storage(), phiThreads.storage());
}

TEST(InitialData, EllipseSignedDistanceMatchesDenseSampling)
{
  const sltk::Ellipsoid<2> e{ { 0.1, -0.2 }, { 1.5, 0.6 } };
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  const int samples = 100000;
  for (int k = 0; k < 100; ++k)
  {
    double x[2] = { u(rng), u(rng) };
    if (k < 4) // on the axes, where the closest point is degenerate
    {
      x[0] = k < 2 ? 0.1 + 0.3 * k : 0.1;
      x[1] = k < 2 ? -0.2 : -0.2 + 0.25 * (k - 1);
    }
    double best = 1e300;
    for (int s = 0; s < samples; ++s)
    {
      const double t = 2.0 * Pi * s / samples;
      best = std::min(best, std::hypot(x[0] - 0.1 - 1.5 * std::cos(t), x[1] + 0.2 - 0.6 * std::sin(t)));
    }
    const double inside = std::pow((x[0] - 0.1) / 1.5, 2) + std::pow((x[1] + 0.2) / 0.6, 2) < 1.0;
    EXPECT_NEAR(sltk::signedDistance(e, x), inside ? -best : best, 1e-6) << x[0] << " " << x[1];
  }
  // The centre: minus the smaller semi-axis.
  const double c[2] = { 0.1, -0.2 };
  EXPECT_NEAR(sltk::signedDistance(e, c), -0.6, 1e-14);
}

TEST(InitialData, EllipsoidSignedDistanceMatchesDenseSampling)
{
  const sltk::Ellipsoid<3> e{ { 0.0, 0.0, 0.0 }, { 0.7, 1.2, 0.5 } };
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (int k = 0; k < 16; ++k)
  {
    double x[3] = { u(rng), u(rng), u(rng) };
    if (k == 0)
    {
      x[0] = 0.2; // on a coordinate plane, inside: the degenerate branch
      x[1] = 0.1;
      x[2] = 0.0;
    }
    double best = 1e300;
    const int n = 500;
    for (int a = 0; a <= n; ++a)
    {
      const double th = Pi * a / n;
      for (int b = 0; b < 2 * n; ++b)
      {
        const double ph = Pi * b / n;
        const double dxp = x[0] - 0.7 * std::sin(th) * std::cos(ph);
        const double dyp = x[1] - 1.2 * std::sin(th) * std::sin(ph);
        const double dzp = x[2] - 0.5 * std::cos(th);
        best = std::min(best, std::sqrt(dxp * dxp + dyp * dyp + dzp * dzp));
      }
    }
    const bool inside = std::pow(x[0] / 0.7, 2) + std::pow(x[1] / 1.2, 2) + std::pow(x[2] / 0.5, 2) < 1.0;
    const double got = sltk::signedDistance(e, x);
    // The sampling overestimates by at most ~ (pi * 1.2 / n)^2 / 8-ish; allow 1e-4.
    EXPECT_LE(std::fabs(got), best + 1e-12) << k;
    EXPECT_NEAR(got, inside ? -best : best, 1e-4) << k;
  }
}

TEST(InitialData, SphereAndEllipsoidGuessesEncloseTheCloud)
{
  const auto cloud = sphereCloud(400, 0.8);
  const auto sphere = sltk::boundingSphere(cloud, 0.1);
  EXPECT_NEAR(sphere.SemiAxes[0], 0.9, 0.01);
  const auto ellipsoid = sltk::boundingEllipsoid(cloud, 0.05);
  for (const auto& q : cloud.Points)
  {
    EXPECT_LT(sltk::signedDistance(sphere, q.data()), -0.099);
    EXPECT_LT(sltk::signedDistance(ellipsoid, q.data()), -0.049);
  }
  const auto g = sltk::uniformBox<3>(31, -1.5, 1.5);
  sltk::GridField<3, double> phi0;
  ASSERT_TRUE(sltk::ellipsoidLevelSet(sphere, g, sltk::Context{}, phi0).isOk());
  for (sltk::Index k = 0; k < g.nodeCount(); k += 7)
  {
    const auto i = phi0.nodeIndex(k);
    const double r = std::sqrt(std::pow(g.coordinate(0, i[0]) - sphere.Centre[0], 2) +
      std::pow(g.coordinate(1, i[1]) - sphere.Centre[1], 2) + std::pow(g.coordinate(2, i[2]) - sphere.Centre[2], 2));
    EXPECT_NEAR(phi0(i), r - sphere.SemiAxes[0], 1e-12);
  }
  sltk::Ellipsoid<3> bad = sphere;
  bad.SemiAxes[1] = 0.0;
  EXPECT_EQ(sltk::ellipsoidLevelSet(bad, g, sltk::Context{}, phi0).code(), sltk::StatusCode::InvalidArgument);
}
