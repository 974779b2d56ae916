// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file RunLoop.h
/// Algorithm 1's runs (thesis 4.5.2), written once for every storage: run r
/// on the grid dx = C_dx h_P / 2^(r-1) (4.36), its set-up, its iterations
/// (RunIterations.h) and, beyond the thesis, the recoveries when a run loses
/// its zero level set or leaves points far from the surface. The uniform grids
/// (SlabRuns.h) and the tiled band (TiledRuns in octree/TiledReconstruction.cxx) are
/// the storages.
///
/// A storage `R` of the runs provides (every call collective):
///  - `Status setUp(int run, double outsideFactor)`: run `run`'s grid, d and
///    initial data (run 1 from the cloud with K_P = `outsideFactor`);
///  - `Status iterate(int run, ReconstructionResult<D>&, bool& vanished)`:
///    the run's iterations (iterateRun on the storage's band);
///  - `void advance(int run)`: the run's result becomes the previous run's;
///  - `Status keepCurrent(int run, ReconstructionResult<D>&)`: the result is
///    this run's; `void keepFailed(int run, ReconstructionResult<D>&)` keeps
///    what a failed run reached, where the storage can;
///  - `Status keepPrevious(int run, ReconstructionResult<D>&)`: the result is
///    the previous run's (or the reason the storage no longer holds it);
///  - `std::int64_t pieces(const ReconstructionResult<D>&)`: the kept result's
///    pieces (InsideComponents.h);
///  - `const Communicator& comm()`: the ranks the runs are split over (each
///    run's record takes this rank's traffic from its set-up to the end of
///    iterate(), RunFigures::Traffic).

#include "sltk/cloud/LocalFrame.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/PointClusters.h"
#include "sltk/recon/Reconstruction.h"
#include "sltk/recon/ReconstructionPlan.h"
#include "sltk/recon/RunIterations.h"
#include "sltk/recon/StoppingRule.h"
#include "sltk/recon/StrayPoints.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>
#include <vector>

