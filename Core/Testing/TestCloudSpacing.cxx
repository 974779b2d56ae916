// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudSpacing.h"

#include "sltk/cloud/SyntheticClouds.h"

#include <gtest/gtest.h>

#include <cmath>

TEST(CloudSpacing, EvenCircleGivesTheChordLength)
{
  sltk::Context ctx;
  double h = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(sltk::circleCloud(64), ctx, h).isOk());
  EXPECT_NEAR(h, 2.0 * std::sin(M_PI / 64), 1e-12); // 0.0981, the thesis circle's h_P (4.5.3)
}

TEST(CloudSpacing, LatticeIn3D)
{
  sltk::PointCloud<3> c;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 3; ++k)
        c.Points.push_back({ 0.1 * i, 0.1 * j, 0.1 * k });
  sltk::Context ctx;
  double h = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(c, ctx, h).isOk());
  EXPECT_NEAR(h, 0.1, 1e-12);
}

TEST(CloudSpacing, SameResultSerialAndThreaded)
{
  sltk::PointCloud<3> c;
  for (int k = 0; k < 20000; ++k)
  {
    const double z = -1.0 + 2.0 * (k + 0.5) / 20000;
    const double r = std::sqrt(1.0 - z * z);
    c.Points.push_back({ r * std::cos(2.4 * k), r * std::sin(2.4 * k), z });
  }
  sltk::ThreadPool pool(2);
  sltk::Context serial, threaded;
  threaded.Executor = &pool;
  double a = 0.0, b = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(c, serial, a).isOk());
  ASSERT_TRUE(sltk::cloudSpacing(c, threaded, b).isOk());
  EXPECT_EQ(a, b);
  EXPECT_GT(a, 0.0);
}

TEST(CloudSpacing, DuplicatesOnlyIsAnError)
{
  sltk::PointCloud<2> c;
  c.Points.assign(50, { 1.0, 1.0 });
  sltk::Context ctx;
  double h = 1.0;
  auto s = sltk::cloudSpacing(c, ctx, h);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_NE(s.message().find("duplicate"), std::string::npos);
}
