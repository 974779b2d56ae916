// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudThinning.h"

#include "sltk/cloud/SyntheticClouds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

TEST(CloudThinning, KeepsTheSphere)
{
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(40000);
  const double cell = 0.1;
  sltk::PointCloud<3> thin;
  ASSERT_TRUE(sltk::thinCloud(cloud, cell, thin).isOk());
  EXPECT_LT(thin.size(), cloud.size() / 4);
  EXPECT_GT(thin.size(), 1000);
  double worst = 0.0;
  for (const auto& p : thin.Points)
  {
    worst = std::max(worst, std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0));
  }
  // A cell mean lies within the chord sag of the cell: about (sqrt(3) cell)^2 / 8 from the sphere.
  EXPECT_LT(worst, 3.0 * cell * cell / 8.0);
  const auto a = sltk::boundingBox(cloud);
  const auto b = sltk::boundingBox(thin);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(a.Min[k], b.Min[k], cell);
    EXPECT_NEAR(a.Max[k], b.Max[k], cell);
  }
}

TEST(CloudThinning, AveragesOverlappingNoisyCopies)
{
  // Two copies of a plane lattice, +-e off the plane: each cell holds one pair, averaged onto the plane.
  sltk::PointCloud<3> cloud;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      for (double e : { -0.01, 0.01 })
        cloud.Points.push_back({ 0.1 * i + 0.05, 0.1 * j + 0.05, 0.5 + e });
  sltk::PointCloud<3> thin;
  ASSERT_TRUE(sltk::thinCloud(cloud, 0.1, thin).isOk());
  ASSERT_EQ(thin.size(), 400);
  for (const auto& p : thin.Points)
  {
    EXPECT_NEAR(p[2], 0.5, 1e-12);
  }
}

TEST(CloudThinning, DeterministicAndOrderIndependent)
{
  sltk::PointCloud<2> cloud = sltk::circleCloud(3000);
  sltk::PointCloud<2> a, b, c;
  ASSERT_TRUE(sltk::thinCloud(cloud, 0.05, a).isOk());
  ASSERT_TRUE(sltk::thinCloud(cloud, 0.05, b).isOk());
  EXPECT_TRUE(a.Points == b.Points);
  std::reverse(cloud.Points.begin(), cloud.Points.end());
  ASSERT_TRUE(sltk::thinCloud(cloud, 0.05, c).isOk());
  ASSERT_EQ(a.size(), c.size()) << "output ordered by cell, not by input";
  for (size_t k = 0; k < a.Points.size(); ++k)
  {
    EXPECT_NEAR(a.Points[k][0], c.Points[k][0], 1e-12);
    EXPECT_NEAR(a.Points[k][1], c.Points[k][1], 1e-12);
  }
}

TEST(CloudThinning, RefusesBadCells)
{
  sltk::PointCloud<3> out;
  EXPECT_FALSE(sltk::thinCloud(sltk::sphereCloud(100), 0.0, out).isOk());
  EXPECT_FALSE(sltk::thinCloud(sltk::sphereCloud(100), -1.0, out).isOk());
  EXPECT_FALSE(sltk::thinCloud(sltk::sphereCloud(100), std::nan(""), out).isOk());
  EXPECT_FALSE(sltk::thinCloud(sltk::sphereCloud(100, 1e6), 1e-15, out).isOk()) << "cells not numberable";
}
