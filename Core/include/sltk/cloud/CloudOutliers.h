// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudOutliers.h
/// Statistical outlier removal, a pre-processing step before Algorithm 1 for
/// real scans: the model (4.9) attracts the surface to every point of P, so a
/// stray point far from the object pulls a spike (or a separate piece) out of
/// the surface, and it inflates the bounding box that fixes the unit-box
/// rescaling (4.5) and the grids (4.36).
///
/// For every point Q, m(Q) is the mean distance to its k nearest neighbours;
/// Q is an outlier when m(Q) > mean(m) + s * std(m) over the cloud (sums rounded
/// once, ExactSum.h: the same on any number of threads and ranks).

#include "sltk/cloud/PointCloud.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Context.h"

namespace sltk
{

struct OutlierOptions
{
  int Neighbours = 8;      ///< k
  double Deviations = 3.0; ///< s: the threshold in standard deviations above the mean
  /// > 0: remove nothing unless some m(Q) exceeds this multiple of the median of
  /// m (the cloud has gross outliers); the automatic cleaning's gate.
  double GrossRatio = 0.0;
};

struct OutlierReport
{
  std::int64_t Removed = 0;
  double MeanNeighbourDistance = 0.0; ///< mean of m(Q) over the cloud
  double Threshold = 0.0;             ///< mean + s std
  double LargestRatio = 0.0;          ///< max m(Q) / median m(Q)
};

/// Copies the points of `cloud` that are not outliers into `kept`, in their
/// order. Deterministic (independent of the number of threads). Clouds with
/// at most k points are copied unchanged.
template <int D>
Status removeOutliers(const PointCloud<D>& cloud, const OutlierOptions& options, const Context& ctx,
  PointCloud<D>& kept, OutlierReport& report);

/// removeOutliers() on a cloud of `total` points spread over the ranks by
/// slabs (PointOwners.h): each owner tests its own points (their neighbours
/// among the points it holds, or on the ranks they may lie on beyond the halo),
/// the mean and deviation are sums rounded once and the gate's median is
/// exact, so the same points go as on one rank holding the whole cloud; the
/// owners drop them and the remaining points take their indices in the kept
/// cloud (`total` becomes its size). Collective.
template <int D>
Status removeOutliersOnRanks(OwnedPoints<D>& points, std::int64_t& total, const OutlierOptions& options,
  const Communicator& comm, const Context& ctx, OutlierReport& report);

extern template Status removeOutliers(
  const PointCloud<2>&, const OutlierOptions&, const Context&, PointCloud<2>&, OutlierReport&);
extern template Status removeOutliers(
  const PointCloud<3>&, const OutlierOptions&, const Context&, PointCloud<3>&, OutlierReport&);
extern template Status removeOutliersOnRanks(
  OwnedPoints<2>&, std::int64_t&, const OutlierOptions&, const Communicator&, const Context&, OutlierReport&);
extern template Status removeOutliersOnRanks(
  OwnedPoints<3>&, std::int64_t&, const OutlierOptions&, const Communicator&, const Context&, OutlierReport&);

} // namespace sltk
