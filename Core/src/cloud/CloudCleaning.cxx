// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudCleaning.h"

#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/CloudThinning.h"

#include <cmath>
#include <sstream>

namespace sltk
{

template <int D>
Status cleanCloud(const PointCloud<D>& cloud, const CloudCleaningOptions& options, const Context& ctx,
  PointCloud<D>& cleaned, CloudCleaningReport& report)
{
  report = CloudCleaningReport{};
  report.InputPoints = cloud.size();
  if (!(options.ThinningFactor >= 0.0) || !std::isfinite(options.ThinningFactor) || options.DensityNeighbours < 1)
  {
    return Status::invalidArgument("cloud cleaning: the thinning factor must be >= 0 and finite, k >= 1");
  }
  PointCloud<D> current = cloud;
  if (options.RemoveOutliers)
  {
    OutlierReport outliers;
    SLTK_RETURN_IF_ERROR(removeOutliers(current, options.Outliers, ctx, current, outliers));
    report.OutliersRemoved = outliers.Removed;
    std::ostringstream log;
    log << "outlier removal: " << outliers.Removed << " of " << cloud.size()
        << " points removed (mean distance to " << options.Outliers.Neighbours << " neighbours above "
        << outliers.Threshold << ", mean " << outliers.MeanNeighbourDistance << ")";
    ctx.logger().log(LogLevel::Info, log.str());
  }
  if (options.ThinningFactor > 0.0 && current.size() > options.DensityNeighbours)
  {
    CloudSpacingOptions so;
    so.DensityNeighbours = options.DensityNeighbours;
    double density = 0.0;
    SLTK_RETURN_IF_ERROR(cloudSpacing(current, ctx, density, so));
    report.ThinningCell = options.ThinningFactor * density;
    const std::int64_t before = current.size();
    SLTK_RETURN_IF_ERROR(thinCloud(current, report.ThinningCell, current));
    std::ostringstream log;
    log << "thinning: cell " << report.ThinningCell << " (" << options.ThinningFactor
        << " x density spacing " << density << "): " << before << " -> " << current.size() << " points";
    ctx.logger().log(LogLevel::Info, log.str());
  }
  report.OutputPoints = current.size();
  cleaned = std::move(current);
  return Status::ok();
}

template Status cleanCloud(
  const PointCloud<2>&, const CloudCleaningOptions&, const Context&, PointCloud<2>&, CloudCleaningReport&);
template Status cleanCloud(
  const PointCloud<3>&, const CloudCleaningOptions&, const Context&, PointCloud<3>&, CloudCleaningReport&);

} // namespace sltk
