// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/interp/CellCache.h"

#include "sltk/grid/SampleField.h"
#include "sltk/interp/Q1.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
/// Points in clusters of four around random centres (the feet of one node of
/// (4.24)), so that cells repeat as in the level-set step.
std::vector<std::array<double, 3>> clusteredPoints(int clusters, double spread)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> centre(-0.95, 0.95);
  std::uniform_real_distribution<double> offset(-spread, spread);
  std::vector<std::array<double, 3>> points;
  for (int c = 0; c < clusters; ++c)
  {
    const std::array<double, 3> x0{ centre(rng), centre(rng), centre(rng) };
    for (int j = 0; j < 4; ++j)
    {
      points.push_back({ x0[0] + offset(rng), x0[1] + offset(rng), x0[2] + offset(rng) });
    }
  }
  return points;
}

/// A kink (|x| - 0.5) and a smooth part on a 21^3 grid: the nonlinear weights matter.
sltk::GridField<3> kinkedField(const sltk::GridSpec<3>& grid)
{
  return sltk::sampleField(
    grid, 2, [](const double* x) { return std::fabs(std::hypot(x[0], x[1], x[2]) - 0.5) + std::sin(3.0 * x[2]); });
}

template <class Interp, int K>
void expectSameAsPlainInterpolation()
{
  const auto grid = sltk::uniformBox<3>(21, -1.0, 1.0);
  const auto field = kinkedField(grid);
  const auto points = clusteredPoints(500, 0.08);
  Interp plain(field);
  sltk::CellCache<Interp, K> cached(Interp(field), field);
  for (const auto& x : points)
  {
    const double expected = sltk::interpolate(plain, grid, x.data());
    ASSERT_EQ(cached(x.data()), expected); // bit-identical: prepare() is deterministic
  }
  EXPECT_EQ(cached.evaluations(), static_cast<double>(points.size()));
  EXPECT_LT(cached.builds(), cached.evaluations());
}

/// CellCache::evaluate() on groups of 1..4 points against operator() point by
/// point on another cache: the same values bit for bit and the same counts
/// (a small table makes two points of a group need one entry).
template <class Interp, int K>
void expectGroupsAsOneByOne()
{
  const auto field = kinkedField(sltk::uniformBox<3>(21, -1.0, 1.0));
  const auto points = clusteredPoints(500, 0.3);
  sltk::CellCache<Interp, K> one(Interp(field), field);
  sltk::CellCache<Interp, K> grouped(Interp(field), field);
  constexpr int L = sltk::CellCache<Interp, K>::PointLanes;
  for (size_t first = 0, g = 0; first < points.size(); ++g)
  {
    const int count = static_cast<int>(std::min<size_t>(1 + g % L, points.size() - first));
    const double* x[L];
    for (int l = 0; l < count; ++l)
    {
      x[l] = points[first + l].data();
    }
    double values[L];
    grouped.evaluate(count, x, values);
    for (int l = 0; l < count; ++l)
    {
      ASSERT_EQ(values[l], one(x[l])) << "point " << first + l;
    }
    first += static_cast<size_t>(count);
  }
  EXPECT_EQ(grouped.evaluations(), one.evaluations());
  EXPECT_EQ(grouped.builds(), one.builds());
}
} // namespace

TEST(CellCache, PointsEvaluatedTogetherAsOneByOne)
{
  expectGroupsAsOneByOne<sltk::CwenoInterpolator<3>, 4096>();
  expectGroupsAsOneByOne<sltk::CwenoZInterpolator<3>, 16>();
  expectGroupsAsOneByOne<sltk::CwenoInterpolator<3>, 8>();
  expectGroupsAsOneByOne<sltk::Q1Interpolator<3>, 256>();
}

TEST(CellCache, HashedCwenoPolynomialsEvaluateExactlyAsTheInterpolatorIn3D)
{
  expectSameAsPlainInterpolation<sltk::CwenoInterpolator<3>, 1024>();
  expectSameAsPlainInterpolation<sltk::CwenoZInterpolator<3>, 16>();
}

TEST(CellCache, SmallCachesOfOtherInterpolatorsEvaluateExactlyAsTheInterpolator)
{
  expectSameAsPlainInterpolation<sltk::Q1Interpolator<3>, 1>();
  expectSameAsPlainInterpolation<sltk::Q1Interpolator<3>, 4>();
}
