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

TEST(PointLocator, NearestDistancesAreTheQueriesBitForBit)
{
  // Batches of a tile's size around centres on, near and far from a surface-like
  // cloud (a sphere), and far from a cloud shifted to survey-like coordinates;
  // a small candidate cap forces the query-per-point fallback too.
  for (const double shift : { 0.0, 4.0e5 })
  {
    sltk::PointCloud<3> cloud;
    std::mt19937_64 rng(11);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int k = 0; k < 4000; ++k)
    {
      std::array<double, 3> p{ g(rng), g(rng), g(rng) };
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      cloud.Points.push_back({ shift + p[0] / r, p[1] / r, p[2] / r });
    }
    const sltk::PointLocator<3> locator(cloud);
    std::vector<std::int64_t> candidates;
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const double away : { 0.0, 0.9, 1.02, 1.3, 3.0 })
    {
      for (const std::int64_t cap : { std::int64_t(1024), std::int64_t(3) })
      {
        const std::array<double, 3> centre{ shift + away * 0.6, away * 0.8, 0.0 };
        const double spread = 0.05;
        std::vector<std::array<double, 3>> x(512);
        for (auto& p : x)
        {
          for (int a = 0; a < 3; ++a)
          {
            p[a] = centre[a] + spread / std::sqrt(3.0) * u(rng);
          }
        }
        std::vector<double> distances(x.size());
        locator.nearestDistances(x.data(), static_cast<std::int64_t>(x.size()), distances.data(), candidates, cap);
        for (size_t i = 0; i < x.size(); ++i)
        {
          ASSERT_EQ(distances[i], locator.nearest(x[i]).Distance)
            << "shift " << shift << ", " << away << " from the centre, cap " << cap << ", point " << i;
        }
      }
    }
  }
}
