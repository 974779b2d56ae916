// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PointCloud.h"

#include "sltk/cloud/LocalFrame.h"

#include "sltk/cloud/SyntheticClouds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
std::string messageOf(const sltk::PointCloud<3>& c)
{
  return sltk::validateCloud(c).message();
}
} // namespace

TEST(PointCloud, SphereIsValidAndBoxed)
{
  auto c = sltk::sphereCloud(500);
  EXPECT_TRUE(sltk::validateCloud(c).isOk()) << messageOf(c);
  auto box = sltk::boundingBox(c);
  EXPECT_NEAR(box.Min[2], -1.0, 0.01);
  EXPECT_NEAR(box.Max[0], 1.0, 0.01);
}

TEST(PointCloud, EmptyCloudIsRefused)
{
  sltk::PointCloud<3> c;
  EXPECT_EQ(sltk::validateCloud(c).code(), sltk::StatusCode::InvalidArgument);
  EXPECT_NE(messageOf(c).find("empty"), std::string::npos);
}

TEST(PointCloud, TooFewPointsAreRefused)
{
  sltk::PointCloud<3> c;
  c.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  EXPECT_NE(messageOf(c).find("at least 4"), std::string::npos) << messageOf(c);
}

TEST(PointCloud, NonFiniteCoordinatesAreNamed)
{
  auto c = sltk::sphereCloud(100);
  c.Points[42][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(messageOf(c).find("point 42"), std::string::npos) << messageOf(c);
  c = sltk::sphereCloud(100);
  c.Points[7][2] = std::numeric_limits<double>::infinity();
  EXPECT_NE(messageOf(c).find("point 7"), std::string::npos) << messageOf(c);
}

TEST(PointCloud, CoincidentPointsAreRefused)
{
  sltk::PointCloud<3> c;
  c.Points.assign(10, { 1.5, 2.5, 3.5 });
  EXPECT_NE(messageOf(c).find("coincide"), std::string::npos) << messageOf(c);
}

TEST(PointCloud, CoplanarPointsAreRefusedIn3D)
{
  sltk::PointCloud<3> c;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      c.Points.push_back({ double(i), double(j), 0.5 * i - 0.25 * j + 3.0 });
  EXPECT_NE(messageOf(c).find("plane"), std::string::npos) << messageOf(c);
  c.Points.push_back({ 0.0, 0.0, 10.0 });
  EXPECT_TRUE(sltk::validateCloud(c).isOk());
}

TEST(PointCloud, CollinearPointsAreRefusedIn2D)
{
  sltk::PointCloud<2> c;
  for (int i = 0; i < 10; ++i)
    c.Points.push_back({ double(i), 2.0 * i + 1.0 });
  EXPECT_NE(sltk::validateCloud(c).message().find("line"), std::string::npos);
  c.Points.push_back({ 0.0, 5.0 });
  EXPECT_TRUE(sltk::validateCloud(c).isOk());
}

TEST(PointCloud, HugeOffsetsAreRefusedWithAFix)
{
  auto c = sltk::sphereCloud(100, 1e-3, { 1e9, 1e9, 1e9 });
  EXPECT_NE(messageOf(c).find("translate"), std::string::npos) << messageOf(c);
  auto ok = sltk::sphereCloud(100, 1.0, { 1e6, 1e6, 1e6 }); // 1e-6 relative extent is fine
  EXPECT_TRUE(sltk::validateCloud(ok).isOk()) << messageOf(ok);
}

TEST(PointCloud, DuplicatePointsAreAccepted)
{
  auto c = sltk::sphereCloud(100);
  auto copy = c.Points;
  c.Points.insert(c.Points.end(), copy.begin(), copy.end());
  EXPECT_TRUE(sltk::validateCloud(c).isOk());
}

TEST(LocalFrame, CloudsNearTheOriginAreNotMoved)
{
  // Within 16 extents: the thesis's and the shared clouds (at most 3) are reconstructed as given.
  for (const double offset : { 0.0, 3.0, -20.0, 31.0 })
  {
    const auto c = sltk::sphereCloud(200, 1.0, { offset, 0.5, -0.25 });
    EXPECT_TRUE(sltk::isZeroShift(sltk::localFrameShift(sltk::boundingBox(c)))) << offset;
  }
}

TEST(LocalFrame, SurveyCoordinatesMoveExactly)
{
  // UTM-like: x, y near 1e6-1e7 with an extent of a few metres; z stays (a height within 16 extents).
  auto c = sltk::sphereCloud(500, 2.5, { 6.5e6 + 0.3, 4.2e5 - 0.7, 12.0 });
  const auto shift = sltk::localFrameShift(sltk::boundingBox(c));
  EXPECT_EQ(shift[2], 0.0);
  EXPECT_NEAR(shift[0], 6.5e6, 8.0); // the centre, to a multiple of the power of two >= the extent (8)
  EXPECT_NEAR(shift[1], 4.2e5, 8.0);
  EXPECT_EQ(std::fmod(shift[0], 8.0), 0.0);
  const auto user = c;
  sltk::moveToLocalFrame(c, shift);
  for (size_t k = 0; k < c.Points.size(); ++k)
  {
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_LT(std::fabs(c.Points[k][a]), 16.0);
      EXPECT_EQ(c.Points[k][a] + shift[a], user.Points[k][a]) << "moved and back is exact";
    }
  }
  EXPECT_TRUE(sltk::validateCloud(c).isOk());
}

TEST(LocalFrame, PositionsKeepTheCloudsDetail)
{
  // Near the origin a stream's 6 digits; at 1e7 with an extent of 100 m, the millimetre.
  EXPECT_EQ(sltk::positionDigits(1.5, 3.0), 6);
  EXPECT_EQ(sltk::positionDigits(1.0e7 + 12.345, 100.0), 11);
  EXPECT_EQ(sltk::positionDigits(1e300, 1e-300), 17);
  EXPECT_EQ(sltk::positionDigits(1.0, 0.0), 6) << "no extent: the default";
  const double near[3] = { 0.125, -1.5, 2.0 };
  EXPECT_EQ(sltk::formatPosition(near, 3, 4.0), "(0.125, -1.5, 2)");
  const double far[2] = { 10000012.345, 4200000.5 };
  EXPECT_EQ(sltk::formatPosition(far, 2, 100.0), "(10000012.345, 4200000.5)");
}
