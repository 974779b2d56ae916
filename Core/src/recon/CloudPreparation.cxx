// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/CloudPreparation.h"

#include "sltk/cloud/CloudSpacing.h"

namespace sltk
{

template <int D>
Status checkAndCleanCloud(
  PointCloud<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report)
{
  SLTK_RETURN_IF_ERROR(validateCloud(cloud));
  // Cleaning comes before the unit box (4.5): an outlier would otherwise set its scale.
  SLTK_RETURN_IF_ERROR(cleanCloud(cloud, options, ctx, report));
  const Status valid = validateCloud(cloud);
  if (!valid.isOk())
  {
    return Status::invalidArgument("after cleaning: " + valid.message() + "; relax outlier removal or thinning");
  }
  return Status::ok();
}

template <int D>
Status placeInUnitBox(PointCloud<D> cloud, const Context& ctx, PointCloud<D>& unitCloud, UnitBox<D>& box,
  std::unique_ptr<const PointLocator<D>>& locator, double& spacing)
{
  locator.reset();
  box = UnitBox<D>(boundingBox(cloud));
  box.toUnit(cloud);
  unitCloud = std::move(cloud);
  locator = std::make_unique<const PointLocator<D>>(unitCloud, ReconstructionPointsPerBucket);
  return cloudSpacing(*locator, ctx, spacing); // h_P (4.36)
}

template Status checkAndCleanCloud(PointCloud<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status checkAndCleanCloud(PointCloud<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status placeInUnitBox(
  PointCloud<2>, const Context&, PointCloud<2>&, UnitBox<2>&, std::unique_ptr<const PointLocator<2>>&, double&);
template Status placeInUnitBox(
  PointCloud<3>, const Context&, PointCloud<3>&, UnitBox<3>&, std::unique_ptr<const PointLocator<3>>&, double&);

} // namespace sltk
