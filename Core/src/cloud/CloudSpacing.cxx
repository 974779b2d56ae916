// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudSpacing.h"

#include "sltk/cloud/PointLocator.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace sltk
{

namespace
{
Status tooFewPoints()
{
  return Status::invalidArgument("the cloud spacing h_P needs at least two points");
}
} // namespace

template <int D>
Status cloudSpacing(const PointCloud<D>& cloud, const Context& ctx, double& spacing, const CloudSpacingOptions& options)
{
  spacing = 0.0;
  if (cloud.size() < 2)
  {
    return tooFewPoints(); // (the locator needs a non-empty cloud)
  }
  const PointLocator<D> locator(cloud);
  return cloudSpacing(locator, ctx, spacing, options);
}

template <int D>
Status cloudSpacing(
  const PointLocator<D>& locator, const Context& ctx, double& spacing, const CloudSpacingOptions& options)
{
  spacing = 0.0;
  const PointCloud<D>& cloud = locator.cloud();
  const std::int64_t n = cloud.size();
  if (n < 2)
  {
    return tooFewPoints();
  }
  // Sample without replacement: a partial Fisher-Yates shuffle with a fixed seed.
  std::int64_t m = static_cast<std::int64_t>(options.SampleFraction * static_cast<double>(n));
  m = std::min(n, std::max(m, options.MinimumSample));
  std::vector<std::int64_t> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::mt19937_64 rng(options.Seed);
  for (std::int64_t i = 0; i < m; ++i)
  {
    std::uniform_int_distribution<std::int64_t> pick(i, n - 1);
    std::swap(order[static_cast<size_t>(i)], order[static_cast<size_t>(pick(rng))]);
  }
  const int kth = options.DensityNeighbours;
  if (kth < 0 || kth >= n)
  {
    return Status::invalidArgument("the density spacing needs 0 < k < the number of points");
  }
  std::vector<double> nearest(static_cast<size_t>(m), 0.0);
  ctx.parallelFor(0, m,
    [&](Index b, Index e)
    {
      std::vector<typename PointLocator<D>::Hit> hits;
      for (Index i = b; i < e; ++i)
      {
        const std::int64_t k = order[static_cast<size_t>(i)];
        if (kth == 0)
        {
          nearest[static_cast<size_t>(i)] = locator.nearest(cloud.Points[static_cast<size_t>(k)], k).Distance;
          continue;
        }
        locator.nearest(cloud.Points[static_cast<size_t>(k)], kth, k, hits);
        nearest[static_cast<size_t>(i)] = hits.back().Distance; // r_k
      }
    });
  double sum = 0.0;
  std::int64_t used = 0;
  for (double d : nearest)
  {
    if (d > 0.0)
    {
      sum += d;
      ++used;
    }
  }
  if (used == 0)
  {
    return Status::invalidArgument("every sampled point has a duplicate at distance 0: remove duplicate points");
  }
  spacing = sum / static_cast<double>(used);
  if (kth > 0)
  {
    spacing = densitySpacing<D>(spacing, kth);
  }
  return Status::ok();
}

template Status cloudSpacing(const PointCloud<2>&, const Context&, double&, const CloudSpacingOptions&);
template Status cloudSpacing(const PointCloud<3>&, const Context&, double&, const CloudSpacingOptions&);
template Status cloudSpacing(const PointLocator<2>&, const Context&, double&, const CloudSpacingOptions&);
template Status cloudSpacing(const PointLocator<3>&, const Context&, double&, const CloudSpacingOptions&);

} // namespace sltk
