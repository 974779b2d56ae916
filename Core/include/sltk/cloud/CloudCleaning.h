// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudCleaning.h
/// The optional pre-processing stage of reconstruct() for real, merged range
/// scans (beyond the thesis, whose clouds are used as given): statistical
/// outlier removal (CloudOutliers.h), then voxel thinning (CloudThinning.h)
/// with a cell of ThinningFactor times the cloud's density spacing
/// (CloudSpacing.h), a spacing that overlapping scans do not collapse the way
/// they collapse the nearest-neighbour h_P (4.36). The grids then follow from
/// h_P (4.36) of the cleaned cloud. With the defaults nothing changes.

#include "sltk/cloud/CloudOutliers.h"
#include "sltk/exec/Context.h"

namespace sltk
{

struct CloudCleaningOptions
{
  bool RemoveOutliers = false;
  OutlierOptions Outliers;
  double ThinningFactor = 0.0; ///< thinning cell in units of the density spacing; 0: no thinning
  int DensityNeighbours = 16;  ///< k of the density spacing
};

struct CloudCleaningReport
{
  std::int64_t InputPoints = 0;
  std::int64_t OutliersRemoved = 0;
  double ThinningCell = 0.0;     ///< 0: not thinned
  std::int64_t OutputPoints = 0; ///< points given to Algorithm 1
};

/// Cleans `cloud` in place (untouched when nothing is enabled) and logs the
/// counts at Info level. Deterministic for any number of threads.
template <int D>
Status cleanCloud(
  PointCloud<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report);

extern template Status cleanCloud(PointCloud<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
extern template Status cleanCloud(PointCloud<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);

} // namespace sltk
