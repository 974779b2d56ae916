// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/ReconstructionPlan.h"

#include "sltk/cloud/CloudNoise.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/CloudThickness.h"
#include "sltk/cloud/CloudThinning.h"
#include "sltk/cloud/LocalSpacing.h"
#include "sltk/exec/Memory.h"
#include "sltk/octree/TiledField.h"
#include "sltk/octree/TiledMemory.h"
#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/CloudInitialData.h"
#include "sltk/recon/CloudPreparation.h"
#include "sltk/recon/SlabPolicy.h"
#include "sltk/recon/StrayPoints.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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
std::string number(double value)
{
  std::ostringstream s;
  s.precision(3);
  s << value;
  return s.str();
}

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
      << " (the cloud is " << number(edge / plan.CloudSpacing) << " h_P across), outside [" << CellSizeFactorRange[0]
      << ", " << CellSizeFactorRange[1] << "]: use MaximumLevel "
      << std::max({ MaximumLevelRange[0], runs - 1,
           levelForCellSizeFactor(CellSizeFactorRange[1], runs, edge, plan.CloudSpacing) + 1 })
      << "-" << levelForCellSizeFactor(CellSizeFactorRange[0], runs, edge, plan.CloudSpacing);
    return Status::invalidArgument(m.str());
  }
  plan.Options.CellSizeFactor = cdx;
  plan.Choices.push_back("C_dx = " + number(cdx) + " from the given MaximumLevel " + std::to_string(level) +
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
    ": the cloud's noise is " + number(noise) + " h_P, " + (clean ? "below " : "not below ") +
    number(AutomaticInterpolatorNoise) + " h_P" +
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
  plan.Choices.push_back("thinning: the density spacing " + number(density * plan.Box.Scale) +
    " is below the finest cell " + number(finestDx * plan.Box.Scale) + ", so the cloud is averaged over cells of " +
    number(AutomaticThinningFactor) + " density spacings: " + std::to_string(before) + " -> " +
    std::to_string(points.size()) + " points (--no-cleaning keeps every point)");
  plan.Box = to;
  SLTK_RETURN_IF_ERROR(points.spacing(ctx, CloudSpacingOptions{}, plan.CloudSpacing)); // h_P (4.36)
  return chooseCellSize(points, plan, po);
}

/// What the windows of the ranks on this machine may take: the budget given,
/// else the memory available (the least over the ranks when the front end
/// agreed it, Options.MemoryAvailable). The automatic 1 GiB is no limit: it
/// sized the whole grid.
template <int D>
double slabMemoryLimit(const ReconstructionPlan<D>& plan)
{
  if (plan.Options.MemoryBudget && !plan.BudgetIsAutomatic)
  {
    return static_cast<double>(plan.Options.MemoryBudget);
  }
  return static_cast<double>(plan.Options.MemoryAvailable ? plan.Options.MemoryAvailable : availableMemoryBytes());
}

/// The largest window, in nodes, of every run of `grids` split over
/// plan.Options.Ranks ranks: the boundaries RunSlab.h cuts (SlabPolicy.h), a
/// later run's widest windows as its cuts follow the previous run's band.
/// `whole`: the largest grid's nodes.
template <int D>
double largestWindowNodes(const ReconstructionPlan<D>& plan, const GridPlan<D>& grids, double& whole)
{
  double window = 0.0;
  whole = 0.0;
  std::vector<Index> boundaries;
  for (size_t r = 0; r < grids.Runs.size(); ++r)
  {
    const std::vector<Index> previous = std::move(boundaries);
    boundaries = slabBoundaries(
      grids.Runs[r], plan.Options.Ranks, plan.Cloud, r > 0 ? &grids.Runs[r - 1] : nullptr, r > 0 ? &previous : nullptr);
    window = std::max(window,
      r > 0 ? largestLaterSlabWindowNodes(grids.Runs[r], grids.Runs[r - 1], previous)
            : largestSlabWindowNodes(grids.Runs[r], boundaries));
    whole = std::max(whole, static_cast<double>(grids.Runs[r].nodeCount()));
  }
  return window;
}

