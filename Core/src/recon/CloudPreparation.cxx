// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/CloudPreparation.h"

#include "sltk/cloud/CloudPoints.h"

namespace sltk
{

template <int D>
Status checkAndCleanCloud(
  CloudPoints<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report)
{
  SLTK_RETURN_IF_ERROR(cloud.validate());
  // Cleaning comes before the unit box (4.5): an outlier would otherwise set its scale.
  SLTK_RETURN_IF_ERROR(cleanCloud(cloud, options, ctx, report));
  const Status valid = cloud.validate();
  if (!valid.isOk())
  {
    return Status::invalidArgument("after cleaning: " + valid.message() + "; relax outlier removal or thinning");
  }
  return Status::ok();
}

template <int D>
Status checkAndCleanCloud(
  PointCloud<D>& cloud, const CloudCleaningOptions& options, const Context& ctx, CloudCleaningReport& report)
{
  WholeCloud<D> whole(cloud, PointLocatorDefaultBucket);
  return checkAndCleanCloud(static_cast<CloudPoints<D>&>(whole), options, ctx, report);
}

template <int D>
Status placeInUnitBox(CloudPoints<D>& cloud, const Context& ctx, UnitBox<D>& box, double& spacing)
{
  box = UnitBox<D>(cloud.box());
  SLTK_RETURN_IF_ERROR(cloud.transform([&box](const std::array<double, D>& p) { return box.toUnit(p); }));
  return cloud.spacing(ctx, CloudSpacingOptions{}, spacing); // h_P (4.36)
}

template <int D>
Status placeInUnitBox(PointCloud<D> cloud, const Context& ctx, PointCloud<D>& unitCloud, UnitBox<D>& box,
  std::unique_ptr<const PointLocator<D>>& locator, double& spacing)
{
  locator.reset();
  unitCloud = std::move(cloud);
  WholeCloud<D> whole(unitCloud, ReconstructionPointsPerBucket);
  SLTK_RETURN_IF_ERROR(placeInUnitBox(static_cast<CloudPoints<D>&>(whole), ctx, box, spacing));
  return whole.release(unitCloud, ReconstructionPointsPerBucket, locator);
}

template Status checkAndCleanCloud(CloudPoints<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status checkAndCleanCloud(CloudPoints<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status placeInUnitBox(CloudPoints<2>&, const Context&, UnitBox<2>&, double&);
template Status placeInUnitBox(CloudPoints<3>&, const Context&, UnitBox<3>&, double&);
template Status checkAndCleanCloud(PointCloud<2>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status checkAndCleanCloud(PointCloud<3>&, const CloudCleaningOptions&, const Context&, CloudCleaningReport&);
template Status placeInUnitBox(
  PointCloud<2>, const Context&, PointCloud<2>&, UnitBox<2>&, std::unique_ptr<const PointLocator<2>>&, double&);
template Status placeInUnitBox(
  PointCloud<3>, const Context&, PointCloud<3>&, UnitBox<3>&, std::unique_ptr<const PointLocator<3>>&, double&);

} // namespace sltk
