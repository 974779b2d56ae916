// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudOutliers.h"

#include "sltk/cloud/SyntheticClouds.h"

#include <gtest/gtest.h>

TEST(CloudOutliers, RemovesTheFarPointOfASphere)
{
  sltk::PointCloud<3> cloud = sltk::sphereCloud(2562);
  cloud.Points.insert(cloud.Points.begin() + 1000, { 3.0, 0.5, -0.2 });
  sltk::Context ctx;
  sltk::PointCloud<3> kept;
  sltk::OutlierReport report;
  ASSERT_TRUE(sltk::removeOutliers(cloud, {}, ctx, kept, report).isOk());
  EXPECT_EQ(report.Removed, 1);
  ASSERT_EQ(kept.size(), 2562);
  EXPECT_TRUE(kept.Points == sltk::sphereCloud(2562).Points) << "the others kept, in their order";
  EXPECT_GT(report.Threshold, report.MeanNeighbourDistance);
}

TEST(CloudOutliers, EvenCloudLosesNothingAndIsDeterministic)
{
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(5000);
  sltk::ThreadPool pool(2);
  sltk::Context serial, threaded;
  threaded.Executor = &pool;
  sltk::PointCloud<3> a, b;
  sltk::OutlierReport ra, rb;
  ASSERT_TRUE(sltk::removeOutliers(cloud, {}, serial, a, ra).isOk());
  ASSERT_TRUE(sltk::removeOutliers(cloud, {}, threaded, b, rb).isOk());
  EXPECT_EQ(ra.Removed, 0);
  EXPECT_TRUE(a.Points == b.Points);
  EXPECT_EQ(ra.Threshold, rb.Threshold);
}

TEST(CloudOutliers, InPlaceAndSmallClouds)
{
  sltk::PointCloud<2> cloud = sltk::circleCloud(200);
  cloud.Points.push_back({ 0.0, 5.0 });
  sltk::Context ctx;
  sltk::OutlierReport report;
  ASSERT_TRUE(sltk::removeOutliers(cloud, {}, ctx, cloud, report).isOk());
  EXPECT_EQ(report.Removed, 1);
  EXPECT_EQ(cloud.size(), 200);
  const sltk::PointCloud<2> tiny = sltk::circleCloud(5);
  sltk::PointCloud<2> out;
  ASSERT_TRUE(sltk::removeOutliers(tiny, {}, ctx, out, report).isOk());
  EXPECT_EQ(out.size(), 5) << "k >= n: nothing to compare with, copied";
}

TEST(CloudOutliers, RefusesBadOptions)
{
  sltk::Context ctx;
  sltk::PointCloud<3> out;
  sltk::OutlierReport report;
  EXPECT_FALSE(sltk::removeOutliers(sltk::sphereCloud(100), { 0, 3.0 }, ctx, out, report).isOk());
  EXPECT_FALSE(sltk::removeOutliers(sltk::sphereCloud(100), { 8, -1.0 }, ctx, out, report).isOk());
}