/// An automatic C_dx split over ranks (beyond the thesis; Distributed.md,
/// "The automatic C_dx under MPI"). The one-rank C_dx (the whole finest grid within the budget)
/// is kept while the windows of the ranks on this machine, ghost rows included,
/// fit slabMemoryLimit: every rank count then runs the one-rank grids. Else C_dx
/// climbs chooseCellSizeFactor's 2% ladder to the smallest whose windows fit (a
/// coarser grid than one rank's, said in the choice) rather than refuse what
/// one rank runs. `po`: the grid options the one-rank C_dx was chosen with.
template <int D>
Status fitWindowsOnThisMachine(ReconstructionPlan<D>& plan, GridPlanOptions po)
{
  if (plan.Options.Ranks <= 1 || plan.Options.OctreeStorage)
  {
    return Status::ok(); // one rank: the whole grid is its window
  }
  const double limit = slabMemoryLimit(plan);
  if (!(limit > 0.0))
  {
    return Status::ok();
  }
  const double here = std::max(1, plan.Options.RanksHere);
  po.MemoryBudget = std::numeric_limits<std::uint64_t>::max(); // the windows, not the whole grid
  for (double c = plan.Options.CellSizeFactor; c <= CellSizeFactorRange[1]; c *= CellSizeLadderStep)
  {
    po.CellSizeFactor = c;
    GridPlan<D> grids;
    SLTK_RETURN_IF_ERROR(planGrids(boundingBox(plan.Cloud), plan.CloudSpacing, po, grids));
    double whole = 0.0;
    if (largestWindowNodes(plan, grids, whole) * here * ReconstructionBytesPerNode <= limit)
    {
      plan.Options.CellSizeFactor = c;
      return Status::ok();
    }
  }
  return Status::ok(); // nothing fits: the memory check refuses with its advice
}

/// The log line of an automatic C_dx: the one-rank choice `oneRank`, or the
/// coarser one the ranks on this machine needed (fitWindowsOnThisMachine).
template <int D>
std::string cellSizeChoice(const ReconstructionPlan<D>& plan, std::uint64_t budget, double oneRank)
{
  const double cdx = plan.Options.CellSizeFactor;
  if (cdx == oneRank)
  {
    return "C_dx = " + number(cdx) +
      (cdx > 1.0
          ? ": the smallest whose finest grid fits the " + std::to_string(budget >> 20) + " MB budget (--memory-budget)"
          : ": the thesis's default, within the memory budget");
  }
  const bool given = plan.Options.MemoryBudget && !plan.BudgetIsAutomatic;
  return "C_dx = " + number(cdx) + ": the smallest whose windows on " + std::to_string(plan.Options.Ranks) +
    " ranks, ghost rows included, fit the " + std::to_string(static_cast<std::uint64_t>(slabMemoryLimit(plan)) >> 20) +
    " MB " + (given ? "budget (--memory-budget)" : "available") + " for the " +
    std::to_string(std::max(1, plan.Options.RanksHere)) +
    " rank(s) on this machine; one rank would take C_dx = " + number(oneRank) +
    ", so the grids and the surface differ from one rank's (ranks on more machines" +
    (given ? " or a larger budget" : " or more memory") + " give one rank's)";
}

/// planRunGrids; with an automatic C_dx split over ranks, the ladder climbed on
/// from fitWindowsOnThisMachine's C_dx while the windows do not fit: that one
/// could not size run 1's padding for its initial surface (K_P is chosen
/// after C_dx), which moves the later runs' cuts by a row or two.
template <int D>
Status planFittingRunGrids(ReconstructionPlan<D>& plan, const Context& ctx)
{
  const Status planned = planRunGrids(plan, plan.Options.Runs, plan.Options.CellSizeFactor, plan.Grids);
  if (planned.code() != StatusCode::OutOfMemory || !plan.AutomaticCellSize || plan.Options.Ranks <= 1 ||
    plan.Options.OctreeStorage)
  {
    return planned;
  }
  for (double c = plan.Options.CellSizeFactor * CellSizeLadderStep; c <= CellSizeFactorRange[1];
       c *= CellSizeLadderStep)
  {
    if (planRunGrids(plan, plan.Options.Runs, c, plan.Grids).isOk())
    {
      plan.Choices.push_back("C_dx = " + number(c) + " rather than " + number(plan.Options.CellSizeFactor) +
        ": run 1's padding for its initial surface widens the windows of the ranks on this machine");
      ctx.logger().log(LogLevel::Info, "automatic " + plan.Choices.back());
      plan.Options.CellSizeFactor = c;
      return Status::ok();
    }
  }
  return planned; // nothing fits: the first refusal, with its advice
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
}

