// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/LocalOffset.h"

#include "sltk/cloud/LocalSpacing.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/DistanceFunction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
/// A unit sphere: every point of the half z < 0, one point in `keep` of the half z > 0.
sltk::PointCloud<3> halfSparseSphere(int n, int keep)
{
  sltk::PointCloud<3> cloud;
  int upper = 0;
  for (const auto& p : sltk::sphereCloud(n).Points)
  {
    if (p[2] < 0.0 || upper++ % keep == 0)
    {
      cloud.Points.push_back(p);
    }
  }
  return cloud;
}

double quantile(std::vector<double> v, double q)
{
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1))];
}
} // namespace

TEST(LocalOffset, SparsityIsOneOnEvenSamplingAndTheSpacingRatioElsewhere)
{
  sltk::Context ctx;
  const sltk::PointCloud<3> even = sltk::sphereCloud(4000);
  const sltk::PointLocator<3> evenLocator(even);
  std::vector<double> rho;
  ASSERT_TRUE(sltk::sparsityFactors(evenLocator, 16, ctx, rho).isOk());
  EXPECT_LE(quantile(rho, 0.99), 1.2);
  // A quarter of the points on the upper half: its spacing is twice the lower half's.
  const sltk::PointCloud<3> uneven = halfSparseSphere(8000, 4);
  const sltk::PointLocator<3> unevenLocator(uneven);
  ASSERT_TRUE(sltk::sparsityFactors(unevenLocator, 16, ctx, rho).isOk());
  std::vector<double> upper;
  for (size_t k = 0; k < rho.size(); ++k)
  {
    if (uneven.Points[k][2] > 0.3)
    {
      upper.push_back(rho[k]);
    }
  }
  EXPECT_NEAR(quantile(upper, 0.5), 2.0, 0.25);
  EXPECT_LE(*std::max_element(rho.begin(), rho.end()), sltk::MaximumSparsity);
}

TEST(LocalOffset, ScaledDistanceDividesByTheNearestPointsSparsity)
{
  sltk::Context ctx;
  const sltk::PointCloud<3> cloud = halfSparseSphere(8000, 4);
  const sltk::PointLocator<3> locator(cloud);
  std::vector<double> rho;
  ASSERT_TRUE(sltk::sparsityFactors(locator, 16, ctx, rho).isOk());
  sltk::GridSpec<3> g;
  for (int a = 0; a < 3; ++a)
  {
    g.Dims[a] = 41;
    g.Origin[a] = -2.0;
    g.Spacing[a] = 0.1;
  }
  sltk::GridField<3, double> d, u;
  ASSERT_TRUE(sltk::distanceToCloud(locator, g, ctx, d).isOk());
  const double reach = 0.6;
  ASSERT_TRUE(sltk::locallyScaledDistance(d, locator, rho, reach, ctx, u).isOk());
  // Along the z axis: below, the dense half (rho 1); above, the sparse half (rho about 2).
  int checked = 0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = d.nodeIndex(k);
    std::array<double, 3> x{ g.coordinate(0, i[0]), g.coordinate(1, i[1]), g.coordinate(2, i[2]) };
    const double dist = d(i);
    if (dist >= reach || std::fabs(x[2]) < 0.5)
    {
      continue;
    }
    // Away from the equator the carried factor is the nearest point's (its neighbours' agree).
    const double expected = dist / rho[static_cast<size_t>(locator.nearest(x).Index)];
    EXPECT_NEAR(u(i), expected, 0.15 * expected) << "node " << k;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  // Beyond the reach: d / max(rho), still at least reach / max(rho).
  const double largest = *std::max_element(rho.begin(), rho.end());
  EXPECT_NEAR(u(std::array<sltk::Index, 3>{ 0, 0, 0 }), d(std::array<sltk::Index, 3>{ 0, 0, 0 }) / largest, 1e-12);
}
