// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudSpacing.h"

#include "SampleOnOwners.h"
#include "sltk/cloud/PointLocator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>

namespace sltk
{

namespace
{
Status tooFewPoints()
{
  return Status::invalidArgument("the cloud spacing h_P needs at least two points");
}

/// The sample's size and the checks of its options for a cloud of n points.
Status sampleSize(std::int64_t n, const CloudSpacingOptions& options, std::int64_t& m)
{
  if (n < 2)
  {
    return tooFewPoints();
  }
  if (options.DensityNeighbours < 0 || options.DensityNeighbours >= n)
  {
    return Status::invalidArgument("the density spacing needs 0 < k < the number of points");
  }
  m = static_cast<std::int64_t>(options.SampleFraction * static_cast<double>(n));
  m = std::min(n, std::max(m, options.MinimumSample));
  return Status::ok();
}

/// The first m indices of a partial Fisher-Yates shuffle of 0..n-1 with a
/// fixed seed (a sample without replacement), in the shuffle's order. The
/// positions it swaps are kept in a map: O(m) memory, the same indices as a
/// shuffle of the whole index array.
std::vector<std::int64_t> sampleIndices(std::int64_t n, std::int64_t m, std::uint64_t seed)
{
  std::vector<std::int64_t> sample(static_cast<size_t>(m));
  std::unordered_map<std::int64_t, std::int64_t> moved; // position -> index now there (absent: itself)
  moved.reserve(static_cast<size_t>(2 * m));
  const auto at = [&moved](std::int64_t position)
  {
    const auto it = moved.find(position);
    return it == moved.end() ? position : it->second;
  };
  std::mt19937_64 rng(seed);
  for (std::int64_t i = 0; i < m; ++i)
  {
    std::uniform_int_distribution<std::int64_t> pick(i, n - 1);
    const std::int64_t j = pick(rng);
    const std::int64_t picked = at(j);
    const std::int64_t first = at(i);
    moved[j] = first; // swap(order[i], order[j]); position i is not read again
    sample[static_cast<size_t>(i)] = picked;
  }
  return sample;
}

/// The distance from point `self` of the locator's cloud to its nearest other
/// point, or (kth > 0) to its kth nearest; +inf when the cloud has too few others.
template <int D>
double neighbourDistance(
  const PointLocator<D>& locator, std::int64_t self, int kth, std::vector<typename PointLocator<D>::Hit>& hits)
{
  const auto& x = locator.cloud().Points[static_cast<size_t>(self)];
  if (kth == 0)
  {
    return locator.nearest(x, self).Distance;
  }
  locator.nearest(x, kth, self, hits);
  return static_cast<int>(hits.size()) < kth ? std::numeric_limits<double>::infinity() : hits.back().Distance; // r_k
}

/// h_P (or the density spacing) from the sample's distances in the sample's
/// order: their mean, duplicates (distance 0) skipped.
template <int D>
Status meanSpacing(const std::vector<double>& nearest, int kth, double& spacing)
{
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
  std::int64_t m = 0;
  SLTK_RETURN_IF_ERROR(sampleSize(locator.cloud().size(), options, m));
  const std::vector<std::int64_t> sample = sampleIndices(locator.cloud().size(), m, options.Seed);
  std::vector<double> nearest(static_cast<size_t>(m), 0.0);
  ctx.parallelFor(0, m,
    [&](Index b, Index e)
    {
      std::vector<typename PointLocator<D>::Hit> hits;
      for (Index i = b; i < e; ++i)
      {
        nearest[static_cast<size_t>(i)] =
          neighbourDistance(locator, sample[static_cast<size_t>(i)], options.DensityNeighbours, hits);
      }
    });
  return meanSpacing<D>(nearest, options.DensityNeighbours, spacing);
}

template <int D>
Status cloudSpacingOnRanks(const OwnedPoints<D>& points, std::int64_t total, const Communicator& comm,
  const Context& ctx, double& spacing, const CloudSpacingOptions& options, std::int64_t* remote)
{
  spacing = 0.0;
  std::int64_t m = 0;
  SLTK_RETURN_IF_ERROR(sampleSize(total, options, m));
  SLTK_RETURN_IF_ERROR(checkTotal(points, total, comm));
  const int kth = options.DensityNeighbours;
  std::vector<double> nearest;
  std::int64_t asked = 0;
  SLTK_RETURN_IF_ERROR(sampleOnOwners(
    points, sampleIndices(total, m, options.Seed), std::max(kth, 1), comm, ctx,
    [kth](const PointLocator<D>& locator, std::int64_t local, std::vector<typename PointLocator<D>::Hit>& hits)
    {
      const double d = neighbourDistance(locator, local, kth, hits);
      return OwnedAnswer{ d, d };
    },
    nearest, asked));
  if (remote)
  {
    *remote = asked;
  }
  return meanSpacing<D>(nearest, kth, spacing);
}

template Status cloudSpacing(const PointCloud<2>&, const Context&, double&, const CloudSpacingOptions&);
template Status cloudSpacing(const PointCloud<3>&, const Context&, double&, const CloudSpacingOptions&);
template Status cloudSpacing(const PointLocator<2>&, const Context&, double&, const CloudSpacingOptions&);
template Status cloudSpacing(const PointLocator<3>&, const Context&, double&, const CloudSpacingOptions&);
template Status cloudSpacingOnRanks(const OwnedPoints<2>&, std::int64_t, const Communicator&, const Context&, double&,
  const CloudSpacingOptions&, std::int64_t*);
template Status cloudSpacingOnRanks(const OwnedPoints<3>&, std::int64_t, const Communicator&, const Context&, double&,
  const CloudSpacingOptions&, std::int64_t*);

} // namespace sltk