/// Steps 1-5 on `points` up to the automatic C_dx and thinning: what reads the
/// cloud before the whole of it is needed (the validation, the cleaning, the
/// unit box, h_P, the noise, the density spacing), on the whole cloud or on
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
  if (options.LocalOffset && options.Guess == InitialGuess::OutsideMarking)
  {
    SLTK_RETURN_IF_ERROR(sparsityFactors(*plan.Locator, options.Cleaning.DensityNeighbours, ctx, plan.Sparsity));
  }
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
        why = "K_P = " + number(ladder[best - 1]) + " encloses " + std::to_string(choice.EnclosedNodes[best - 1]) +
          ": the sampling has holes it does not bridge";
      }
      else if (choice.FirstRung > 0)
      {
        why = "K_P below " + number(ladder[choice.FirstRung]) +
          " would put the initial surface less than two of run 1's cells (2 C_dx = " +
          number(2.0 * plan.Options.CellSizeFactor) + " h_P) from the cloud";
      }
      plan.Choices.push_back("K_P = " + number(choice.Factor) + ": its initial surface encloses " +
        std::to_string(choice.EnclosedNodes[best]) + " nodes of a " + std::to_string(choice.ProbeNodes) +
        "-node grid, the most of K_P = " + number(ladder[choice.FirstRung]) + "..32 (" + why + ")");
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
  SLTK_RETURN_IF_ERROR(validateCloudShares(share, firstId, comm)); // before a NaN could meet the cuts
  OwnedCloud<D> points(comm);
  SLTK_RETURN_IF_ERROR(points.own(share, firstId));
  share = PointCloud<D>(); // at its owners now
  GridPlanOptions po;
  const Status prepared = prepareCloud<D>(points, options, ctx, po, plan);
  plan.PointsHeldMax = points.heldMax(); // collective: every rank gets here (the steps fail on every rank alike)
  SLTK_RETURN_IF_ERROR(prepared);
  return planOnWholeCloud(options, ctx, po, plan);
}

namespace
{
/// The memory check of grids split over plan.Options.Ranks ranks: the largest
/// window of every run (SlabPolicy.h, the boundaries RunSlab.h will cut) times
/// the ranks on this machine, against the budget given, or else the memory
/// available, naming the C_dx that would fit. The automatic budget is not a
/// limit here: it chose the whole grid's C_dx as on one rank (so any rank count
/// runs the same grids), and the windows with their ghost rows hold more.
template <int D>
Status checkSlabMemory(const ReconstructionPlan<D>& plan, double cellSizeFactor, GridPlan<D>& grids)
{
  const int ranks = plan.Options.Ranks, here = std::max(1, plan.Options.RanksHere);
  double whole = 0.0;
  const double window = largestWindowNodes(plan, grids, whole);
  const double budget = slabMemoryLimit(plan);
  const double need = window * here * ReconstructionBytesPerNode;
  if (budget > 0.0 && need > budget)
  {
    // The node count scales as C_dx^-D: the factor that fits with 10% headroom.
    const double fit = cellSizeFactor * std::pow(need / (0.9 * budget), 1.0 / D);
    std::ostringstream m;
    m << "the largest grid (of " << grids.Runs.size() << " runs, " << whole << " nodes) split over " << ranks
      << " ranks leaves the " << here << " rank(s) on this machine windows of up to " << window << " nodes each, about "
      << need / 1e9 << " GB together, more than the " << budget / 1e9 << " GB available: use C_dx >= " << fit
      << ", fewer runs, or the ranks on more machines";
    grids.Runs.clear();
    return Status::outOfMemory(m.str());
  }
  return Status::ok();
}
} // namespace

