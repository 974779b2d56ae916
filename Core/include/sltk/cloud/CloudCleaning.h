// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudCleaning.h
/// The optional pre-processing stage of reconstruct() for real, merged range
/// scans (beyond the thesis, whose clouds are used as given): statistical
/// outlier removal (CloudOutliers.h), then voxel thinning (CloudThinning.h)
/// with a cell of ThinningFactor times the cloud's density spacing
/// (CloudSpacing.h), a spacing that overlapping scans do not collapse the way
/// they collapse the nearest-neighbour h_P (4.36). The grids then follow from
/// h_P (4.36) of the cleaned cloud.
///
/// Automatic cleaning (the default, when neither step is asked for explicitly):
/// outliers are removed only when the cloud has gross ones (some point's mean
/// distance to its neighbours above GrossOutlierRatio times the median), and
/// the reconstruction plan thins a cloud that is denser than its finest grid
/// (AutomaticParameters.h). Clouds without gross outliers are left as given.

#include "sltk/cloud/CloudOutliers.h"
#include "sltk/exec/Context.h"

namespace sltk
{

/// The automatic gate: gross outliers lie this many times farther from their
/// neighbours than the median point (clean clouds measured: at most 3.7; the
/// merged Stanford bunny scans' stray point: 164).
constexpr double GrossOutlierRatio = 20.0;

struct CloudCleaningOptions
{
  /// Decide from the cloud; ignored (off) as soon as RemoveOutliers or
  /// ThinningFactor is set explicitly. false: the cloud is used as given.
  bool Automatic = true;
  bool RemoveOutliers = false;
  OutlierOptions Outliers;
  double ThinningFactor = 0.0; ///< thinning cell in units of the density spacing; 0: no thinning
  int DensityNeighbours = 16;  ///< k of the density spacing
};

struct CloudCleaningReport
{
  std::int64_t InputPoints = 0;
  std::int64_t OutliersRemoved = 0;
  double ThinningCell = 0.0;      ///< 0: not thinned
  std::int64_t OutputPoints = 0;  ///< points given to Algorithm 1
  bool AutomaticOutliers = false; ///< outliers were removed because gross ones were found
  bool AutomaticThinning = false; ///< thinned because the cloud is denser than the finest grid
};

/// True when `options` leaves the cleaning to the automatic rules.
inline bool automaticCleaning(const CloudCleaningOptions& options)
{
  return options.Automatic && !options.RemoveOutliers && !(options.ThinningFactor > 0.0);
}

/// Cleans `cloud` in place (untouched when nothing is enabled) and logs the
/// counts at Info level. Deterministic for any number of threads.
template <int D>
Status cleanCloud(
  PointCloud<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report);

template <int D>
class CloudPoints;

/// The same on a cloud held whole or spread over the ranks (CloudPoints.h):
/// the same points removed and thinned, the same report and log lines.
template <int D>
Status cleanCloud(
  CloudPoints<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report);

extern template Status cleanCloud(CloudPoints<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
extern template Status cleanCloud(CloudPoints<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
extern template Status cleanCloud(PointCloud<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
extern template Status cleanCloud(PointCloud<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);

} // namespace sltk
