// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudOutliers.h"

#include "sltk/cloud/PointLocator.h"

#include <algorithm>
#include <cmath>

namespace sltk
{

template <int D>
Status removeOutliers(const PointCloud<D>& cloud, const OutlierOptions& options, const Context& ctx,
  PointCloud<D>& kept, OutlierReport& report)
{
  report = OutlierReport{};
  if (options.Neighbours < 1 || !(options.Deviations > 0.0) || !std::isfinite(options.Deviations))
  {
    return Status::invalidArgument("outlier removal needs k >= 1 neighbours and a positive, finite threshold");
  }
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
        locator.nearest(cloud.Points[static_cast<size_t>(i)], options.Neighbours, i, hits);
        double s = 0.0;
        for (const auto& h : hits)
        {
          s += h.Distance;
        }
        meanDistance[static_cast<size_t>(i)] = s / static_cast<double>(hits.size());
      }
    });
  // Serial sums: the same threshold for any number of threads.
  double sum = 0.0;
  for (double m : meanDistance)
  {
    sum += m;
  }
  const double mean = sum / static_cast<double>(n);
  double var = 0.0;
  for (double m : meanDistance)
  {
    var += (m - mean) * (m - mean);
  }
  report.MeanNeighbourDistance = mean;
  report.Threshold = mean + options.Deviations * std::sqrt(var / static_cast<double>(n));
  std::vector<double> sorted = meanDistance;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double median = sorted[static_cast<size_t>(n / 2)];
  const double largest = *std::max_element(meanDistance.begin(), meanDistance.end());
  report.LargestRatio = median > 0.0 ? largest / median : 0.0;
  if (options.GrossRatio > 0.0 && !(report.LargestRatio > options.GrossRatio))
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

template Status removeOutliers(
  const PointCloud<2>&, const OutlierOptions&, const Context&, PointCloud<2>&, OutlierReport&);
template Status removeOutliers(
  const PointCloud<3>&, const OutlierOptions&, const Context&, PointCloud<3>&, OutlierReport&);

} // namespace sltk