namespace sltk
{

namespace detail
{
/// Drops the history of `run`: a run that lost its zero level set and is redone or replaced.
inline void forgetRun(int run, std::vector<IterationRecord>& history)
{
  history.erase(
    std::remove_if(history.begin(), history.end(), [run](const IterationRecord& it) { return it.Run == run; }),
    history.end());
}

/// "(x, y, z)" in the user's coordinates: the unit box's position moved back by the
/// front end's local frame (`frame`, LocalFrame.h), with the digits that keep its detail.
template <int D>
std::string position(const UnitBox<D>& box, const std::array<double, 3>& frame, const std::array<double, D>& unit)
{
  std::array<double, D> p = box.toUser(unit);
  for (int a = 0; a < D; ++a)
  {
    p[a] += frame[static_cast<size_t>(a)];
  }
  return formatPosition(p.data(), D, 2.0 * box.Scale);
}

/// "around (..) from (..) to (..)": a missed place's centre and bounds (unit-box units) in the
/// user's coordinates.
template <int D>
std::string placeBounds(const MissedPlace<D>& place, const UnitBox<D>& box, const std::array<double, 3>& frame)
{
  return "around " + position<D>(box, frame, place.Centre) + " from " + position<D>(box, frame, place.Lower) + " to " +
    position<D>(box, frame, place.Upper);
}

/// Where the missed points lie (MissedPlaces.h, unit-box units) in the user's: "; outside
/// it they gather at N point(s) (of the M there) around (..) from (..) to (..), ...", or ""
/// when none.
template <int D>
std::string describeMissedPlaces(
  const std::vector<MissedPlace<D>>& places, const UnitBox<D>& box, const std::array<double, 3>& frame)
{
  if (places.empty())
  {
    return "";
  }
  std::ostringstream text;
  text << "; outside it they gather " << (places.size() == 1 ? "at" : "most at");
  for (size_t k = 0; k < places.size(); ++k)
  {
    const MissedPlace<D>& place = places[k];
    text << (k ? "," : "") << " " << place.Points << " point(s) (of the " << place.Nearby << " there) "
         << placeBounds<D>(place, box, frame);
  }
  return text.str();
}

template <int D>
void recover(const std::string& what, const Context& ctx, ReconstructionResult<D>& result)
{
  ctx.logger().log(LogLevel::Warning, what);
  result.Recoveries.push_back(what);
}

/// `kept` (a storage's keepCurrent or keepPrevious), with the kept result's pieces counted.
template <int D, class Runs>
Status countPieces(const Status& kept, const Runs& runs, const Context& ctx, ReconstructionResult<D>& result)
{
  if (kept.isOk())
  {
    const auto start = std::chrono::steady_clock::now();
    result.Pieces = runs.pieces(result);
    ctx.logger().log(LogLevel::Info,
      "the result has " + std::to_string(result.Pieces) + " piece(s) (components of phi < 0), counted in " +
        std::to_string(secondsSince(start)) + " s");
  }
  return kept;
}
} // namespace detail

/// Runs 1..options.Runs of Algorithm 1 with `options` (the plan's, or a finer
/// start: reconstructWithRecoveries()) on `runs`' storage. A run 1 that loses
/// its zero level set with an automatic K_P starts again with the ladder's
/// next K_P (AutomaticParameters.h); a later run that loses it is replaced by
/// the previous run's result where the storage holds it.
template <int D, class Runs>
Status runAlgorithm1(Runs& runs, const ReconstructionPlan<D>& plan, const ReconstructionOptions& options,
  const Context& ctx, ReconstructionResult<D>& result)
{
  double outsideFactor = options.OutsideThresholdFactor;
  // An automatic K_P may be raised when run 1 loses its zero level set (AutomaticParameters.h).
  const double outsideRoom = plan.Enclosure ? outsideFactorWithRestart(outsideFactor) : outsideFactor;
  for (int run = 1; run <= options.Runs; ++run)
  {
    ctx.interrupter().start("run " + std::to_string(run) + "/" + std::to_string(options.Runs));
    const CommTraffic trafficBefore = runs.comm().traffic();
    const size_t records = result.Runs.size();
    const Status setUp = runs.setUp(run, outsideFactor);
    if (!setUp.isOk())
    {
      ctx.interrupter().end();
      return setUp;
    }
    bool vanished = false;
    const Status status = runs.iterate(run, result, vanished);
    ctx.interrupter().end();
    if (result.Runs.size() > records) // the run's record (iterateRun adds none when it fails)
    {
      result.Runs.back().Traffic = runs.comm().traffic().since(trafficBefore);
    }
    const double wider = nextOutsideFactor(outsideFactor);
    if (vanished && run == 1 && wider > 0.0 && wider <= outsideRoom)
    {
      // The initial surface leaked through a hole: start run 1 again from a wider one.
      detail::recover("run 1 lost its zero level set with the automatic K_P = " + std::to_string(outsideFactor) +
          "; restarted with K_P = " + std::to_string(wider),
        ctx, result);
      detail::forgetRun(1, result.History);
      outsideFactor = wider;
      result.OutsideThresholdFactor = wider;
      run = 0;
      continue;
    }
    if (vanished && run > 1)
    {
      // Keep the last run that held a surface rather than fail (its grid is coarser).
      const Status kept = detail::countPieces(runs.keepPrevious(run, result), runs, ctx, result);
      if (kept.isOk())
      {
        detail::recover("run " + std::to_string(run) + " lost its zero level set; the result is run " +
            std::to_string(run - 1) + "'s, on its grid (try a smaller eta in later runs, --schedule)",
          ctx, result);
        detail::forgetRun(run, result.History);
        return kept;
      }
      return Status::numericalFailure(status.message() + "; " + kept.message());
    }
    if (!status.isOk())
    {
      runs.keepFailed(run, result);
      if (vanished)
      {
        const std::string stray = strayPointAdvice(plan.Cloud, ctx);
        return Status::numericalFailure(
          status.message() + "; " + (stray.empty() ? "try a larger K_P or a larger eta" : stray));
      }
      return status;
    }
    if (run < options.Runs)
    {
      runs.advance(run);
    }
  }
  return detail::countPieces(runs.keepCurrent(options.Runs, result), runs, ctx, result);
}

/// Every rank must hold the same plan, made from the whole cloud (each rank's
/// slab boundaries and messages follow from it): its size, h_P, the runs'
/// grids and a checksum of the points, compared over the ranks.
template <int D>
Status samePlanOnEveryRank(const ReconstructionPlan<D>& plan, const Communicator& comm)
{
  std::vector<double> print = { static_cast<double>(plan.Cloud.size()), plan.CloudSpacing,
    static_cast<double>(plan.Grids.Runs.size()), 0.0 };
  for (const auto& p : plan.Cloud.Points)
  {
    for (int a = 0; a < D; ++a)
    {
      print[3] += p[a];
    }
  }
  std::int64_t count[2] = { static_cast<std::int64_t>(plan.Grids.Runs.size()), 0 };
  count[1] = -count[0];
  comm.allReduce(count, 2, ReduceOp::Max);
  if (count[0] == -count[1])
  {
    for (const GridSpec<D>& g : plan.Grids.Runs)
    {
      for (int a = 0; a < D; ++a)
      {
        print.insert(print.end(), { static_cast<double>(g.Dims[a]), g.Origin[a], g.Spacing[a] });
      }
    }
  }
  std::vector<double> low = print, high = print;
  comm.allReduce(low.data(), low.size(), ReduceOp::Min);
  comm.allReduce(high.data(), high.size(), ReduceOp::Max);
  return count[0] == -count[1] && low == high
    ? Status::ok()
    : Status::invalidArgument("the ranks hold different clouds or plans (each needs the whole cloud and the same "
                              "options): give every rank the whole cloud, e.g. a reader that is not split into pieces");
}

/// Whether the last run lost features thinner than run 1's cells: more than FarPointWarning
/// of the points beyond one run-1 cell, or more than FitShare beyond misfitDistance (an
/// interpolator that lets the surface shrink less, the least-squares Q1, can lose a thin
/// fin whole yet leave few points beyond one run-1 cell: the disc with a fin of
/// TestAutomaticParameters, 0.5% far and 23.6% missed).
inline bool lostThinFeatures(const RunFigures& last)
{
  return last.FarPoints > FarPointWarning || last.MisfitPoints > FitShare;
}

/// Whether the result lost thin features (lostThinFeatures) or a part of the model, a place
/// where nearly every point is missed (lostPart, MissedPlaces.h) of a cloud of `cloudPoints`.
template <int D>
bool lostFeatures(const ReconstructionResult<D>& records, Index cloudPoints)
{
  return !records.Runs.empty() &&
    (lostThinFeatures(records.Runs.back()) || lostPart(records.MissedPlaces, cloudPoints) != nullptr);
}

/// "N of the M points around (x, y, z) from (..) to (..)": a lost part (lostPart), given in the
/// run's unit-box units, in the user's coordinates.
template <int D>
std::string lostPartText(const ReconstructionPlan<D>& plan, const MissedPlace<D>& place)
{
  return std::to_string(place.Points) + " of the " + std::to_string(place.Nearby) + " points " +
    detail::placeBounds<D>(place, plan.Box, plan.Options.FrameShift);
}

/// "the result has N pieces where the cloud has M connected component(s) at 4 local
/// spacings (at least 4 h_P = L)" (PieceLinkFactor, cloudComponents, L in the user's units).
template <int D>
std::string piecesAgainstComponents(const ReconstructionPlan<D>& plan, std::int64_t pieces, Index components)
{
  std::ostringstream text;
  text.precision(3);
  text << "the result has " << pieces << " pieces where the cloud has " << components << " connected component(s) at "
       << PieceLinkFactor << " local spacings (at least " << PieceLinkFactor
       << " h_P = " << PieceLinkFactor * plan.userCloudSpacing() << ")";
  return text.str();
}

/// The honest outcome when the result has more pieces than the cloud has components
/// (Documentation/Numerics.md, "Pieces against the cloud's components"): FitsCloud is
/// false and the statement comes first, with advice that is not what just ran (`ran`), or
/// `groups` (separateGroupsAdvice) when the cloud is a few groups far apart.
template <int D>
void statePieces(const ReconstructionPlan<D>& plan, const ReconstructionOptions& ran, Index components,
  const std::string& groups, const Context& ctx, ReconstructionResult<D>& records)
{
  std::ostringstream statement;
  statement.precision(3);
  statement << piecesAgainstComponents(plan, records.Pieces, components);
  if (!groups.empty()) // separateGroupsAdvice: no C_dx helps
  {
    statement << ". " << groups;
  }
  else
  {
    statement << ": parts thinner than the cells broke apart; a C_dx below the " << ran.CellSizeFactor
              << " that ran (--cdx" << (ran.OctreeStorage ? "" : ", with --octree for the memory") << ")"
              << (ran.Interpolator == InterpolatorKind::LeastSquaresQ1 ? " or --interpolator weno3" : "")
              << " may keep them";
  }
  records.FitsCloud = false;
  records.Warnings.insert(records.Warnings.begin(), statement.str());
  ctx.logger().log(LogLevel::Warning, statement.str());
}

/// `finer`: `ran` with one run fewer from half its C_dx, which ends on the same finest grid,
/// and its grids. When that is one run, its grid is the finest grid, which the automatic C_dx
/// fitted to the memory budget without run 1's padding for its initial surface; if the padding
/// takes it past the budget, the smallest C_dx above the half that fits, up the ladder of the
/// automatic C_dx (CellSizeLadderStep, AutomaticParameters.h) while it stays below `ran`'s.
/// False when none fits (with two runs or more, a run 1 that does not fit at half the C_dx is
/// not restarted, as before). Collective: every rank takes the same decisions (comm.agree;
/// machines differ).
template <int D>
bool planFinerStart(const ReconstructionPlan<D>& plan, const Communicator& comm, const ReconstructionOptions& ran,
  ReconstructionOptions& finer, GridPlan<D>& grids)
{
  finer = ran;
  finer.Runs -= 1;
  for (double c = ran.CellSizeFactor / 2.0; c < ran.CellSizeFactor; c *= CellSizeLadderStep)
  {
    const Status planned = comm.agree(planRunGrids(plan, finer.Runs, c, grids));
    if (planned.isOk())
    {
      finer.CellSizeFactor = c;
      return true;
    }
    if (planned.code() != StatusCode::OutOfMemory || finer.Runs > 1)
    {
      return false;
    }
  }
  return false;
}

/// Why the result of `ran` starts again as `finer`, from half its C_dx (reconstructWithRecoveries):
/// its pieces against the cloud's `components`, else its far or missed points.
template <int D>
std::string restartReason(const ReconstructionPlan<D>& plan, const ReconstructionResult<D>& records, Index components,
  const ReconstructionOptions& ran, const ReconstructionOptions& finer)
{
  const RunFigures& last = records.Runs.back();
  const MissedPlace<D>* lost = lostPart(records.MissedPlaces, plan.Cloud.size());
  std::ostringstream what;
  if (records.Pieces > components)
  {
    what << piecesAgainstComponents(plan, records.Pieces, components);
  }
  else if (last.FarPoints > FarPointWarning)
  {
    what << 100.0 * last.FarPoints << "% of the points ended more than one cell of run 1 from the surface";
  }
  else if (last.MisfitPoints > FitShare || lost == nullptr)
  {
    what << 100.0 * last.MisfitPoints << "% of the points ended more than two finest cells and h_P from the surface";
  }
  else
  {
    what << lostPartText(plan, *lost)
         << " ended more than two finest cells and h_P from the surface (a part of the model lost)";
  }
  what << " with C_dx = " << ran.CellSizeFactor << ": reconstructed again from C_dx = " << finer.CellSizeFactor
       << " with " << finer.Runs << " run(s), which end on "
       << (finer.CellSizeFactor == ran.CellSizeFactor / 2.0
              ? "the same finest grid"
              : "the finest grid that fits the memory budget (run 1's padding for its initial surface)");
  return what.str();
}

/// The honest outcome when the last run misses more than FitShare of the points, or a part of
/// the model (lostPart): FitsCloud is false and the statement comes first, with where the
/// missed points gather and advice (`groups`: separateGroupsAdvice, or a smaller C_dx when no
/// warning gave any). Nothing when it fits.
template <int D>
void stateMisfit(
  const ReconstructionPlan<D>& plan, const std::string& groups, const Context& ctx, ReconstructionResult<D>& records)
{
  if (records.Runs.empty())
  {
    return;
  }
  const RunRecord<D>& last = records.Runs.back();
  const MissedPlace<D>* lost = lostPart(records.MissedPlaces, plan.Cloud.size());
  if (!(last.MisfitPoints > FitShare) && lost == nullptr)
  {
    return;
  }
  std::ostringstream statement;
  statement.precision(3);
  const double distance = plan.Box.Scale * misfitDistance(last.Grid.Spacing[0], plan.CloudSpacing);
  if (last.MisfitPoints > FitShare)
  {
    statement << "the result does not fit the cloud: " << 100.0 * last.MisfitPoints
              << "% of the points lie more than two finest cells and h_P (" << distance
              << ") from the surface (features thinner than the cells were lost, or the points scatter more than "
              << "that)";
  }
  else
  {
    statement << "the result does not fit the cloud: it lost a part of the model, " << lostPartText(plan, *lost)
              << " lie more than two finest cells and h_P (" << distance << ") from the surface ("
              << 100.0 * last.MisfitPoints << "% of all the points)";
  }
  if (!groups.empty())
  {
    statement << ". " << groups;
  }
  else if (records.Warnings.empty())
  {
    statement << ": a C_dx below the " << records.CellSizeFactor << " that ran (--cdx) resolves thinner features";
  }
  if (last.MisfitPoints > FitShare)
  {
    statement << detail::describeMissedPlaces<D>(records.MissedPlaces, plan.Box, plan.Options.FrameShift);
  }
  records.FitsCloud = false;
  records.Warnings.insert(records.Warnings.begin(), statement.str());
  ctx.logger().log(LogLevel::Warning, statement.str());
}

/// Algorithm 1 on the plan with every recovery: `runWith(options, grids)`
/// runs it (runAlgorithm1 on a fresh storage, filling `records`) with the
/// plan's options; when C_dx was chosen automatically and the last run lost
/// thin features (lostThinFeatures) or the result has more pieces than the cloud has
/// components (PieceLinkFactor), it runs again from half the C_dx with one run fewer,
/// which ends on the same finest grid, and halves again while the pieces stay more
/// (down to one run on that grid); when the automatic interpolator chose the
/// least-squares Q1 and the result still has more pieces, again with WENO3 on the same grids.
/// The records are returned in the user's units (recordsToUser), with the plan's
/// choices; the storage's fields are left in unit-box units.
template <int D, class RunWith>
Status reconstructWithRecoveries(const ReconstructionPlan<D>& plan, const Context& ctx, const Communicator& comm,
  ReconstructionResult<D>& records, RunWith&& runWith)
{
  records = ReconstructionResult<D>{};
  if (!plan.Locator || plan.Grids.Runs.size() != static_cast<size_t>(plan.Options.Runs))
  {
    return Status::invalidArgument("reconstruct: the plan is incomplete (planReconstruction failed or was not called)");
  }
  if (comm.size() > 1)
  {
    SLTK_RETURN_IF_ERROR(samePlanOnEveryRank(plan, comm));
  }
  const auto start = [&](const ReconstructionOptions& options, const std::vector<GridSpec<D>>& grids)
  {
    records.OutsideThresholdFactor = options.OutsideThresholdFactor;
    records.CellSizeFactor = options.CellSizeFactor;
    const Status ran = runWith(options, grids);
    if (!records.Runs.empty() && !records.MissedPlaces.empty())
    {
      std::ostringstream missed;
      missed.precision(3);
      missed << "the last run's surface misses " << 100.0 * records.Runs.back().MisfitPoints << "% of the points"
             << detail::describeMissedPlaces<D>(records.MissedPlaces, plan.Box, plan.Options.FrameShift);
      ctx.logger().log(LogLevel::Info, missed.str());
    }
    return ran;
  };
  // A run again after `what`, the recoveries so far kept first.
  const auto again =
    [&](const ReconstructionOptions& options, const std::vector<GridSpec<D>>& grids, const std::string& what)
  {
    ctx.logger().log(LogLevel::Warning, what);
    std::vector<std::string> recoveries = std::move(records.Recoveries);
    recoveries.push_back(what);
    records = ReconstructionResult<D>{};
    const Status rerun = start(options, grids);
    records.Recoveries.insert(records.Recoveries.begin(), recoveries.begin(), recoveries.end());
    return rerun;
  };
  Status status = start(plan.Options, plan.Grids.Runs);
  const auto counting = std::chrono::steady_clock::now();
  // Links that follow the local spacing (Documentation/Numerics.md, "Pieces against the
  // cloud's components"): every rank holds the whole cloud and counts the same.
  const Index components =
    cloudComponents(*plan.Locator, plan.CloudSpacing, PieceLinkFactor, plan.Options.Cleaning.DensityNeighbours, ctx);
  ctx.logger().log(LogLevel::Info,
    "the cloud has " + std::to_string(components) + " connected component(s) at 4 local spacings, counted in " +
      std::to_string(detail::secondsSince(counting)) + " s");
  ReconstructionOptions ran = plan.Options;
  std::vector<GridSpec<D>> ranGrids = plan.Grids.Runs;
  bool restarted = false;
  // Run 1 lost features thinner than its cells (lostThinFeatures, or thin parts broke into
  // more pieces than the cloud's components): start at half the cell size with one run fewer,
  // which ends on the same finest grid (the same memory); again while the pieces stay more
  // (Documentation/Numerics.md, "Lost thin features").
  while (status.isOk() && plan.AutomaticCellSize && ran.Runs > 1 && !records.Runs.empty() &&
    (records.Pieces > components || (!restarted && lostFeatures(records, plan.Cloud.size()))))
  {
    ReconstructionOptions finer = ran;
    GridPlan<D> finerGrids;
    if (!planFinerStart(plan, comm, ran, finer, finerGrids))
    {
      break;
    }
    status = again(finer, finerGrids.Runs, restartReason(plan, records, components, ran, finer));
    ran = finer;
    ranGrids = finerGrids.Runs;
    restarted = true;
  }
  if (status.isOk() && records.Pieces > components && plan.CloudNoise >= 0.0 &&
    ran.Interpolator == InterpolatorKind::LeastSquaresQ1)
  {
    // The automatic least-squares Q1 let thin parts break apart: WENO3 on the same grids.
    ran.Interpolator = InterpolatorKind::Weno3;
    status = again(ran, ranGrids,
      piecesAgainstComponents(plan, records.Pieces, components) +
        " with the automatic interpolator lsq-q1: reconstructed again with weno3 on the same grids");
  }
  // A result that does not fit a cloud of a few groups far apart: no C_dx helps, their own runs do.
  const bool fits = records.Runs.empty() || (!lostFeatures(records, plan.Cloud.size()) && records.Pieces <= components);
  const std::string groups = status.isOk() && !fits && components >= 2
    ? separateGroupsAdvice(
        plan, plan.AutomaticCellSize ? 1.0 : ran.CellSizeFactor, "its cells are too coarse for each group")
    : std::string();
  if (status.isOk() && !records.Runs.empty() && records.Runs.back().FarPoints > FarPointWarning)
  {
    // Advice that is not what just ran.
    std::ostringstream warning;
    warning << 100.0 * records.Runs.back().FarPoints
            << "% of the points lie more than one cell of run 1 from the surface: features thinner than that cell "
            << "were lost; "
            << (!groups.empty()
                   ? "the grid spans the empty space between groups of points far apart, and no C_dx that fits the "
                     "memory resolves them: reconstruct each group in its own run"
                   : restarted ? "the restart from half the C_dx did not keep them: a smaller C_dx with as many runs "
                                 "(the octree storage for the memory) may"
                   : records.Runs.size() <= 1 ? "a smaller C_dx may keep them"
                                              : "try half the C_dx with one run fewer (the same finest grid)");
    ctx.logger().log(LogLevel::Warning, warning.str());
    records.Warnings.push_back(warning.str());
  }
  if (status.isOk())
  {
    stateMisfit(plan, groups, ctx, records);
  }
  if (status.isOk() && records.Pieces > components)
  {
    statePieces(plan, ran, components, groups, ctx, records);
  }
  records.SeparateGroups = !groups.empty();
  records.CloudComponents = components;
  records.CloudSpacing = plan.userCloudSpacing();
  records.Cleaning = plan.Cleaning;
  records.Choices = plan.Choices;
  records.Interpolator = ran.Interpolator.value_or(InterpolatorKind::Weno3);
  records.CloudNoise = plan.CloudNoise;
  recordsToUser(plan.Box, records);
  return status;
}

} // namespace sltk