namespace
{
/// The slots of tiles over `grid` (one per TileEdge^D nodes).
template <int D>
double slotCount(const GridSpec<D>& grid)
{
  return static_cast<double>(grid.nodeCount()) / static_cast<double>(tileNodes<D>());
}

/// The tiled reconstruction's memory (OctreeStorage): run 1's uniform grid and
/// the finest run's tiles (their slots, then the nodes estimated from the
/// cloud, TiledMemory.h), against `budget` (0: none).
template <int D>
double tiledNeedBytes(const ReconstructionPlan<D>& plan, const GridPlan<D>& grids, double budget)
{
  const GridSpec<D>& finest = grids.Runs.back();
  const double first = static_cast<double>(grids.Runs.front().nodeCount()) * ReconstructionBytesPerNode;
  const double slots = slotCount(finest);
  if (budget > 0.0 && 5.0 * slots > budget) // the count itself would not fit
  {
    return first + 5.0 * slots; // a slot: its int32 entry, and a byte while the tiles are counted
  }
  return first + 4.0 * slots + estimatedTiledNodes(plan.Cloud, finest) * TiledBytesPerStoredNode;
}

template <int D>
double memoryBudgetBytes(const ReconstructionPlan<D>& plan)
{
  return plan.Options.MemoryBudget ? static_cast<double>(plan.Options.MemoryBudget)
                                   : static_cast<double>(availableMemoryBytes());
}

} // namespace

template <int D>
GridPlanOptions runGridOptions(const ReconstructionPlan<D>& plan, int runs, double cellSizeFactor)
{
  GridPlanOptions po;
  po.Runs = runs;
  po.CellSizeFactor = cellSizeFactor;
  po.Padding = plan.Options.Padding;
  po.BytesPerNode = ReconstructionBytesPerNode;
  po.MemoryBudget = plan.Options.MemoryBudget;
  const double dx1 = cellSizeFactor * plan.CloudSpacing; // (4.36)
  po.FirstRunPadding = static_cast<int>(std::ceil(plan.FirstRunReach / dx1 + plan.Options.GammaFactor + 2.0));
  return po;
}

/// With OctreeStorage: tiledNeedBytes must fit. A refusal names the smallest
/// C_dx, in steps of 5% up to the range's end, whose plan fits with 10%
/// headroom: the need is run 1's grid and the slots (C_dx^-D) plus the tiles
/// (C_dx^-(D-1)), so no single power predicts it.
template <int D>
Status checkTiledMemory(const ReconstructionPlan<D>& plan, double cellSizeFactor, GridPlan<D>& grids)
{
  const double budget = memoryBudgetBytes(plan);
  const double need = tiledNeedBytes(plan, grids, budget);
  if (budget > 0.0 && need > budget)
  {
    const int runs = static_cast<int>(grids.Runs.size());
    double fit = 0.0;
    for (double c = cellSizeFactor * 1.05; fit == 0.0 && c <= CellSizeFactorRange[1]; c *= 1.05)
    {
      GridPlanOptions po = runGridOptions(plan, runs, c);
      po.MemoryBudget = std::numeric_limits<std::uint64_t>::max();
      GridPlan<D> coarser;
      fit = planGrids(boundingBox(plan.Cloud), plan.CloudSpacing, po, coarser).isOk() &&
          tiledNeedBytes(plan, coarser, budget) <= 0.9 * budget
        ? c
        : 0.0;
    }
    std::ostringstream m;
    m << "the octree reconstruction (" << runs << " runs, the finest grid " << grids.Runs.back().nodeCount()
      << " nodes) would need about " << need / 1e9 << " GB for run 1's grid and the finest run's tiles, more than the "
      << budget / 1e9 << " GB available: ";
    if (fit > 0.0)
    {
      m << "use C_dx >= " << fit << " or fewer runs";
    }
    else
    {
      m << "no C_dx up to " << CellSizeFactorRange[1] << " fits with " << runs << " runs: use fewer runs";
    }
    grids.Runs.clear();
    return Status::outOfMemory(m.str());
  }
  return Status::ok();
}

