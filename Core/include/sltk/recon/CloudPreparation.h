// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudPreparation.h
/// The first steps of every reconstruction, uniform (ReconstructionPlan.h)
/// or adaptive (P4est/): the cloud checked and cleaned, then moved into the
/// unit box [-1, 1]^D (4.5) with one point locator and h_P (4.36). One
/// implementation for both, so that the two versions see the same cloud.

#include "sltk/cloud/CloudCleaning.h"
#include "sltk/cloud/CloudPoints.h"
#include "sltk/cloud/PointLocator.h"
#include "sltk/exec/Context.h"
#include "sltk/recon/UnitBox.h"

#include <memory>

namespace sltk
{

/// Points per bucket of the reconstruction's locator: coarser than the
/// locator's default (2), because the first bands lie K_P h_P (4.4.4) from the
/// cloud, where a fine bucket grid makes every nearest-point query scan
/// thousands of empty buckets (K_P = 16 on merged scans: run 1 took 40% less
/// time); the distances are the same exact ones.
constexpr double ReconstructionPointsPerBucket = 16.0;

/// validateCloud, cleanCloud (in place) and validateCloud again; the second
/// failure says that the cleaning emptied or flattened the cloud.
template <int D>
Status checkAndCleanCloud(
  PointCloud<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report);

/// The same on a cloud held whole or spread over the ranks (CloudPoints.h).
template <int D>
Status checkAndCleanCloud(
  CloudPoints<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report);

/// `cloud` (held whole or spread over the ranks) moved into the unit box of its
/// bounding box (`box`, 4.5), and h_P (4.36) of it in unit-box units.
template <int D>
Status placeInUnitBox(CloudPoints<D>& cloud, const Context& ctx, UnitBox<D>& box, double& spacing);

/// `cloud` moved into the unit box of its bounding box (`box`, 4.5), stored
/// in `unitCloud`, a locator on `unitCloud` (which must then stay where it is)
/// and h_P (4.36) of it in unit-box units.
template <int D>
Status placeInUnitBox(PointCloud<D> cloud, const Context& ctx, PointCloud<D>& unitCloud, UnitBox<D>& box,
  std::unique_ptr<const PointLocator<D>>& locator, double& spacing);

extern template Status checkAndCleanCloud(
  CloudPoints<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
extern template Status checkAndCleanCloud(
  CloudPoints<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
extern template Status placeInUnitBox(CloudPoints<2>&, const Context&, UnitBox<2>&, double&);
extern template Status placeInUnitBox(CloudPoints<3>&, const Context&, UnitBox<3>&, double&);
extern template Status checkAndCleanCloud(
  PointCloud<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
extern template Status checkAndCleanCloud(
  PointCloud<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
extern template Status placeInUnitBox(
  PointCloud<2>, const Context&, PointCloud<2>&, UnitBox<2>&, std::unique_ptr<const PointLocator<2>>&, double&);
extern template Status placeInUnitBox(
  PointCloud<3>, const Context&, PointCloud<3>&, UnitBox<3>&, std::unique_ptr<const PointLocator<3>>&, double&);

} // namespace sltk
