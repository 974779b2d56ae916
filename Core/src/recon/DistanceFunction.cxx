// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/DistanceFunction.h"

#include "sltk/levelset/FastSweeping.h"

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
} // namespace

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
Status distanceToCloud(const PointLocator<D>& locator, const GridSpec<D>& grid, const Context& ctx,
  GridField<D, double>& distance, const DistanceOptions& options, DistanceReport* report)
{
  const PointCloud<D>& cloud = locator.cloud();
  SLTK_RETURN_IF_ERROR(grid.validate());
  if (cloud.size() == 0)
  {
    return emptyCloud();
  }
  if (options.ExactHalfWidth < 1 || options.Ghost < 0 || options.MaxSweepCycles < 1)
  {
    return Status::invalidArgument("distance options: ExactHalfWidth >= 1, Ghost >= 0 and MaxSweepCycles >= 1");
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
  const Index nodes = grid.nodeCount();
  std::vector<std::uint8_t> exact(static_cast<size_t>(nodes), 0);
  // Mark the 4^D box around each point: the cell of Q (located, clipped) and
  // ExactHalfWidth - 1 more layers. Marking is idempotent, so the mask does
  // not depend on the order; it is done serially (O(|P| 4^D)) to avoid races.
  const Index w = options.ExactHalfWidth;
  for (const auto& q : cloud.Points)
  {
    const CellLocation<D> loc = locate(grid, q.data());
    std::array<Index, D> lo, hi;
    for (int a = 0; a < D; ++a)
    {
      lo[a] = std::max<Index>(0, loc.Cell[a] - (w - 1));
      hi[a] = std::min<Index>(grid.Dims[a] - 1, loc.Cell[a] + w);
    }
    std::array<Index, D> i = lo;
    for (;;)
    {
      Index lin = 0;
      for (int a = D - 1; a >= 0; --a)
      {
        lin = lin * grid.Dims[a] + i[a];
      }
      exact[static_cast<size_t>(lin)] = 1;
      int a = 0;
      for (; a < D; ++a)
      {
        if (++i[a] <= hi[a])
        {
          break;
        }
        i[a] = lo[a];
      }
      if (a == D)
      {
        break;
      }
    }
  }
  distance.resize(grid, options.Ghost, std::numeric_limits<double>::infinity());
  // Exact distance on the marked nodes, per node: independent of the thread count.
  const double exactCount = ctx.parallelSum(0, nodes,
    [&](Index b, Index e)
    {
      double count = 0.0;
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
          x[a] = grid.coordinate(a, i[a]);
        }
        distance(i) = locator.nearest(x).Distance;
        count += 1.0;
      }
      return count;
    });
  if (ctx.interrupter().wasInterrupted())
  {
    return Status::aborted();
  }
  // Fast sweeping for all other nodes (4.4.2, ref. [121]).
  FastSweepingOptions sweep;
  sweep.MaxCycles = options.MaxSweepCycles;
  FastSweepingReport swept;
  SLTK_RETURN_IF_ERROR(fastSweep(distance, exact, ctx, sweep, &swept));
  if (options.Ghost > 0)
  {
    distance.fillGhosts();
  }
  if (report)
  {
    report->ExactNodes = static_cast<Index>(exactCount);
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

} // namespace sltk