namespace
{
/// A uniform plan refused for memory (`refusal`): where the tiled storage
/// would fit (2D or 3D), the refusal says so, with its estimate.
template <int D>
Status withTiledAlternative(const ReconstructionPlan<D>& plan, GridPlanOptions po, const Status& refusal)
{
  if (refusal.code() != StatusCode::OutOfMemory)
  {
    return refusal;
  }
  po.MemoryBudget = std::numeric_limits<std::uint64_t>::max();
  GridPlan<D> grids;
  const double budget = memoryBudgetBytes(plan);
  if (!planGrids(boundingBox(plan.Cloud), plan.CloudSpacing, po, grids).isOk() || budget <= 0.0)
  {
    return refusal;
  }
  const double need = tiledNeedBytes(plan, grids, budget);
  if (need > budget)
  {
    return refusal;
  }
  std::ostringstream m;
  m << refusal.message() << "; or store only the tiles near the surface (about " << need / 1e9
    << " GB): OctreeStorage in the filter, --octree with sltk reconstruct";
  return Status::outOfMemory(m.str());
}

} // namespace

template <int D>
double storedNodesEstimate(const ReconstructionPlan<D>& plan, int run)
{
  const GridSpec<D>& grid = plan.Grids.Runs[static_cast<size_t>(run - 1)];
  const double nodes = static_cast<double>(grid.nodeCount());
  return plan.Options.OctreeStorage && run > 1 ? std::min(estimatedTiledNodes(plan.Cloud, grid), nodes) : nodes;
}

template <int D>
double storageMemoryEstimate(const ReconstructionPlan<D>& plan, int run)
{
  if (!plan.Options.OctreeStorage || run == 1)
  {
    return plan.memoryEstimate(run);
  }
  return 4.0 * slotCount(plan.Grids.Runs[static_cast<size_t>(run - 1)]) +
    storedNodesEstimate(plan, run) * TiledBytesPerStoredNode;
}

template <int D>
Status planRunGrids(const ReconstructionPlan<D>& plan, int runs, double cellSizeFactor, GridPlan<D>& grids)
{
  GridPlanOptions po = runGridOptions(plan, runs, cellSizeFactor); // room for run 1's initial surface
  if (plan.Options.OctreeStorage)
  {
    po.MemoryBudget = std::numeric_limits<std::uint64_t>::max(); // not the uniform grids: their tiles
    SLTK_RETURN_IF_ERROR(planGrids(boundingBox(plan.Cloud), plan.CloudSpacing, po, grids));
    return checkTiledMemory(plan, cellSizeFactor, grids);
  }
  if (plan.Options.Ranks <= 1)
  {
    return withTiledAlternative(plan, po, planGrids(boundingBox(plan.Cloud), plan.CloudSpacing, po, grids));
  }
  // Split over ranks: the windows of the ranks on this machine must fit, not the whole grid.
  po.MemoryBudget = std::numeric_limits<std::uint64_t>::max();
  SLTK_RETURN_IF_ERROR(planGrids(boundingBox(plan.Cloud), plan.CloudSpacing, po, grids));
  return checkSlabMemory(plan, cellSizeFactor, grids);
}

template double storedNodesEstimate(const ReconstructionPlan<2>&, int);
template double storedNodesEstimate(const ReconstructionPlan<3>&, int);
template double storageMemoryEstimate(const ReconstructionPlan<2>&, int);
template double storageMemoryEstimate(const ReconstructionPlan<3>&, int);
template Status validateReconstructionOptions<2>(const ReconstructionOptions&);
template Status validateReconstructionOptions<3>(const ReconstructionOptions&);
template Status planRunGrids(const ReconstructionPlan<2>&, int, double, GridPlan<2>&);
template Status planRunGrids(const ReconstructionPlan<3>&, int, double, GridPlan<3>&);
template Status planReconstruction(PointCloud<2>, const ReconstructionOptions&, const Context&, ReconstructionPlan<2>&);
template Status planReconstruction(PointCloud<3>, const ReconstructionOptions&, const Context&, ReconstructionPlan<3>&);
template Status planReconstructionOnRanks(PointCloud<2>, std::int64_t, const ReconstructionOptions&, const Context&,
  const Communicator&, ReconstructionPlan<2>&);
template Status planReconstructionOnRanks(PointCloud<3>, std::int64_t, const ReconstructionOptions&, const Context&,
  const Communicator&, ReconstructionPlan<3>&);
template GridPlanOptions runGridOptions(const ReconstructionPlan<2>&, int, double);
template GridPlanOptions runGridOptions(const ReconstructionPlan<3>&, int, double);

} // namespace sltk
