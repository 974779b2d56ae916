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

/// The checks every distance computation makes (the cloud, the options, the grid).
template <int D>
Status checkDistanceInput(const PointCloud<D>& cloud, const GridSpec<D>& grid, const DistanceOptions& options)
{
  SLTK_RETURN_IF_ERROR(grid.validate());
  if (cloud.size() == 0)
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

/// The exact distance on the nodes of the 4^D box around each point (the cell
/// of Q in the whole grid, clipped to it, and ExactHalfWidth - 1 more layers),
/// for the nodes of `distance`: the rows from `firstRow` of the last axis of
/// `whole` (all of it for one rank). `exact` marks them (one entry a node).
template <int D>
Status exactNearPoints(const PointLocator<D>& locator, const GridSpec<D>& whole, Index firstRow, const Context& ctx,
  const DistanceOptions& options, GridField<D, double>& distance, std::vector<std::uint8_t>& exact, Index& count)
{
  const GridSpec<D>& window = distance.spec();
  const Index nodes = window.nodeCount();
  exact.assign(static_cast<size_t>(nodes), 0);
  // Marking is idempotent, so the mask does not depend on the order; it is
  // done serially (O(|P| 4^D)) to avoid races.
  const Index w = options.ExactHalfWidth;
  const Index lastRow = firstRow + window.Dims[D - 1] - 1;
  for (const auto& q : locator.cloud().Points)
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
  // Exact distance on the marked nodes, per node: independent of the thread count.
  count = static_cast<Index>(ctx.parallelSum(0, nodes,
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
  return ctx.interrupter().wasInterrupted() ? Status::aborted() : Status::ok();
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
  SLTK_RETURN_IF_ERROR(comm.agree(checkDistanceInput(locator.cloud(), whole, options)));
  GridSpec<D> window = whole; // the slab's rows at the whole grid's coordinates, bitwise
  window.Dims[D - 1] = slab.windowRows();
  window.Offset[D - 1] = whole.Offset[D - 1] + slab.First;
  distance.resize(window, options.Ghost, std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> exact;
  Index exactNodes = 0;
  SLTK_RETURN_IF_ERROR(
    comm.agree(exactNearPoints(locator, whole, slab.First, ctx, options, distance, exact, exactNodes)));
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

template Status distanceToCloud(const PointCloud<2>&, const GridSpec<2>&, const Context&, GridField<2, double>&,
  const DistanceOptions&, DistanceReport*);
template Status distanceToCloud(const PointCloud<3>&, const GridSpec<3>&, const Context&, GridField<3, double>&,
  const DistanceOptions&, DistanceReport*);
template Status distanceToCloud(const PointLocator<2>&, const GridSpec<2>&, const Context&, GridField<2, double>&,
  const DistanceOptions&, DistanceReport*);
template Status distanceToCloud(const PointLocator<3>&, const GridSpec<3>&, const Context&, GridField<3, double>&,
  const DistanceOptions&, DistanceReport*);
template Status distanceToCloudSlabs(const PointLocator<2>&, const GridSpec<2>&, const SlabPlan&, const Communicator&,
  const Context&, GridField<2, double>&, const DistanceOptions&, DistanceReport*);
template Status distanceToCloudSlabs(const PointLocator<3>&, const GridSpec<3>&, const SlabPlan&, const Communicator&,
  const Context&, GridField<3, double>&, const DistanceOptions&, DistanceReport*);

} // namespace sltk
