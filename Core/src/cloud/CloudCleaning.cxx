// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudCleaning.h"

#include "sltk/cloud/CloudPoints.h"

#include <cmath>
#include <sstream>

namespace sltk
{

template <int D>
Status cleanCloud(
  CloudPoints<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report)
{
  report = CloudCleaningReport{};
  report.InputPoints = cloud.size();
  if (!(options.ThinningFactor >= 0.0) || !std::isfinite(options.ThinningFactor) || options.DensityNeighbours < 1)
  {
    return Status::invalidArgument("cloud cleaning: the thinning factor must be >= 0 and finite, k >= 1");
  }
  const bool automatic = automaticCleaning(options);
  if (options.RemoveOutliers || automatic)
  {
    OutlierOptions outlierOptions = options.Outliers;
    if (automatic)
    {
      outlierOptions.GrossRatio = GrossOutlierRatio;
    }
    OutlierReport outliers;
    SLTK_RETURN_IF_ERROR(cloud.removeOutliers(outlierOptions, ctx, outliers));
    report.OutliersRemoved = outliers.Removed;
    report.AutomaticOutliers = automatic && outliers.Removed > 0;
    if (automatic && outliers.Removed == 0)
    {
      report.OutputPoints = cloud.size();
      return Status::ok(); // no gross outlier: the cloud is used as given
    }
    std::ostringstream log;
    if (automatic)
    {
      log << "gross outliers (a point " << outliers.LargestRatio
          << " times farther from its neighbours than the median point): automatic ";
    }
    log << "outlier removal: " << outliers.Removed << " of " << report.InputPoints
        << " points removed (mean distance to " << options.Outliers.Neighbours << " neighbours above "
        << outliers.Threshold << ", mean " << outliers.MeanNeighbourDistance << ")";
    ctx.logger().log(LogLevel::Info, log.str());
  }
  if (!automatic && options.ThinningFactor > 0.0 && cloud.size() > options.DensityNeighbours)
  {
    CloudSpacingOptions so;
    so.DensityNeighbours = options.DensityNeighbours;
    double density = 0.0;
    SLTK_RETURN_IF_ERROR(cloud.spacing(ctx, so, density));
    report.ThinningCell = options.ThinningFactor * density;
    const std::int64_t before = cloud.size();
    SLTK_RETURN_IF_ERROR(cloud.thin(report.ThinningCell));
    std::ostringstream log;
    log << "thinning: cell " << report.ThinningCell << " (" << options.ThinningFactor << " x density spacing "
        << density << "): " << before << " -> " << cloud.size() << " points";
    ctx.logger().log(LogLevel::Info, log.str());
  }
  report.OutputPoints = cloud.size();
  return Status::ok();
}

template <int D>
Status cleanCloud(
  PointCloud<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report)
{
  WholeCloud<D> whole(cloud, PointLocatorDefaultBucket);
  return cleanCloud(static_cast<CloudPoints<D>&>(whole), options, ctx, report);
}

template Status cleanCloud(CloudPoints<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status cleanCloud(CloudPoints<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status cleanCloud(PointCloud<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status cleanCloud(PointCloud<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);

} // namespace sltk
