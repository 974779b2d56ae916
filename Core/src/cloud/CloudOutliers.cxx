// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudOutliers.h"

#include "SampleOnOwners.h"
#include "sltk/cloud/PointLocator.h"
#include "sltk/core/ExactSum.h"
#include "sltk/exec/OrderStatistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sltk
{

namespace
{
Status checkOptions(const OutlierOptions& options)
{
  if (options.Neighbours < 1 || !(options.Deviations > 0.0) || !std::isfinite(options.Deviations))
  {
    return Status::invalidArgument("outlier removal needs k >= 1 neighbours and a positive, finite threshold");
  }
  return Status::ok();
}

/// m(Q) of point `i` of the locator's cloud, and its farthest neighbour (+inf: fewer than k others held).
template <int D>
OwnedAnswer meanNeighbourDistance(
  const PointLocator<D>& locator, std::int64_t i, int k, std::vector<typename PointLocator<D>::Hit>& hits)
{
  locator.nearest(locator.cloud().Points[static_cast<size_t>(i)], k, i, hits);
  if (static_cast<int>(hits.size()) < k)
  {
    return { 0.0, std::numeric_limits<double>::infinity() };
  }
  double s = 0.0;
  for (const auto& h : hits)
  {
    s += h.Distance;
  }
  return { s / static_cast<double>(hits.size()), hits.back().Distance };
}

/// The test's mean, threshold and gate from every rank's m(Q) (`local`, of
/// `total` points): exactly rounded sums and an exact median, so that any
/// split of the cloud over ranks gives one rank's report.
OutlierReport outlierStatistics(
  const std::vector<double>& local, std::int64_t total, const OutlierOptions& options, const Communicator& comm)
{
  OutlierReport report;
  ExactSum sum;
  for (double m : local)
  {
    sum.add(m);
  }
  sum.reduceOver(comm);
  const double mean = sum.value() / static_cast<double>(total);
  ExactSum squares;
  for (double m : local)
  {
    squares.add((m - mean) * (m - mean));
  }
  squares.reduceOver(comm);
  report.MeanNeighbourDistance = mean;
  report.Threshold = mean + options.Deviations * std::sqrt(squares.value() / static_cast<double>(total));
  const double median = kthSmallestOverRanks(local, total / 2, comm);
  const double largest = comm.allReduce(
    local.empty() ? -std::numeric_limits<double>::infinity() : *std::max_element(local.begin(), local.end()),
    ReduceOp::Max);
  report.LargestRatio = median > 0.0 ? largest / median : 0.0;
  return report;
}

/// Whether the test removes anything: always, unless gated on gross outliers and none is gross.
bool removes(const OutlierReport& report, const OutlierOptions& options)
{
  return !(options.GrossRatio > 0.0 && !(report.LargestRatio > options.GrossRatio));
}
} // namespace

template <int D>
Status removeOutliers(const PointCloud<D>& cloud, const OutlierOptions& options, const Context& ctx,
  PointCloud<D>& kept, OutlierReport& report)
{
  report = OutlierReport{};
  SLTK_RETURN_IF_ERROR(checkOptions(options));
  const std::int64_t n = cloud.size();
  if (n <= options.Neighbours)
  {
    kept = cloud;
    return Status::ok();
  }
  const PointLocator<D> locator(cloud);
  std::vector<double> meanDistance(static_cast<size_t>(n), 0.0);
  ctx.parallelFor(0, n,
    [&](Index b, Index e)
    {
      std::vector<typename PointLocator<D>::Hit> hits;
      for (Index i = b; i < e; ++i)
      {
        meanDistance[static_cast<size_t>(i)] = meanNeighbourDistance(locator, i, options.Neighbours, hits).Value;
      }
    });
  report = outlierStatistics(meanDistance, n, options, serialCommunicator());
  if (!removes(report, options))
  {
    kept = cloud;
    return Status::ok();
  }
  PointCloud<D> out;
  out.Points.reserve(cloud.Points.size());
  for (std::int64_t i = 0; i < n; ++i)
  {
    if (meanDistance[static_cast<size_t>(i)] <= report.Threshold)
    {
      out.Points.push_back(cloud.Points[static_cast<size_t>(i)]);
    }
  }
  report.Removed = n - out.size();
  kept = std::move(out);
  return Status::ok();
}

template <int D>
Status removeOutliersOnRanks(OwnedPoints<D>& points, std::int64_t& total, const OutlierOptions& options,
  const Communicator& comm, const Context& ctx, OutlierReport& report)
{
  report = OutlierReport{};
  SLTK_RETURN_IF_ERROR(checkOptions(options));
  SLTK_RETURN_IF_ERROR(checkTotal(points, total, comm));
  if (total <= options.Neighbours)
  {
    return Status::ok();
  }
  std::vector<std::int64_t> own; // positions of this rank's points in points.Cloud
  for (size_t j = 0; j < points.Ids.size(); ++j)
  {
    if (points.Mine[j])
    {
      own.push_back(static_cast<std::int64_t>(j));
    }
  }
  std::vector<double> meanDistance;
  std::int64_t remote = 0;
  const int k = options.Neighbours;
  SLTK_RETURN_IF_ERROR(answerOnOwners(
    points, own, k, comm, ctx,
    [k](const PointLocator<D>& locator, std::int64_t i, std::vector<typename PointLocator<D>::Hit>& hits)
    { return meanNeighbourDistance(locator, i, k, hits); },
    meanDistance, remote));
  report = outlierStatistics(meanDistance, total, options, comm);
  if (!removes(report, options))
  {
    return Status::ok();
  }
  std::vector<std::uint8_t> keep(points.Ids.size(), 1);
  for (size_t s = 0; s < own.size(); ++s)
  {
    keep[static_cast<size_t>(own[s])] = meanDistance[s] <= report.Threshold ? 1 : 0;
  }
  SLTK_RETURN_IF_ERROR(comm.agree(keepOwned(points, keep, comm, report.Removed)));
  total -= report.Removed;
  return Status::ok();
}

template Status removeOutliers(
  const PointCloud<2>&, const OutlierOptions&, const Context&, PointCloud<2>&, OutlierReport&);
template Status removeOutliers(
  const PointCloud<3>&, const OutlierOptions&, const Context&, PointCloud<3>&, OutlierReport&);
template Status removeOutliersOnRanks(
  OwnedPoints<2>&, std::int64_t&, const OutlierOptions&, const Communicator&, const Context&, OutlierReport&);
template Status removeOutliersOnRanks(
  OwnedPoints<3>&, std::int64_t&, const OutlierOptions&, const Communicator&, const Context&, OutlierReport&);

} // namespace sltk
