// SPDX-License-Identifier: BSD-3-Clause
/// \file ReconstructionPlan.cxx
/// The plan of a reconstruction (ReconstructionPlan.h): the options checked,
/// the cloud steps (validation, cleaning, unit box, h_P, noise, the automatic
/// interpolator, C_dx and thinning, the local offset's rho, on the whole cloud or
/// on its owners), K_P
/// and run 1's surface; the grids against the memory are RunGridMemory.cxx's.
#include "sltk/recon/ReconstructionPlan.h"

#include "sltk/cloud/CloudNoise.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/CloudThickness.h"
#include "sltk/cloud/CloudThinning.h"
#include "sltk/cloud/LocalSpacing.h"
#include "sltk/exec/CountingCommunicator.h"
#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/CloudInitialData.h"
#include "sltk/recon/CloudPreparation.h"
#include "sltk/recon/StrayPoints.h"

#include "RunGridMemory.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace sltk
{

namespace
{
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

/// Refuses a cloud flatter than half the finest cell (CloudThickness.h): the
/// level set would have no cell to stay in, and no K_P or eta helps. Half, so
/// that an automatic C_dx refined once by the reconstruction is covered.
template <int D>
Status refuseFlatCloud(const ReconstructionPlan<D>& plan, const Context& ctx)
{
  const GridSpec<D>& finest = plan.Grids.Runs.back();
  const double dx = *std::min_element(finest.Spacing.begin(), finest.Spacing.end());
  const FlatFit<D> fit = fitFlat(plan.Cloud);
  if (!(fit.Thickness < 0.5 * dx))
  {
    return Status::ok();
  }
  const std::string stray = strayPointAdvice(plan.Cloud, ctx);
  if (!stray.empty())
  {
    return Status::invalidArgument("the grid's cells are too coarse for the object: " + stray);
  }
  const std::string groups = separateGroupsAdvice(
    plan, plan.AutomaticCellSize ? 1.0 : plan.Options.CellSizeFactor, "its cells are too coarse for each group");
  if (!groups.empty()) // not flat: far apart
  {
    return Status::invalidArgument("the grid's cells are too coarse for the objects. " + groups);
  }
  const double scale = plan.Box.Scale;
  std::ostringstream m;
  m << "the cloud is flat: every point lies within " << fit.Thickness * scale << " of the "
    << (D == 3 ? "plane" : "line") << " through (";
  for (int a = 0; a < D; ++a)
  {
    m << (a ? ", " : "") << plan.Box.Centre[a] + scale * fit.Centre[a];
  }
  m << ") with normal (";
  for (int a = 0; a < D; ++a)
  {
    m << (a ? ", " : "") << fit.Normal[a];
  }
  m << "), less than half the finest cell (" << dx * scale << "), so it encloses no volume the grid can resolve "
    << "and no K_P or eta can help. ";
  if (D == 3)
  {
    m << "For a planar outline, rotate the points into a plane z = constant (a 2D reconstruction); for a thin "
         "object, a smaller C_dx (a finer grid)";
  }
  else
  {
    m << "For a thin object, use a smaller C_dx (a finer grid)";
  }
  return Status::invalidArgument(m.str());
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

Status validateOptionRanges(const ReconstructionOptions& options)
{
  SLTK_RETURN_IF_ERROR(
    checkOptionRange(InitialGuessRange, static_cast<int>(options.Guess), InitialGuessRange.Property));
  InterpolatorKind kind{};
  if (options.Interpolator)
  {
    SLTK_RETURN_IF_ERROR(interpolatorOfCode(static_cast<int>(*options.Interpolator), kind));
  }
  const std::pair<const char*, double> values[] = {
    { "NumberOfRuns", static_cast<double>(options.Runs) },
    { "MaximumNumberOfIterations", static_cast<double>(options.MaxIterations) }, { "Tolerance", options.Tolerance },
    { "Padding", static_cast<double>(options.Padding) }, { "FinalEta", options.FinalEta },
    { "OutlierDeviations", options.Cleaning.Outliers.Deviations },
    { "ThinningFactor", options.Cleaning.ThinningFactor }, { "CellSizeFactor", options.CellSizeFactor },
    { "MaximumLevel", static_cast<double>(options.MaximumLevel) },
    { "OutsideThresholdFactor", options.OutsideThresholdFactor },
    { "MemoryBudget",
      static_cast<double>(options.MemoryBudget) / static_cast<double>(BytesPerMB) }, // as the front ends give it
  };
  for (const auto& value : values)
  {
    SLTK_RETURN_IF_ERROR(checkOptionRange(*findOptionRange(value.first), value.second, value.first));
  }
  return validateSchedule(options.Schedule);
}

template <int D>
Status validateReconstructionOptions(const ReconstructionOptions& options)
{
  if (options.Runs < 1 || options.MaxIterations < 1 || options.MinIterations < 0 || options.EnergyWindow < 1 ||
    !(options.OutsideThresholdFactor >= 0.0) || !(options.CellSizeFactor >= 0.0) ||
    !std::isfinite(options.OutsideThresholdFactor) || !std::isfinite(options.CellSizeFactor) ||
    !(options.Tolerance >= 0.0) || options.ReinitDilation < 1 || !(options.BetaFactor > 0.0) ||
    !(options.GammaFactor > options.BetaFactor))
  {
    return Status::invalidArgument("reconstruction options out of range: need runs >= 1, iterations >= 1, "
                                   "K_P >= 0 and C_dx >= 0 (0: automatic), tolerance >= 0, 0 < beta < gamma");
  }
  const auto automaticOr = [](double v, double low, double high) { return v == 0.0 || (v >= low && v <= high); };
  const double* cdx = CellSizeFactorRange;
  const double* kp = OutsideThresholdFactorRange;
  if (!automaticOr(options.CellSizeFactor, cdx[0], cdx[1]) ||
    !automaticOr(options.OutsideThresholdFactor, kp[0], kp[1]))
  {
    std::ostringstream m;
    m << "C_dx = " << options.CellSizeFactor << ", K_P = " << options.OutsideThresholdFactor << ": C_dx must be 0 "
      << "(automatic) or in [" << cdx[0] << ", " << cdx[1] << "], K_P 0 (automatic) or in [" << kp[0] << ", " << kp[1]
      << "]";
    return Status::invalidArgument(m.str());
  }
  if (options.MaximumLevel != 0 &&
    (options.MaximumLevel < MaximumLevelRange[0] || options.MaximumLevel > MaximumLevelRange[1]))
  {
    std::ostringstream m;
    m << "MaximumLevel (--max-level) = " << options.MaximumLevel << " is outside [" << MaximumLevelRange[0] << ", "
      << MaximumLevelRange[1] << "]: give a level in it, or 0 for C_dx";
    return Status::invalidArgument(m.str());
  }
  if (options.MaximumLevel != 0 && options.CellSizeFactor > 0.0)
  {
    std::ostringstream m;
    m << "MaximumLevel (--max-level) = " << options.MaximumLevel << " and C_dx = " << options.CellSizeFactor
      << ": give the finest level or C_dx, not both (0 turns either off)";
    return Status::invalidArgument(m.str());
  }
  if (options.MaximumLevel != 0 && options.MaximumLevel < options.Runs - 1)
  {
    std::ostringstream m;
    m << "MaximumLevel (--max-level) = " << options.MaximumLevel << " with " << options.Runs
      << " runs puts run 1 below level 0 (5.10: L0 = L - R + 1): use MaximumLevel >= " << options.Runs - 1
      << " or fewer runs";
    return Status::invalidArgument(m.str());
  }
  SLTK_RETURN_IF_ERROR(validateSchedule(options.Schedule));
  return options.Reinit.validate<D>();
}

namespace
{
/// C_dx from the finest level asked (GridPlan.h), refused when it leaves C_dx's range.
template <int D>
Status cellSizeFromLevel(const CloudPoints<D>& points, ReconstructionPlan<D>& plan)
{
  const int level = plan.Options.MaximumLevel, runs = plan.Options.Runs;
  const double edge = points.box().largestExtent();
  const double cdx = cellSizeFactorForLevel(level, runs, edge, plan.CloudSpacing);
  if (!(cdx >= CellSizeFactorRange[0] && cdx <= CellSizeFactorRange[1]))
  {
    std::ostringstream m;
    m << "MaximumLevel (--max-level) = " << level << " with " << runs << " runs gives C_dx = " << cdx
      << " (the cloud is " << planNumber(edge / plan.CloudSpacing) << " h_P across), outside ["
      << CellSizeFactorRange[0] << ", " << CellSizeFactorRange[1] << "]: use MaximumLevel "
      << std::max({ MaximumLevelRange[0], runs - 1,
           levelForCellSizeFactor(CellSizeFactorRange[1], runs, edge, plan.CloudSpacing) + 1 })
      << "-" << levelForCellSizeFactor(CellSizeFactorRange[0], runs, edge, plan.CloudSpacing);
    return Status::invalidArgument(m.str());
  }
  plan.Options.CellSizeFactor = cdx;
  plan.Choices.push_back("C_dx = " + planNumber(cdx) + " from the given MaximumLevel " + std::to_string(level) +
    ": the finest cell is the cloud's extent / 2^" + std::to_string(level) + ", run 1 at level " +
    std::to_string(level - runs + 1) + " (5.10)");
  return Status::ok();
}

/// A plan from a level refused for memory (`refusal`): the refusal with its
/// advice replaced by the finest level that fits, found by planning every
/// coarser level in C_dx's range (a level's C_dx extrapolation misses the
/// padding and the ghost rows, which do not shrink with the cell).
template <int D>
Status withFittingLevel(const ReconstructionPlan<D>& plan, const Status& refusal)
{
  const int runs = plan.Options.Runs;
  const double edge = boundingBox(plan.Cloud).largestExtent();
  const int coarsest = std::max({ MaximumLevelRange[0], runs - 1,
    levelForCellSizeFactor(CellSizeFactorRange[1], runs, edge, plan.CloudSpacing) + 1 });
  int fits = 0;
  for (int level = plan.Options.MaximumLevel - 1; level >= coarsest && fits == 0; --level)
  {
    GridPlan<D> grids;
    fits =
      planRunGrids(plan, runs, cellSizeFactorForLevel(level, runs, edge, plan.CloudSpacing), grids).isOk() ? level : 0;
  }
  const std::string& message = refusal.message();
  const size_t use = message.find(": use C_dx >= ");
  std::ostringstream m;
  m << message.substr(0, use) << ": ";
  if (fits > 0)
  {
    m << "use MaximumLevel (--max-level) <= " << fits << ", the finest level that fits, or fewer runs";
  }
  else
  {
    m << "no MaximumLevel of " << coarsest << "-" << plan.Options.MaximumLevel
      << " fits: use fewer runs or a larger memory budget";
  }
  return Status::outOfMemory(m.str());
}

/// An automatic interpolator from the cloud's noise, measured before any thinning
/// (AutomaticParameters.h, AutomaticInterpolatorNoise).
template <int D>
Status chooseInterpolator(const CloudPoints<D>& points, ReconstructionPlan<D>& plan, const Context& ctx)
{
  plan.CloudNoise = -1.0;
  if (plan.Options.Interpolator)
  {
    return Status::ok();
  }
  double noise = 0.0;
  if (!points.noise(plan.CloudSpacing, ctx, noise).isOk())
  {
    plan.Options.Interpolator = InterpolatorKind::Weno3; // too few points to tell
    plan.Choices.push_back("interpolator weno3: too few points to measure the noise");
    return Status::ok();
  }
  plan.CloudNoise = noise;
  const bool clean = noise < AutomaticInterpolatorNoise;
  plan.Options.Interpolator = clean ? InterpolatorKind::LeastSquaresQ1 : InterpolatorKind::Weno3;
  plan.Choices.push_back(std::string("interpolator ") + interpolatorInfo(*plan.Options.Interpolator).Name +
    ": the cloud's noise is " + planNumber(noise) + " h_P, " + (clean ? "below " : "not below ") +
    planNumber(AutomaticInterpolatorNoise) + " h_P" +
    (clean ? " (the least-squares Q1 (5.5); --interpolator weno3 for the thesis's)"
           : " (WENO3 damps the noise the least-squares Q1 follows)"));
  return Status::ok();
}

/// An automatic C_dx: 1, or the smallest that fits the budget (AutomaticParameters.h).
template <int D>
Status chooseCellSize(const CloudPoints<D>& points, ReconstructionPlan<D>& plan, const GridPlanOptions& po)
{
  double cdx = 1.0;
  SLTK_RETURN_IF_ERROR(chooseCellSizeFactor(points.box(), plan.CloudSpacing, po, cdx));
  plan.Options.CellSizeFactor = cdx;
  return Status::ok();
}

/// Automatic thinning of a cloud denser than its finest grid (AutomaticParameters.h).
template <int D>
Status thinIfDenserThanGrid(
  CloudPoints<D>& points, ReconstructionPlan<D>& plan, const GridPlanOptions& po, const Context& ctx)
{
  CloudSpacingOptions so;
  so.DensityNeighbours = plan.Options.Cleaning.DensityNeighbours;
  double density = 0.0;
  if (points.size() <= so.DensityNeighbours || !points.spacing(ctx, so, density).isOk())
  {
    return Status::ok();
  }
  const double finestDx = plan.Options.CellSizeFactor * plan.CloudSpacing / std::ldexp(1.0, plan.Options.Runs - 1);
  if (!(density < finestDx))
  {
    return Status::ok();
  }
  const std::int64_t before = points.size();
  SLTK_RETURN_IF_ERROR(points.thin(AutomaticThinningFactor * density));
  // The thinned cloud in the unit box of its own box (4.5), as placeInUnitBox puts it after
  // moving it back to the user's units, with one change of units (one move to the owners): toUser
  // is increasing along every axis, so it maps the box in unit-box units onto the box in the
  // user's, and each point takes toUser's value, rounded, before toUnit's, as two steps give it.
  const UnitBox<D> from = plan.Box;
  const Box<D> unitBox = points.box();
  const UnitBox<D> to(Box<D>{ from.toUser(unitBox.Min), from.toUser(unitBox.Max) });
  SLTK_RETURN_IF_ERROR(
    points.transform([&from, &to](const std::array<double, D>& p) { return to.toUnit(from.toUser(p)); }));
  plan.Cleaning.AutomaticThinning = true;
  plan.Cleaning.ThinningCell = AutomaticThinningFactor * density * from.Scale;
  plan.Cleaning.OutputPoints = points.size();
  plan.Choices.push_back("thinning: the density spacing " + planNumber(density * plan.Box.Scale) +
    " is below the finest cell " + planNumber(finestDx * plan.Box.Scale) + ", so the cloud is averaged over cells of " +
    planNumber(AutomaticThinningFactor) + " density spacings: " + std::to_string(before) + " -> " +
    std::to_string(points.size()) + " points (--no-cleaning keeps every point)");
  plan.Box = to;
  SLTK_RETURN_IF_ERROR(points.spacing(ctx, CloudSpacingOptions{}, plan.CloudSpacing)); // h_P (4.36)
  return chooseCellSize(points, plan, po);
}
} // namespace

namespace
{
/// A refusal for memory (`refusal`) of a cloud made of a few groups of points far apart
/// (two scanned objects in one file) says so, with separateGroupsAdvice.
template <int D>
Status withSeparateRuns(const ReconstructionPlan<D>& plan, const Status& refusal)
{
  if (refusal.code() != StatusCode::OutOfMemory || !(plan.Options.CellSizeFactor > 0.0))
  {
    return refusal;
  }
  const std::string advice = separateGroupsAdvice(plan, plan.Options.CellSizeFactor, "a coarser grid would lose them");
  return advice.empty() ? refusal : Status::outOfMemory(refusal.message() + ". " + advice);
}
} // namespace

namespace
{
template <int D>
void resetPlan(const ReconstructionOptions& options, ReconstructionPlan<D>& plan)
{
  plan.Locator.reset();
  plan.Cloud = PointCloud<D>();
  plan.Cleaning = CloudCleaningReport{};
  plan.CloudSpacing = 0.0;
  plan.InitialEllipsoid.reset();
  plan.Grids = GridPlan<D>{};
  plan.Options = options;
  plan.Choices.clear();
  plan.Enclosure.reset();
  plan.PointsHeldMax = 0;
  plan.Traffic = CommTraffic{};
  plan.Sparsity.clear();
}

/// Steps 1-5 on `points` up to the automatic C_dx and thinning: what reads the
/// cloud before the whole of it is needed (the validation, the cleaning, the
/// unit box, h_P, the noise, the density spacing, the local offset's rho), on the whole cloud or on
/// its owners alike; then the cloud and its locator in the plan. `options`: as
/// given (plan.Options takes the automatic choices).
template <int D>
Status prepareCloud(CloudPoints<D>& points, const ReconstructionOptions& options, const Context& ctx,
  GridPlanOptions& po, ReconstructionPlan<D>& plan)
{
  SLTK_RETURN_IF_ERROR(checkAndCleanCloud(points, options.Cleaning, ctx, plan.Cleaning));
  if (plan.Cleaning.AutomaticOutliers)
  {
    plan.Choices.push_back("outliers: gross ones found, " + std::to_string(plan.Cleaning.OutliersRemoved) +
      " points removed (3 sigma; --no-cleaning keeps them)");
  }
  SLTK_RETURN_IF_ERROR(placeInUnitBox(points, ctx, plan.Box, plan.CloudSpacing));
  SLTK_RETURN_IF_ERROR(chooseInterpolator(points, plan, ctx));

  const bool automaticCellSize = !(options.CellSizeFactor > 0.0) && options.MaximumLevel == 0;
  plan.AutomaticCellSize = automaticCellSize;
  plan.BudgetIsAutomatic = automaticCellSize && !options.MemoryBudget;
  if (options.MaximumLevel > 0)
  {
    SLTK_RETURN_IF_ERROR(cellSizeFromLevel(points, plan));
  }
  po.Runs = options.Runs;
  po.Padding = options.Padding;
  po.BytesPerNode = ReconstructionBytesPerNode;
  po.MemoryBudget = options.MemoryBudget ? options.MemoryBudget : automaticCellSize ? AutomaticMemoryBudget : 0;
  if (automaticCellSize)
  {
    SLTK_RETURN_IF_ERROR(chooseCellSize(points, plan, po));
    if (automaticCleaning(options.Cleaning))
    {
      SLTK_RETURN_IF_ERROR(thinIfDenserThanGrid(points, plan, po, ctx));
    }
  }
  if (options.LocalOffset && options.Guess == InitialGuess::OutsideMarking)
  {
    // rho of the local offset (LocalOffset.h), on the owners when the cloud is spread over the ranks.
    SLTK_RETURN_IF_ERROR(points.sparsity(options.Cleaning.DensityNeighbours, ctx, plan.Sparsity));
  }
  return points.release(plan.Cloud, ReconstructionPointsPerBucket, plan.Locator);
}

/// Steps 5-7 on the plan's whole cloud: the C_dx of the ranks' windows, K_P,
/// run 1's surface, the grids and the memory check.
template <int D>
Status planOnWholeCloud(
  const ReconstructionOptions& options, const Context& ctx, const GridPlanOptions& po, ReconstructionPlan<D>& plan)
{
  if (plan.AutomaticCellSize)
  {
    const double oneRank = plan.Options.CellSizeFactor;
    SLTK_RETURN_IF_ERROR(fitWindowsOnThisMachine(plan, po));
    plan.Choices.push_back(cellSizeChoice(plan, po.MemoryBudget, oneRank));
  }
  const double dx1 = plan.Options.CellSizeFactor * plan.CloudSpacing; // run 1 (4.36)
  const Box<D> bounds = boundingBox(plan.Cloud);
  const double sparsest = plan.Sparsity.empty() ? 1.0 : *std::max_element(plan.Sparsity.begin(), plan.Sparsity.end());
  double roomFactor = plan.Options.OutsideThresholdFactor;
  if (!(options.OutsideThresholdFactor > 0.0))
  {
    plan.Options.OutsideThresholdFactor = 2.0; // the thesis's default for the sphere/ellipsoid margins
    if (options.Guess == InitialGuess::OutsideMarking)
    {
      OutsideFactorChoice choice;
      SLTK_RETURN_IF_ERROR(
        chooseOutsideFactor(*plan.Locator, bounds, plan.CloudSpacing, dx1, plan.Sparsity, ctx, choice));
      plan.Options.OutsideThresholdFactor = choice.Factor;
      const auto& ladder = outsideFactorLadder();
      const size_t best = static_cast<size_t>(std::find(ladder.begin(), ladder.end(), choice.Factor) - ladder.begin());
      std::string why = "no holes to bridge";
      if (best > choice.FirstRung)
      {
        why = "K_P = " + planNumber(ladder[best - 1]) + " encloses " + std::to_string(choice.EnclosedNodes[best - 1]) +
          ": the sampling has holes it does not bridge";
      }
      else if (choice.FirstRung > 0)
      {
        why = "K_P below " + planNumber(ladder[choice.FirstRung]) +
          " would put the initial surface less than two of run 1's cells (2 C_dx = " +
          planNumber(2.0 * plan.Options.CellSizeFactor) + " h_P) from the cloud";
      }
      plan.Choices.push_back("K_P = " + planNumber(choice.Factor) + ": its initial surface encloses " +
        std::to_string(choice.EnclosedNodes[best]) + " nodes of a " + std::to_string(choice.ProbeNodes) +
        "-node grid, the most of K_P = " + planNumber(ladder[choice.FirstRung]) + "..32 (" + why + ")");
      plan.Enclosure = std::move(choice);
    }
    roomFactor = outsideFactorWithRestart(plan.Options.OutsideThresholdFactor);
  }
  for (const std::string& choice : plan.Choices)
  {
    ctx.logger().log(LogLevel::Info, "automatic " + choice);
  }

  const double farDistance = plan.Options.OutsideThresholdFactor * plan.CloudSpacing; // K_P h_P (4.4.4)
  if (options.Guess == InitialGuess::BoundingSphere)
  {
    plan.InitialEllipsoid = boundingSphere(plan.Cloud, farDistance);
  }
  else if (options.Guess == InitialGuess::BoundingEllipsoid)
  {
    plan.InitialEllipsoid = boundingEllipsoid(plan.Cloud, farDistance);
  }
  plan.Options.MemoryBudget = po.MemoryBudget;
  // Run 1 must hold the initial surface (at the K_P of a restart, when automatic).
  plan.FirstRunReach =
    initialReach(bounds, sparsest * std::max(farDistance, roomFactor * plan.CloudSpacing), plan.InitialEllipsoid);
  const Status planned = planFittingRunGrids(plan, ctx);
  if (planned.code() == StatusCode::OutOfMemory && options.MaximumLevel > 0)
  {
    return withSeparateRuns(plan, withFittingLevel(plan, planned));
  }
  SLTK_RETURN_IF_ERROR(withSeparateRuns(plan, planned));
  return refuseFlatCloud(plan, ctx);
}
} // namespace

template <int D>
Status planReconstruction(
  PointCloud<D> cloud, const ReconstructionOptions& options, const Context& ctx, ReconstructionPlan<D>& plan)
{
  resetPlan(options, plan);
  plan.Cloud = std::move(cloud);
  plan.PointsHeldMax = plan.Cloud.size();
  SLTK_RETURN_IF_ERROR(validateReconstructionOptions<D>(options));
  WholeCloud<D> points(plan.Cloud, ReconstructionPointsPerBucket);
  GridPlanOptions po;
  SLTK_RETURN_IF_ERROR(prepareCloud<D>(points, options, ctx, po, plan));
  return planOnWholeCloud(options, ctx, po, plan);
}

template <int D>
Status planReconstructionOnRanks(PointCloud<D> share, std::int64_t firstId, const ReconstructionOptions& options,
  const Context& ctx, const Communicator& comm, ReconstructionPlan<D>& plan)
{
  resetPlan(options, plan);
  SLTK_RETURN_IF_ERROR(validateReconstructionOptions<D>(options));
  const CountingCommunicator counted(comm);                           // the plan's traffic
  SLTK_RETURN_IF_ERROR(validateCloudShares(share, firstId, counted)); // before a NaN could meet the cuts
  OwnedCloud<D> points(counted);
  SLTK_RETURN_IF_ERROR(points.own(share, firstId));
  share = PointCloud<D>(); // at its owners now
  GridPlanOptions po;
  const Status prepared = prepareCloud<D>(points, options, ctx, po, plan);
  plan.PointsHeldMax = points.heldMax(); // collective: every rank gets here (the steps fail on every rank alike)
  SLTK_RETURN_IF_ERROR(prepared);
  const Status planned = planOnWholeCloud(options, ctx, po, plan);
  plan.Traffic = counted.traffic();
  return planned;
}

template Status validateReconstructionOptions<2>(const ReconstructionOptions&);
template Status validateReconstructionOptions<3>(const ReconstructionOptions&);
template Status planReconstruction(PointCloud<2>, const ReconstructionOptions&, const Context&, ReconstructionPlan<2>&);
template Status planReconstruction(PointCloud<3>, const ReconstructionOptions&, const Context&, ReconstructionPlan<3>&);
template Status planReconstructionOnRanks(PointCloud<2>, std::int64_t, const ReconstructionOptions&, const Context&,
  const Communicator&, ReconstructionPlan<2>&);
template Status planReconstructionOnRanks(PointCloud<3>, std::int64_t, const ReconstructionOptions&, const Context&,
  const Communicator&, ReconstructionPlan<3>&);

} // namespace sltk
