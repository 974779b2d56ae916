// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/AutomaticParameters.h"

#include "sltk/exec/ThreadPool.h"
#include "sltk/recon/CloudInitialData.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/LocalOffset.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sltk
{

namespace
{
/// The probe grid's nodes at most: coarser probes are made by doubling dx.
constexpr double MaximumProbeNodes = 4e6;
} // namespace

const std::vector<double>& outsideFactorLadder()
{
  static const std::vector<double> ladder = { 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32 };
  return ladder;
}

double nextOutsideFactor(double factor)
{
  for (double k : outsideFactorLadder())
  {
    if (k > factor)
    {
      return k;
    }
  }
  return 0.0;
}

double outsideFactorWithRestart(double factor)
{
  return std::max(factor, nextOutsideFactor(factor));
}

namespace
{
/// For every rung K of the ladder, the nodes the initial surface at gamma_P =
/// K h_P (4.4.4) encloses: d >= gamma_P with no way out above it (bottleneck
/// below it). One pass over the nodes for all the rungs; the counts are
/// integers, the same whatever the chunks.
template <int D>
std::vector<Index> enclosedNodes(
  const GridField<D, double>& distance, const std::vector<double>& bottleneck, double cloudSpacing, const Context& ctx)
{
  const std::vector<double>& ladder = outsideFactorLadder();
  const size_t rungs = ladder.size();
  std::vector<double> threshold(rungs);
  for (size_t r = 0; r < rungs; ++r)
  {
    threshold[r] = ladder[r] * cloudSpacing;
  }
  const Index nodes = distance.spec().nodeCount();
  const Index grain = std::max<Index>(4096, (nodes + 63) / 64);
  std::vector<Index> partial(static_cast<size_t>(ThreadPool::chunkCount(0, nodes, grain)) * rungs, 0);
  ctx.parallelFor(
    0, nodes,
    [&](Index b, Index e)
    {
      std::vector<Index> count(rungs, 0); // this chunk's, stored once (no line shared between threads)
      for (Index k = b; k < e; ++k)
      {
        const double d = distance(distance.nodeIndex(k));
        const double way = bottleneck[static_cast<size_t>(k)];
        for (size_t r = 0; r < rungs; ++r)
        {
          count[r] += d >= threshold[r] && way < threshold[r] ? 1 : 0;
        }
      }
      std::copy(count.begin(), count.end(), partial.begin() + static_cast<std::ptrdiff_t>(b / grain * rungs));
    },
    grain);
  std::vector<Index> enclosed(rungs, 0);
  for (size_t c = 0; c < partial.size(); ++c)
  {
    enclosed[c % rungs] += partial[c];
  }
  return enclosed;
}
} // namespace

namespace
{
/// The probe of chooseOutsideFactor(): its grid around `bounds` (run 1's
/// spacing dx, doubled until it has at most MaximumProbeNodes nodes),
/// `scaledDistance(grid, reach, distance)` on it (the distance to the cloud
/// (4.4.2), divided by the local sparsity within `reach` when `local`), and
/// the rung chosen from the nodes each encloses.
template <int D, class ScaledDistance>
Status probeOutsideFactor(const Box<D>& bounds, double cloudSpacing, double dx, double largestSparsity,
  const Context& ctx, ScaledDistance scaledDistance, OutsideFactorChoice& choice)
{
  choice = OutsideFactorChoice{};
  const std::vector<double>& ladder = outsideFactorLadder();
  GridPlanOptions po;
  po.Runs = 1;
  po.MemoryBudget = std::numeric_limits<std::uint64_t>::max(); // the probe is bounded below instead
  GridPlan<D> probe;
  const size_t first = firstOutsideRung(dx / cloudSpacing);
  for (;;)
  {
    po.CellSizeFactor = dx / cloudSpacing;
    // Room for the largest K's uniform offset and a margin. Not for its local
    // offset (up to MaximumSparsity times more): the marking starts from the whole
    // grid boundary (CloudInitialData.h), so a surface cut by the box encloses
    // the same nodes, and a padding 4 times wider coarsened the probe grid 4
    // times (teapot: K_P = 2 on a 1.6M-node probe, whose cells hide its holes).
    po.Padding = static_cast<int>(std::ceil(ladder.back() * cloudSpacing / dx)) + 4;
    SLTK_RETURN_IF_ERROR(planGrids(bounds, cloudSpacing, po, probe));
    if (static_cast<double>(probe.Runs[0].nodeCount()) <= MaximumProbeNodes)
    {
      break;
    }
    dx *= 2.0;
  }
  const GridSpec<D>& grid = probe.Runs[0];
  GridField<D, double> distance;
  SLTK_RETURN_IF_ERROR(scaledDistance(grid, largestSparsity * ladder.back() * cloudSpacing, distance));
  std::vector<double> bottleneck;
  SLTK_RETURN_IF_ERROR(outsideBottleneck(distance, ctx, bottleneck));
  const std::vector<Index> enclosed = enclosedNodes(distance, bottleneck, cloudSpacing, ctx);
  size_t best = first;
  for (size_t r = first + 1; r < enclosed.size(); ++r)
  {
    best = enclosed[r] > enclosed[best] ? r : best;
  }
  choice.Factor = ladder[best];
  choice.FirstRung = first;
  choice.EnclosedNodes = enclosed;
  choice.ProbeNodes = grid.nodeCount();
  choice.ProbeSpacing = grid.Spacing[0];
  return Status::ok();
}
} // namespace

template <int D>
Status chooseOutsideFactor(const PointLocator<D>& locator, const Box<D>& bounds, double cloudSpacing, double dx,
  const std::vector<double>& sparsity, const Context& ctx, OutsideFactorChoice& choice)
{
  const double largest = sparsity.empty() ? 1.0 : *std::max_element(sparsity.begin(), sparsity.end());
  return probeOutsideFactor(
    bounds, cloudSpacing, dx, largest, ctx,
    [&](const GridSpec<D>& grid, double reach, GridField<D, double>& distance)
    {
      DistanceOptions dopt;
      dopt.Ghost = 0;
      SLTK_RETURN_IF_ERROR(distanceToCloud(locator, grid, ctx, distance, dopt)); // (4.4.2)
      if (sparsity.empty())
      {
        return Status::ok();
      }
      GridField<D, double> scaled;
      SLTK_RETURN_IF_ERROR(locallyScaledDistance(distance, locator, sparsity, reach, ctx, scaled));
      distance = std::move(scaled);
      return Status::ok();
    },
    choice);
}

template <int D>
Status chooseOutsideFactorOnRanks(const OwnedPoints<D>& points, const Box<D>& bounds, double cloudSpacing, double dx,
  const std::vector<double>& sparsity, const Communicator& comm, const Context& ctx, OutsideFactorChoice& choice)
{
  const bool local = comm.anyRank(!sparsity.empty());
  const double largest = local ? largestOwnedFactor(points, sparsity, comm) : 1.0;
  return probeOutsideFactor(
    bounds, cloudSpacing, dx, largest, ctx,
    [&](const GridSpec<D>& grid, double reach, GridField<D, double>& distance)
    {
      DistanceOptions dopt;
      dopt.Ghost = 0;
      SLTK_RETURN_IF_ERROR(distanceToCloudOnRanks(points, grid, comm, ctx, distance, dopt)); // (4.4.2)
      if (!local)
      {
        return Status::ok();
      }
      GridField<D, double> scaled;
      SLTK_RETURN_IF_ERROR(locallyScaledDistanceOnRanks(distance, points, sparsity, reach, comm, ctx, scaled));
      distance = std::move(scaled);
      return Status::ok();
    },
    choice);
}

size_t firstOutsideRung(double cellSizeFactor)
{
  const std::vector<double>& ladder = outsideFactorLadder();
  size_t first = 0;
  while (first + 1 < ladder.size() && ladder[first] < 2.0 * cellSizeFactor)
  {
    ++first;
  }
  return first;
}

template <int D>
Status chooseCellSizeFactor(const Box<D>& bounds, double cloudSpacing, GridPlanOptions options, double& cellSizeFactor)
{
  GridPlan<D> plan;
  for (double c = 1.0; c <= 1e4; c *= CellSizeLadderStep)
  {
    options.CellSizeFactor = c;
    const Status status = planGrids(bounds, cloudSpacing, options, plan);
    if (status.isOk())
    {
      cellSizeFactor = c;
      return status;
    }
    if (status.code() != StatusCode::OutOfMemory)
    {
      return status;
    }
  }
  return Status::outOfMemory("no C_dx up to 1e4 gives grids within the memory budget: raise the budget");
}

template Status chooseOutsideFactor(const PointLocator<2>&, const Box<2>&, double, double, const std::vector<double>&,
  const Context&, OutsideFactorChoice&);
template Status chooseOutsideFactor(const PointLocator<3>&, const Box<3>&, double, double, const std::vector<double>&,
  const Context&, OutsideFactorChoice&);
template Status chooseOutsideFactorOnRanks(const OwnedPoints<2>&, const Box<2>&, double, double,
  const std::vector<double>&, const Communicator&, const Context&, OutsideFactorChoice&);
template Status chooseOutsideFactorOnRanks(const OwnedPoints<3>&, const Box<3>&, double, double,
  const std::vector<double>&, const Communicator&, const Context&, OutsideFactorChoice&);
template Status chooseCellSizeFactor(const Box<2>&, double, GridPlanOptions, double&);
template Status chooseCellSizeFactor(const Box<3>&, double, GridPlanOptions, double&);

} // namespace sltk
