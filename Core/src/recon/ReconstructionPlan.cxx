// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/ReconstructionPlan.h"

#include "sltk/cloud/CloudSpacing.h"
#include "sltk/recon/CloudInitialData.h"

#include <cmath>
#include <sstream>

namespace sltk
{

namespace
{
/// Coarser buckets than the locator's default (2 points): the first bands of run 1
/// lie K_P h_P (4.4.4) from the cloud, where a fine bucket grid makes every
/// nearest-point query scan thousands of empty buckets (K_P = 16 on merged
/// scans: run 1 took 40% less time); the distances are the same exact ones.
constexpr double PointsPerBucket = 16.0;

/// How far outside the cloud's box run 1's initial surface reaches: K_P h_P
/// (4.4.4), or the bounding ellipsoid's overhang.
template <int D>
double initialReach(const Box<D>& bounds, double farDistance, const std::optional<Ellipsoid<D>>& ellipsoid)
{
  double reach = farDistance;
  if (ellipsoid)
  {
    for (int a = 0; a < D; ++a)
    {
      reach = std::max(reach, ellipsoid->Centre[a] + ellipsoid->SemiAxes[a] - bounds.Max[a]);
      reach = std::max(reach, bounds.Min[a] - (ellipsoid->Centre[a] - ellipsoid->SemiAxes[a]));
    }
  }
  return reach;
}
} // namespace

Status validateSchedule(const std::vector<RunParameters>& schedule)
{
  for (size_t k = 0; k < schedule.size(); ++k)
  {
    const RunParameters& run = schedule[k];
    if (!(run.P >= 1.0 && run.P <= 10.0) || !(run.Eta >= 0.0 && run.Eta <= 100.0))
    {
      std::ostringstream m;
      m << "run schedule pair " << k + 1 << " (p = " << run.P << ", eta = " << run.Eta
        << ") out of range: the model (4.9) needs 1 <= p <= 10 and 0 <= eta <= 100";
      return Status::invalidArgument(m.str());
    }
  }
  return Status::ok();
}

template <int D>
Status validateReconstructionOptions(const ReconstructionOptions& options)
{
  if (options.Runs < 1 || options.MaxIterations < 1 || options.MinIterations < 0 || options.EnergyWindow < 1 ||
    !(options.OutsideThresholdFactor > 0.0) || !(options.Tolerance >= 0.0) || options.ReinitDilation < 1 ||
    !(options.BetaFactor > 0.0) || !(options.GammaFactor > options.BetaFactor))
  {
    return Status::invalidArgument("reconstruction options out of range: need runs >= 1, iterations >= 1, "
                                   "K_P > 0, tolerance >= 0, 0 < beta < gamma");
  }
  SLTK_RETURN_IF_ERROR(validateSchedule(options.Schedule));
  return options.Reinit.validate<D>();
}

template <int D>
Status planReconstruction(
  PointCloud<D> cloud, const ReconstructionOptions& options, const Context& ctx, ReconstructionPlan<D>& plan)
{
  plan.Locator.reset();
  plan.Cloud = PointCloud<D>();
  plan.Cleaning = CloudCleaningReport{};
  plan.CloudSpacing = 0.0;
  plan.InitialEllipsoid.reset();
  plan.Grids = GridPlan<D>{};
  SLTK_RETURN_IF_ERROR(validateReconstructionOptions<D>(options));
  SLTK_RETURN_IF_ERROR(validateCloud(cloud));
  // Cleaning comes before the unit box (4.5): an outlier would otherwise set its scale.
  SLTK_RETURN_IF_ERROR(cleanCloud(cloud, options.Cleaning, ctx, plan.Cleaning));
  const Status valid = validateCloud(cloud);
  if (!valid.isOk())
  {
    return Status::invalidArgument("after cleaning: " + valid.message() + "; relax outlier removal or thinning");
  }
  plan.Box = UnitBox<D>(boundingBox(cloud));
  plan.Box.toUnit(cloud);
  plan.Cloud = std::move(cloud);
  plan.Locator = std::make_unique<const PointLocator<D>>(plan.Cloud, PointsPerBucket);
  SLTK_RETURN_IF_ERROR(cloudSpacing(*plan.Locator, ctx, plan.CloudSpacing)); // h_P (4.36)

  const double farDistance = options.OutsideThresholdFactor * plan.CloudSpacing; // K_P h_P (4.4.4)
  if (options.Guess == InitialGuess::BoundingSphere)
  {
    plan.InitialEllipsoid = boundingSphere(plan.Cloud, farDistance);
  }
  else if (options.Guess == InitialGuess::BoundingEllipsoid)
  {
    plan.InitialEllipsoid = boundingEllipsoid(plan.Cloud, farDistance);
  }
  GridPlanOptions po;
  po.Runs = options.Runs;
  po.CellSizeFactor = options.CellSizeFactor;
  po.Padding = options.Padding;
  // Run 1 must hold the initial surface, plus the band gamma and two cells, inside the grid.
  const Box<D> bounds = boundingBox(plan.Cloud);
  const double dx1 = options.CellSizeFactor * plan.CloudSpacing;
  po.FirstRunPadding = static_cast<int>(
    std::ceil(initialReach(bounds, farDistance, plan.InitialEllipsoid) / dx1 + options.GammaFactor + 2.0));
  po.BytesPerNode = ReconstructionBytesPerNode;
  po.MemoryBudget = options.MemoryBudget;
  return planGrids(bounds, plan.CloudSpacing, po, plan.Grids);
}

template Status validateReconstructionOptions<2>(const ReconstructionOptions&);
template Status validateReconstructionOptions<3>(const ReconstructionOptions&);
template Status planReconstruction(PointCloud<2>, const ReconstructionOptions&, const Context&, ReconstructionPlan<2>&);
template Status planReconstruction(PointCloud<3>, const ReconstructionOptions&, const Context&, ReconstructionPlan<3>&);

} // namespace sltk
