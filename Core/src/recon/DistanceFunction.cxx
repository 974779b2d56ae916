// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/DistanceFunction.h"

#include "sltk/core/IndexBox.h"
#include "sltk/levelset/FastSweeping.h"
#include "sltk/levelset/FastSweepingSlabs.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <cmath>
#include <limits>

namespace sltk
{

namespace
{
Status emptyCloud()
{
  return Status::invalidArgument("the distance function needs a non-empty point cloud");
}

/// The checks every distance computation makes (the cloud, the options, the
/// grid); `empty`: whether the cloud is empty (on ranks, every rank's share).
template <int D>
Status checkDistanceInput(
  const PointCloud<D>& cloud, bool empty, const GridSpec<D>& grid, const DistanceOptions& options)
{
  SLTK_RETURN_IF_ERROR(grid.validate());
  if (empty)
  {
    return emptyCloud();
  }
  if (options.ExactHalfWidth < 1 || options.Ghost < 0 || options.MaxSweepCycles < 1 || !(options.SweepTolerance >= 0.0))
  {
    return Status::invalidArgument(
      "distance options: ExactHalfWidth >= 1, Ghost >= 0, MaxSweepCycles >= 1 and SweepTolerance >= 0");
  }
  for (const auto& q : cloud.Points)
  {
    for (int a = 0; a < D; ++a)
    {
      if (!std::isfinite(q[a]))
      {
        return Status::invalidArgument("the point cloud has a non-finite coordinate");
      }
    }
  }
  return Status::ok();
}

/// Marks the nodes of the 4^D box around each of `points` (the cell of Q in
/// the whole grid, clipped to it, and ExactHalfWidth - 1 more layers) among
/// the nodes of `window`: the rows from `firstRow` of the last axis of
/// `whole` (all of it for one rank). `exact` gets one entry a node.
template <int D>
void markExactBoxes(const std::vector<std::array<double, D>>& points, const GridSpec<D>& whole, Index firstRow,
  const GridSpec<D>& window, const DistanceOptions& options, std::vector<std::uint8_t>& exact)
{
  exact.assign(static_cast<size_t>(window.nodeCount()), 0);
  // Marking is idempotent, so the mask does not depend on the order; it is
  // done serially (O(|P| 4^D)) to avoid races.
  const Index w = options.ExactHalfWidth;
  const Index lastRow = firstRow + window.Dims[D - 1] - 1;
  for (const auto& q : points)
  {
    const CellLocation<D> loc = locate(whole, q.data());
    std::array<Index, D> lo, hi;
    for (int a = 0; a < D; ++a)
    {
      lo[a] = std::max<Index>(0, loc.Cell[a] - (w - 1));
      hi[a] = std::min<Index>(whole.Dims[a] - 1, loc.Cell[a] + w);
    }
    lo[D - 1] = std::max(lo[D - 1], firstRow) - firstRow; // the window's rows, in its numbering
    hi[D - 1] = std::min(hi[D - 1], lastRow) - firstRow;
    if (hi[D - 1] < lo[D - 1])
    {
      continue; // the box lies in another rank's rows
    }
    forEachIndexInBox<D>(lo, hi,
      [&](const std::array<Index, D>& i)
      {
        Index lin = 0;
        for (int a = D - 1; a >= 0; --a)
        {
          lin = lin * window.Dims[a] + i[a];
        }
        exact[static_cast<size_t>(lin)] = 1;
      });
  }
}

/// The distance to the locator's cloud at the marked nodes of `distance`, per
/// node (independent of the thread count); returns how many are marked.
template <int D>
Index distanceAtMarked(const PointLocator<D>& locator, const std::vector<std::uint8_t>& exact, const Context& ctx,
  GridField<D, double>& distance)
{
  const GridSpec<D>& window = distance.spec();
  return static_cast<Index>(ctx.parallelSum(0, window.nodeCount(),
    [&](Index b, Index e)
    {
      double marked = 0.0;
      for (Index k = b; k < e; ++k)
      {
        if (!exact[static_cast<size_t>(k)])
        {
          continue;
        }
        const std::array<Index, D> i = distance.nodeIndex(k);
        std::array<double, D> x;
        for (int a = 0; a < D; ++a)
        {
          x[a] = window.coordinate(a, i[a]);
        }
        distance(i) = locator.nearest(x).Distance;
        marked += 1.0;
      }
      return marked;
    }));
}

/// The exact distance on the nodes of the boxes around the locator's points (markExactBoxes).
template <int D>
Status exactNearPoints(const PointLocator<D>& locator, const GridSpec<D>& whole, Index firstRow, const Context& ctx,
  const DistanceOptions& options, GridField<D, double>& distance, std::vector<std::uint8_t>& exact, Index& count)
{
  markExactBoxes<D>(locator.cloud().Points, whole, firstRow, distance.spec(), options, exact);
  count = distanceAtMarked(locator, exact, ctx, distance);
  return ctx.interrupter().wasInterrupted() ? Status::aborted() : Status::ok();
}

/// The fast sweeping (4.4.2) from the exact nodes, then the ghost layers.
template <int D>
Status sweepFromExact(GridField<D, double>& distance, const std::vector<std::uint8_t>& exact, const SlabPlan& slab,
  const Communicator& comm, const Context& ctx, const DistanceOptions& options, Index exactNodes,
  DistanceReport* report)
{
  FastSweepingOptions sweep;
  sweep.MaxCycles = options.MaxSweepCycles;
  sweep.Tolerance = options.SweepTolerance;
  FastSweepingSlabsReport swept;
  SLTK_RETURN_IF_ERROR(fastSweepSlabs(distance, exact, slab, comm, ctx, sweep, &swept));
  if (options.Ghost > 0)
  {
    distance.fillGhosts();
  }
  if (report)
  {
    report->ExactNodes = exactNodes;
    report->SweepCycles = swept.Cycles;
  }
  return Status::ok();
}
} // namespace

template <int D>
Status distanceToCloud(const PointLocator<D>& locator, const GridSpec<D>& grid, const Context& ctx,
  GridField<D, double>& distance, const DistanceOptions& options, DistanceReport* report)
{
  return distanceToCloudSlabs(
    locator, grid, wholeSlab(grid.Dims[D - 1]), serialCommunicator(), ctx, distance, options, report);
}

template <int D>
Status distanceToCloud(const PointCloud<D>& cloud, const GridSpec<D>& grid, const Context& ctx,
  GridField<D, double>& distance, const DistanceOptions& options, DistanceReport* report)
{
  if (cloud.size() == 0)
  {
    return emptyCloud(); // (the locator needs a non-empty cloud)
  }
  const PointLocator<D> locator(cloud);
  return distanceToCloud(locator, grid, ctx, distance, options, report);
}

template <int D>
Status distanceToCloudSlabs(const PointLocator<D>& locator, const GridSpec<D>& whole, const SlabPlan& slab,
  const Communicator& comm, const Context& ctx, GridField<D, double>& distance, const DistanceOptions& options,
  DistanceReport* report)
{
  SLTK_RETURN_IF_ERROR(comm.agree(checkDistanceInput(locator.cloud(), locator.cloud().size() == 0, whole, options)));
  GridSpec<D> window = whole; // the slab's rows at the whole grid's coordinates, bitwise
  window.Dims[D - 1] = slab.windowRows();
  window.Offset[D - 1] = whole.Offset[D - 1] + slab.First;
  distance.resize(window, options.Ghost, std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> exact;
  Index exactNodes = 0;
  SLTK_RETURN_IF_ERROR(
    comm.agree(exactNearPoints(locator, whole, slab.First, ctx, options, distance, exact, exactNodes)));
  return sweepFromExact(distance, exact, slab, comm, ctx, options, exactNodes, report);
}

template <int D>
Status distanceToCloudOnRanks(const OwnedPoints<D>& points, const GridSpec<D>& grid, const Communicator& comm,
  const Context& ctx, GridField<D, double>& distance, const DistanceOptions& options, DistanceReport* report)
{
  const bool empty = comm.allReduce(points.held(), ReduceOp::Sum) == 0;
  const Status checked = checkDistanceInput(points.Cloud, empty, grid, options);
  SLTK_RETURN_IF_ERROR(comm.agree(checked));
  distance.resize(grid, options.Ghost, std::numeric_limits<double>::infinity());
  // The boxes of every rank's points, and at their nodes the nearest of every
  // rank's: the whole cloud's marks and distances, bit for bit.
  std::vector<std::uint8_t> exact;
  markExactBoxes<D>(points.Cloud.Points, grid, 0, grid, options, exact);
  std::vector<std::int64_t> marks(exact.begin(), exact.end());
  comm.allReduce(marks.data(), marks.size(), ReduceOp::Max);
  std::copy(marks.begin(), marks.end(), exact.begin());
  marks = {};
  std::vector<Index> at;
  std::vector<std::array<double, D>> x;
  for (Index k = 0; k < grid.nodeCount(); ++k)
  {
    if (exact[static_cast<size_t>(k)])
    {
      const auto i = distance.nodeIndex(k);
      at.push_back(k);
      x.emplace_back();
      for (int a = 0; a < D; ++a)
      {
        x.back()[a] = grid.coordinate(a, i[a]);
      }
    }
  }
  // A marked node lies within ExactHalfWidth cells of a point along every axis.
  double reach = 0.0;
  for (int a = 0; a < D; ++a)
  {
    reach += std::pow(options.ExactHalfWidth * grid.Spacing[a], 2);
  }
  std::vector<double> nearest;
  std::vector<std::int64_t> ids;
  nearestOverRanks<D>(points, x, std::sqrt(reach) * (1.0 + 1e-9), comm, ctx, nearest, ids);
  for (size_t m = 0; m < at.size(); ++m)
  {
    distance(distance.nodeIndex(at[m])) = nearest[m];
  }
  SLTK_RETURN_IF_ERROR(comm.agree(ctx.interrupter().wasInterrupted() ? Status::aborted() : Status::ok()));
  return sweepFromExact(distance, exact, wholeSlab(grid.Dims[D - 1]), serialCommunicator(), ctx, options,
    static_cast<Index>(at.size()), report);
}

template Status distanceToCloud(const PointCloud<2>&, const GridSpec<2>&, const Context&, GridField<2, double>&,
  const DistanceOptions&, DistanceReport*);
template Status distanceToCloud(const PointCloud<3>&, const GridSpec<3>&, const Context&, GridField<3, double>&,
  const DistanceOptions&, DistanceReport*);
template Status distanceToCloud(const PointLocator<2>&, const GridSpec<2>&, const Context&, GridField<2, double>&,
  const DistanceOptions&, DistanceReport*);
template Status distanceToCloud(const PointLocator<3>&, const GridSpec<3>&, const Context&, GridField<3, double>&,
  const DistanceOptions&, DistanceReport*);
template Status distanceToCloudOnRanks(const OwnedPoints<2>&, const GridSpec<2>&, const Communicator&, const Context&,
  GridField<2, double>&, const DistanceOptions&, DistanceReport*);
template Status distanceToCloudOnRanks(const OwnedPoints<3>&, const GridSpec<3>&, const Communicator&, const Context&,
  GridField<3, double>&, const DistanceOptions&, DistanceReport*);
template Status distanceToCloudSlabs(const PointLocator<2>&, const GridSpec<2>&, const SlabPlan&, const Communicator&,
  const Context&, GridField<2, double>&, const DistanceOptions&, DistanceReport*);
template Status distanceToCloudSlabs(const PointLocator<3>&, const GridSpec<3>&, const SlabPlan&, const Communicator&,
  const Context&, GridField<3, double>&, const DistanceOptions&, DistanceReport*);

} // namespace sltk
