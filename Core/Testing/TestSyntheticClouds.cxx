// SPDX-License-Identifier: BSD-3-Clause
// The synthetic clouds of the thesis's tests (4.5.3, 4.5.4), their exact signed
// distances and the quadratures of the exact shapes.
#include "sltk/cloud/SyntheticClouds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
constexpr double Pi = 3.14159265358979323846;

template <int D>
double weightSum(const sltk::ShapeQuadrature<D>& q)
{
  double sum = 0.0;
  for (const auto& node : q)
  {
    sum += node.second;
  }
  return sum;
}
} // namespace

TEST(SyntheticClouds, CircleAndSphereDistances)
{
  EXPECT_DOUBLE_EQ(sltk::circleSdf({ 0.0, 0.0 }), -1.0);
  EXPECT_DOUBLE_EQ(sltk::circleSdf({ 3.0, 4.0 }), 4.0);
  EXPECT_DOUBLE_EQ(sltk::circleSdf({ 2.0, 1.0 }, 0.5, { 2.0, 0.0 }), 0.5);
  EXPECT_DOUBLE_EQ(sltk::sphereSdf({ 0.0, 0.0, 0.0 }), -1.0);
  EXPECT_DOUBLE_EQ(sltk::sphereSdf({ 1.0, 2.0, 5.0 }, 2.0, { 1.0, 2.0, 2.0 }), 1.0);
  for (const auto& p : sltk::circleCloud(64).Points)
  {
    EXPECT_NEAR(sltk::circleSdf(p), 0.0, 1e-15);
  }
}

TEST(SyntheticClouds, RotatedSquareIsTheThesisSquare)
{
  // 4.5.3: 24 points, corners included, spacing sqrt(2) / 6 along the sides.
  const auto cloud = sltk::rotatedSquareCloud(6);
  ASSERT_EQ(cloud.size(), 24);
  EXPECT_DOUBLE_EQ(cloud.Points[0][0], 1.0);
  EXPECT_DOUBLE_EQ(cloud.Points[6][1], 1.0);
  for (const auto& p : cloud.Points)
  {
    EXPECT_NEAR(std::fabs(p[0]) + std::fabs(p[1]), 1.0, 1e-15);
    EXPECT_NEAR(sltk::rotatedSquareSdf(p), 0.0, 1e-15);
  }
  EXPECT_NEAR(std::hypot(cloud.Points[1][0] - cloud.Points[0][0], cloud.Points[1][1] - cloud.Points[0][1]),
    std::sqrt(2.0) / 6.0, 1e-15);
  EXPECT_NEAR(sltk::rotatedSquareSdf({ 0.0, 0.0 }), -1.0 / std::sqrt(2.0), 1e-15); // centre to side
  EXPECT_NEAR(sltk::rotatedSquareSdf({ 2.0, 0.0 }), 1.0, 1e-15);                   // nearest point: the corner
  EXPECT_NEAR(sltk::rotatedSquareSdf({ 1.0, 1.0 }), 1.0 / std::sqrt(2.0), 1e-15);  // nearest point: mid-side
}

TEST(SyntheticClouds, HeartIsEvenlySpacedOnTheHeartCurve)
{
  // 24 points from the cusp (0, 5), through the point (0, -17), at equal arc
  // length: neighbours about L / 24 apart (chords of equal arcs), mirror
  // images in x = 0.
  const auto cloud = sltk::heartCloud(24);
  ASSERT_EQ(cloud.size(), 24);
  EXPECT_NEAR(cloud.Points[0][0], 0.0, 1e-12);
  EXPECT_NEAR(cloud.Points[0][1], 5.0, 1e-12);
  EXPECT_NEAR(cloud.Points[12][0], 0.0, 1e-9);
  EXPECT_NEAR(cloud.Points[12][1], -17.0, 1e-9);
  double smallest = 1e300, largest = 0.0;
  for (int k = 0; k < 24; ++k)
  {
    const auto& p = cloud.Points[static_cast<size_t>(k)];
    const auto& q = cloud.Points[static_cast<size_t>((k + 1) % 24)];
    const double chord = std::hypot(q[0] - p[0], q[1] - p[1]);
    smallest = std::min(smallest, chord);
    largest = std::max(largest, chord);
    const auto& mirror = cloud.Points[static_cast<size_t>((24 - k) % 24)];
    EXPECT_NEAR(p[0], -mirror[0], 1e-9);
    EXPECT_NEAR(p[1], mirror[1], 1e-9);
  }
  EXPECT_GT(smallest, 0.75 * largest); // chords of equal arcs: shorter only where the curve bends
  EXPECT_GT(largest, 3.5);
  EXPECT_LT(largest, 4.26); // the curve is 102.17 long: arcs of 4.257, chords shorter
}

