// SPDX-License-Identifier: BSD-3-Clause
/// \file RunGridMemory.cxx
/// The plan's run grids against the memory (ReconstructionPlan.h, step 7):
/// the uniform grid's budget, the windows of the ranks on this machine
/// (Distributed.md, "The automatic C_dx under MPI") and the tiled storage's
/// estimate (TiledMemory.h), with the refusals that name what would fit.
#include "RunGridMemory.h"

#include "sltk/exec/Memory.h"
#include "sltk/octree/TiledField.h"
#include "sltk/octree/TiledMemory.h"
#include "sltk/recon/SlabPolicy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace sltk
{

std::string planNumber(double value)
{
  std::ostringstream s;
  s.precision(3);
  s << value;
  return s.str();
}

namespace
{
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
} // namespace

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
    return "C_dx = " + planNumber(cdx) +
      (cdx > 1.0
          ? ": the smallest whose finest grid fits the " + std::to_string(budget >> 20) + " MB budget (--memory-budget)"
          : ": the thesis's default, within the memory budget");
  }
  const bool given = plan.Options.MemoryBudget && !plan.BudgetIsAutomatic;
  return "C_dx = " + planNumber(cdx) + ": the smallest whose windows on " + std::to_string(plan.Options.Ranks) +
    " ranks, ghost rows included, fit the " + std::to_string(static_cast<std::uint64_t>(slabMemoryLimit(plan)) >> 20) +
    " MB " + (given ? "budget (--memory-budget)" : "available") + " for the " +
    std::to_string(std::max(1, plan.Options.RanksHere)) +
    " rank(s) on this machine; one rank would take C_dx = " + planNumber(oneRank) +
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
      plan.Choices.push_back("C_dx = " + planNumber(c) + " rather than " + planNumber(plan.Options.CellSizeFactor) +
        ": run 1's padding for its initial surface widens the windows of the ranks on this machine");
      ctx.logger().log(LogLevel::Info, "automatic " + plan.Choices.back());
      plan.Options.CellSizeFactor = c;
      return Status::ok();
    }
  }
  return planned; // nothing fits: the first refusal, with its advice
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
template Status planRunGrids(const ReconstructionPlan<2>&, int, double, GridPlan<2>&);
template Status planRunGrids(const ReconstructionPlan<3>&, int, double, GridPlan<3>&);
template GridPlanOptions runGridOptions(const ReconstructionPlan<2>&, int, double);
template GridPlanOptions runGridOptions(const ReconstructionPlan<3>&, int, double);
template Status fitWindowsOnThisMachine(ReconstructionPlan<2>&, GridPlanOptions);
template Status fitWindowsOnThisMachine(ReconstructionPlan<3>&, GridPlanOptions);
template std::string cellSizeChoice(const ReconstructionPlan<2>&, std::uint64_t, double);
template std::string cellSizeChoice(const ReconstructionPlan<3>&, std::uint64_t, double);
template Status planFittingRunGrids(ReconstructionPlan<2>&, const Context&);
template Status planFittingRunGrids(ReconstructionPlan<3>&, const Context&);

} // namespace sltk
