// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PointClusters.h
/// The points a run's surface leaves outside, grouped by proximity: the far-point
/// seeds keep the groups attached to the surface (FarPointSeeds.h), and a result
/// that does not fit its cloud says where its missed groups lie (MissedPlaces.h); the
/// cloud's connected components, which the result's pieces are compared with.

#include "sltk/cloud/LinkedComponents.h"
#include "sltk/cloud/LocalSpacing.h"
#include "sltk/cloud/PointCloud.h"
#include "sltk/core/DisjointSets.h"
#include "sltk/core/IndexBox.h"
#include "sltk/exec/OrderStatistics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace sltk
{

/// A point outside the surface and I[phi] there.
struct OutsidePoint
{
  Index Point = 0;
  double Value = 0.0;
};

/// A point outside the surface with its place and its global index (Point), as
/// the ranks gather them: no rank needs the whole cloud to place it.
template <int D>
struct PlacedPoint
{
  Index Point = 0;
  double Value = 0.0;
  std::array<double, D> X{};
};

/// The places of `points` (their Point indices into `cloud`), with the indices
/// mapped by `index` (a run's point to the whole cloud's).
template <int D, class Map>
std::vector<PlacedPoint<D>> placedPoints(const std::vector<OutsidePoint>& points, const PointCloud<D>& cloud, Map index)
{
  std::vector<PlacedPoint<D>> placed(points.size());
  for (size_t j = 0; j < points.size(); ++j)
  {
    placed[j] = { index(points[j].Point), points[j].Value, cloud.Points[static_cast<size_t>(points[j].Point)] };
  }
  return placed;
}

/// Every rank's `local` points on every rank, in increasing Point (the cloud's order). Collective.
template <int D>
std::vector<PlacedPoint<D>> gatherPlaced(const std::vector<PlacedPoint<D>>& local, const Communicator& comm)
{
  std::vector<PlacedPoint<D>> all = comm.size() > 1 ? comm.allGatherV(local) : local;
  std::sort(all.begin(), all.end(), [](const PlacedPoint<D>& a, const PlacedPoint<D>& b) { return a.Point < b.Point; });
  return all;
}

/// The groups of `points` (pointGroups below) from their places alone: the same groups.
template <int D>
std::vector<Index> placedGroups(const std::vector<PlacedPoint<D>>& points, double link);

/// The groups of `points` (indices into `cloud`): two points closer than `link` are
/// in one group, and so, through chains of such pairs, are their groups. Returns,
/// for every entry of `points`, the entry that stands for its group (a union-find
/// over buckets of edge `link`); the same for any order of the ranks' points once
/// they are sorted by index. A link of 0 or less (or NaN) links no pair: every
/// entry is its own group.
template <int D>
std::vector<Index> pointGroups(const PointCloud<D>& cloud, const std::vector<OutsidePoint>& points, double link)
{
  if (!(link > 0.0)) // no bucket of edge link: x / link is not a bucket's index
  {
    return singletonForest<Index>(points.size());
  }
  std::map<std::array<Index, D>, std::vector<Index>> buckets;
  const auto bucketOf = [&](const std::array<double, D>& x)
  {
    std::array<Index, D> b{};
    for (int a = 0; a < D; ++a)
    {
      b[a] = static_cast<Index>(std::floor(x[a] / link));
    }
    return b;
  };
  const auto at = [&](Index j) -> const std::array<double, D>&
  { return cloud.Points[static_cast<size_t>(points[static_cast<size_t>(j)].Point)]; };
  const Index n = static_cast<Index>(points.size());
  for (Index j = 0; j < n; ++j)
  {
    buckets[bucketOf(at(j))].push_back(j);
  }
  std::vector<Index> parent = singletonForest<Index>(static_cast<size_t>(n));
  for (Index j = 0; j < n; ++j)
  {
    std::array<Index, D> lo = bucketOf(at(j)), hi = lo;
    for (int a = 0; a < D; ++a)
    {
      --lo[a];
      ++hi[a];
    }
    forEachIndexInBox<D>(lo, hi,
      [&](const std::array<Index, D>& b)
      {
        const auto found = buckets.find(b);
        if (found == buckets.end())
        {
          return;
        }
        for (Index k : found->second)
        {
          double d2 = 0.0;
          for (int a = 0; a < D; ++a)
          {
            d2 += (at(j)[a] - at(k)[a]) * (at(j)[a] - at(k)[a]);
          }
          if (k > j && d2 < link * link)
          {
            unite(parent, j, k);
          }
        }
      });
  }
  std::vector<Index> group(static_cast<size_t>(n));
  for (Index j = 0; j < n; ++j)
  {
    group[static_cast<size_t>(j)] = findRoot(parent, j);
  }
  return group;
}

template <int D>
std::vector<Index> placedGroups(const std::vector<PlacedPoint<D>>& points, double link)
{
  PointCloud<D> places;
  std::vector<OutsidePoint> entries(points.size());
  for (size_t j = 0; j < points.size(); ++j)
  {
    places.Points.push_back(points[j].X);
    entries[j] = { static_cast<Index>(j), points[j].Value };
  }
  return pointGroups(places, entries, link);
}

/// The cloud's connected components, what the result's pieces are compared with
/// (Documentation/Numerics.md, "Pieces against the cloud's components"): points i and j
/// are linked when |p_i - p_j| < max(r_i, r_j), r_i = `factor` max(h_P, min(s_i,
/// MaximumSparsity median s)), s_i the unsmoothed density spacing at the k-th neighbour
/// (LocalSpacing.h): a link that follows the sampling where it is sparser than h_P (the
/// vertices of CAD meshes), capped where a point is far from all others. `cloudSpacing`
/// alone (factor h_P) for k < 1 or at most k points. The count is a property of the
/// cloud alone: the same for any order, number of threads or ranks.
template <int D>
Index cloudComponents(const PointLocator<D>& locator, double cloudSpacing, double factor, int k, const Context& ctx)
{
  const PointCloud<D>& cloud = locator.cloud();
  const Index n = cloud.size();
  std::vector<double> radius(static_cast<size_t>(n), factor * cloudSpacing);
  std::vector<double> spacing;
  if (k >= 1 && n > k && densitySpacings(locator, k, ctx, spacing).isOk())
  {
    const double cap = MaximumSparsity * medianOf(spacing);
    for (size_t i = 0; i < radius.size(); ++i)
    {
      radius[i] = factor * std::max(cloudSpacing, std::min(spacing[i], cap));
    }
  }
  std::vector<std::int64_t> parent = singletonForest<std::int64_t>(static_cast<size_t>(n));
  linkWithinRadii(locator, radius, nullptr, parent);
  Index roots = 0;
  for (Index i = 0; i < n; ++i)
  {
    roots += findRoot(parent, static_cast<std::int64_t>(i)) == i ? 1 : 0;
  }
  return roots;
}

/// cloudComponents() of a cloud spread over the ranks by owners (PointOwners.h):
/// each point's s from its owner (densitySpacingsOnRanks), the median an exact
/// order statistic over the ranks, the links and their joins across the cuts by
/// linkedComponentsOnRanks. `count` is the one-rank count for any number of
/// ranks and any cuts; a spacing that makes a radius negative or not finite
/// fails (where one rank's cloudComponents counts what such radii link).
/// Collective.
template <int D>
Status cloudComponentsOnRanks(const OwnedPoints<D>& points, double cloudSpacing, double factor, int k,
  const Communicator& comm, const Context& ctx, std::int64_t& count)
{
  const std::int64_t n = comm.allReduce(points.Owned, ReduceOp::Sum);
  std::vector<double> radius(static_cast<size_t>(points.held()), factor * cloudSpacing);
  if (k >= 1 && n > k)
  {
    std::vector<std::int64_t> own;
    std::vector<double> spacing;
    std::int64_t remote = 0;
    SLTK_RETURN_IF_ERROR(densitySpacingsOnRanks(points, k, comm, ctx, own, spacing, remote));
    const double cap = MaximumSparsity * kthSmallestOverRanks(spacing, n / 2, comm); // medianOf's middle
    for (size_t s = 0; s < own.size(); ++s)
    {
      radius[static_cast<size_t>(own[s])] = factor * std::max(cloudSpacing, std::min(spacing[s], cap));
    }
  }
  LinkedComponents components;
  SLTK_RETURN_IF_ERROR(linkedComponentsOnRanks(points, radius, comm, ctx, components));
  count = components.Count;
  return Status::ok();
}

} // namespace sltk