TEST(SyntheticClouds, PolygonCloudCutsEachSide)
{
  // A 2 x 1 rectangle every 0.25: 8 + 4 + 8 + 4 points.
  const auto cloud = sltk::polygonCloud({ { 0.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 1.0 }, { 0.0, 1.0 } }, 0.25);
  ASSERT_EQ(cloud.size(), 24);
  EXPECT_DOUBLE_EQ(cloud.Points[8][0], 2.0);
  EXPECT_DOUBLE_EQ(cloud.Points[8][1], 0.0);
  // A side that is not a multiple of h gets ceil(L / h) parts.
  EXPECT_EQ(sltk::polygonCloud({ { 0.0, 0.0 }, { 1.0, 0.0 } }, 0.3).size(), 8);
}

TEST(SyntheticClouds, IcosphereHasTheThesisCount)
{
  EXPECT_EQ(sltk::icosphereCloud(0).size(), 12);
  const auto cloud = sltk::icosphereCloud(4);
  ASSERT_EQ(cloud.size(), 2562); // 4.5.4: 10 * 4^4 + 2
  for (const auto& p : cloud.Points)
  {
    EXPECT_NEAR(sltk::sphereSdf(p), 0.0, 1e-15);
  }
}

TEST(SyntheticClouds, CubeSpheresCloudLiesOnItsSurface)
{
  sltk::CubeSpheres shape;
  const auto cloud = shape.cloud(2346);
  EXPECT_EQ(cloud.size(), 2346); // 4.5.4
  const auto box = sltk::boundingBox(cloud);
  double half = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    half = std::max(half, 0.5 * box.extent(a));
    EXPECT_NEAR(box.Min[a] + box.Max[a], 0.0, 1e-12); // centred
  }
  EXPECT_NEAR(half, 1.0, 1e-12); // unit box
  for (const auto& p : cloud.Points)
  {
    EXPECT_NEAR(shape.sdf(p), 0.0, 1e-12);
  }
  EXPECT_LT(shape.sdf({ 0.0, 0.0, 0.0 }), -0.3); // inside the cube
  EXPECT_GT(shape.sdf({ 3.0, 3.0, 3.0 }), 3.0);  // far outside
}

TEST(SyntheticClouds, GaussianNoiseIsReproducible)
{
  const auto clean = sltk::circleCloud(64);
  const auto a = sltk::withGaussianNoise(clean, 0.1, 2024);
  const auto b = sltk::withGaussianNoise(clean, 0.1, 2024);
  const auto c = sltk::withGaussianNoise(clean, 0.1, 7);
  EXPECT_EQ(a.Points, b.Points);
  EXPECT_NE(a.Points, c.Points);
  double sum2 = 0.0;
  for (size_t k = 0; k < clean.Points.size(); ++k)
  {
    for (int d = 0; d < 2; ++d)
    {
      sum2 += std::pow(a.Points[k][d] - clean.Points[k][d], 2);
    }
  }
  EXPECT_NEAR(std::sqrt(sum2 / 128.0), 0.1, 0.03); // sample deviation of 128 draws
  EXPECT_EQ(sltk::withGaussianNoise(clean, 0.0, 1).Points, clean.Points);
}

TEST(SyntheticClouds, QuadraturesAndShapeEnergy)
{
  EXPECT_NEAR(weightSum<2>(sltk::circleQuadrature(1000)), 2.0 * Pi, 1e-12);
  EXPECT_NEAR(weightSum<2>(sltk::rotatedSquareQuadrature(100)), 4.0 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(weightSum<3>(sltk::sphereQuadrature(1000)), 4.0 * Pi, 1e-12);
  // 4.5.3: E_2 of the unit circle for its 64 points is "about 7.10e-2".
  EXPECT_NEAR(sltk::shapeEnergy<2>(sltk::circleCloud(64), sltk::circleQuadrature(64000)), 7.10e-2, 5e-4);
  // Every point of the icosphere is at distance 1 from the centre: E_2 = sqrt(1 * 1^2).
  EXPECT_DOUBLE_EQ(sltk::shapeEnergy<3>(sltk::icosphereCloud(1), { { { 0.0, 0.0, 0.0 }, 1.0 } }), 1.0);
}
