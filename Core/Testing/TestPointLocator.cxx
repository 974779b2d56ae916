// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PointLocator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
template <int D>
sltk::PointCloud<D> randomCloud(int n, std::uint64_t seed, double stretch = 1.0)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  sltk::PointCloud<D> c;
  for (int k = 0; k < n; ++k)
  {
    std::array<double, D> p;
    for (int a = 0; a < D; ++a)
    {
      p[a] = u(rng) * (a == 0 ? stretch : 1.0);
    }
    c.Points.push_back(p);
  }
  return c;
}

template <int D>
typename sltk::PointLocator<D>::Hit bruteForce(
  const sltk::PointCloud<D>& c, const std::array<double, D>& x, std::int64_t exclude)
{
  typename sltk::PointLocator<D>::Hit best;
  for (std::int64_t k = 0; k < c.size(); ++k)
  {
    if (k == exclude)
      continue;
    double d2 = 0.0;
    for (int a = 0; a < D; ++a)
      d2 += (c.Points[static_cast<size_t>(k)][a] - x[a]) * (c.Points[static_cast<size_t>(k)][a] - x[a]);
    if (std::sqrt(d2) < best.Distance)
    {
      best.Distance = std::sqrt(d2);
      best.Index = k;
    }
  }
  return best;
}
} // namespace

TEST(PointLocator, MatchesBruteForceIn3DInsideAndOutsideTheBox)
{
  auto cloud = randomCloud<3>(2000, 7);
  sltk::PointLocator<3> locator(cloud);
  auto queries = randomCloud<3>(300, 8, 1.0);
  for (auto& q : queries.Points)
  {
    q[1] *= 3.0; // many queries outside the cloud's box
    auto got = locator.nearest(q);
    auto want = bruteForce<3>(cloud, q, -1);
    ASSERT_EQ(got.Index, want.Index);
    ASSERT_DOUBLE_EQ(got.Distance, want.Distance);
  }
}

TEST(PointLocator, ExcludesTheQueryPointItself)
{
  auto cloud = randomCloud<2>(500, 3, 20.0); // a thin, long box
  sltk::PointLocator<2> locator(cloud);
  for (std::int64_t k = 0; k < cloud.size(); k += 7)
  {
    auto got = locator.nearest(cloud.Points[static_cast<size_t>(k)], k);
    auto want = bruteForce<2>(cloud, cloud.Points[static_cast<size_t>(k)], k);
    ASSERT_NE(got.Index, k);
    ASSERT_EQ(got.Index, want.Index);
  }
}

TEST(PointLocator, SinglePointCloudHasNoNeighbourOfItself)
{
  sltk::PointCloud<3> cloud;
  cloud.Points = { { 1.0, 2.0, 3.0 } };
  sltk::PointLocator<3> locator(cloud);
  EXPECT_EQ(locator.nearest({ 1.0, 2.0, 3.0 }, 0).Index, -1);
  EXPECT_EQ(locator.nearest({ 0.0, 0.0, 0.0 }).Index, 0);
}

TEST(PointLocator, KNearestMatchesBruteForce)
{
  const sltk::PointCloud<3> cloud = randomCloud<3>(3000, 99);
  const sltk::PointLocator<3> locator(cloud);
  std::vector<sltk::PointLocator<3>::Hit> hits;
  for (std::int64_t q = 0; q < 3000; q += 37)
  {
    locator.nearest(cloud.Points[static_cast<size_t>(q)], 8, q, hits);
    std::vector<std::pair<double, std::int64_t>> all;
    for (std::int64_t k = 0; k < 3000; ++k)
    {
      if (k != q)
      {
        double d2 = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          const double d = cloud.Points[static_cast<size_t>(k)][a] - cloud.Points[static_cast<size_t>(q)][a];
          d2 += d * d;
        }
        all.push_back({ std::sqrt(d2), k });
      }
    }
    std::sort(all.begin(), all.end());
    ASSERT_EQ(hits.size(), 8u);
    for (size_t j = 0; j < 8; ++j)
    {
      EXPECT_EQ(hits[j].Index, all[j].second);
      EXPECT_DOUBLE_EQ(hits[j].Distance, all[j].first);
    }
    EXPECT_EQ(locator.nearest(cloud.Points[static_cast<size_t>(q)], q).Index, hits[0].Index);
  }
  locator.nearest(cloud.Points[0], 5000, -1, hits);
  EXPECT_EQ(hits.size(), 3000u) << "fewer points than asked: all of them";
}

TEST(PointLocator, WithinIsEveryPointCloserThanTheRadius)
{
  // Against the k nearest with k the whole cloud (checked against brute force above),
  // for radii inside one bucket, across many, and a query outside the box.
  const sltk::PointCloud<3> cloud = randomCloud<3>(3000, 7);
  const sltk::PointLocator<3> locator(cloud);
  std::vector<sltk::PointLocator<3>::Hit> all;
  std::vector<std::int64_t> found;
  for (const double radius : { 0.01, 0.05, 0.3 })
  {
    for (std::int64_t q = 0; q < 3000; q += 101)
    {
      std::array<double, 3> x = cloud.Points[static_cast<size_t>(q)];
      x[0] += q % 2 == 0 ? 0.0 : 2.1; // outside the box [-1, 1]^3 for odd q
      locator.within(x, radius, q, found);
      locator.nearest(x, 3000, q, all);
      std::vector<std::int64_t> expected;
      for (const auto& hit : all)
      {
        if (hit.Distance < radius)
        {
          expected.push_back(hit.Index);
        }
      }
      std::sort(found.begin(), found.end());
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(found, expected) << "radius " << radius << ", point " << q;
    }
  }
}
