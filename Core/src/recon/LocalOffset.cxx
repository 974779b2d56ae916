// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/LocalOffset.h"

#include "sltk/core/SortByKey.h"
#include "sltk/grid/SlabExchange.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace sltk
{

namespace
{
/// rho(x) of every node: the factor of the nearest point within `near` of the
/// cloud, then carried outwards along the steepest descent of d in increasing
/// order of d (`order`: the nodes with near <= d < reach, sorted). A node whose
/// window row is below keepBelow or at least keepAbove is skipped: it keeps its value
/// (a slab's edge ghost row, whose lowest neighbour may lie outside the window).
template <int D>
void carryDescent(const GridField<D, double>& distance, const std::vector<Index>& order, Index keepBelow,
  Index keepAbove, GridField<D, double>& rho)
{
  const GridSpec<D>& g = distance.spec();
  for (const Index k : order)
  {
    const auto i = distance.nodeIndex(k);
    if (i[D - 1] < keepBelow || i[D - 1] >= keepAbove)
    {
      continue;
    }
    double lowest = distance(i);
    for (int a = 0; a < D; ++a)
    {
      for (int side = -1; side <= 1; side += 2)
      {
        const Index j = i[a] + side;
        if (j >= 0 && j < g.Dims[a])
        {
          auto n = i;
          n[a] = j;
          const double d = distance(n);
          if (d < lowest)
          {
            lowest = d;
            rho(i) = rho(n);
          }
        }
      }
    }
  }
}

/// Two cell diagonals: rho is queried at the nodes this near the cloud (a
/// nearest-point query is cheap there).
template <int D>
double queryRadius(const GridSpec<D>& g)
{
  double diagonal = 0.0;
  for (int a = 0; a < D; ++a)
  {
    diagonal += g.Spacing[a] * g.Spacing[a];
  }
  return 2.0 * std::sqrt(diagonal);
}

template <int D>
std::array<double, D> nodePosition(const GridSpec<D>& g, const std::array<Index, D>& i)
{
  std::array<double, D> x;
  for (int a = 0; a < D; ++a)
  {
    x[a] = g.coordinate(a, i[a]);
  }
  return x;
}

/// The nodes where rho is queried, within queryRadius of the cloud, and `order`, the nodes it is carried to
/// (near <= d < reach), in increasing d, ties by node index (sortByKey orders
/// equal keys by their items; d > 0, so equal distances have equal keys): a total order.
template <int D>
void nodesNearCloud(
  const GridField<D, double>& distance, double reach, std::vector<Index>& queried, std::vector<Index>& order)
{
  const GridSpec<D>& g = distance.spec();
  const double near = queryRadius(g);
  std::vector<std::uint64_t> key; // of d
  queried.clear();
  order.clear();
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    const double d = distance(distance.nodeIndex(k));
    if (d < near)
    {
      queried.push_back(k);
    }
    else if (d < reach)
    {
      key.push_back(orderedKey(d));
      order.push_back(k);
    }
  }
  sortByKey(key, order);
}

/// The part shared by the one-rank and slab versions: rho queried near the
/// cloud (elsewhere `largest`, the whole cloud's largest factor), and `order`,
/// the nodes to carry it to (nodesNearCloud).
template <int D>
Status queryNearCloud(const GridField<D, double>& distance, const PointLocator<D>& locator,
  const std::vector<double>& sparsity, double largest, double reach, const Context& ctx, GridField<D, double>& rho,
  std::vector<Index>& order)
{
  const GridSpec<D>& g = distance.spec();
  rho.resize(g, 0, largest);
  std::vector<Index> queried;
  nodesNearCloud(distance, reach, queried, order);
  ctx.parallelFor(0, static_cast<Index>(queried.size()),
    [&](Index b, Index e)
    {
      for (Index q = b; q < e; ++q)
      {
        const auto i = distance.nodeIndex(queried[static_cast<size_t>(q)]);
        rho(i) = sparsity[static_cast<size_t>(locator.nearest(nodePosition<D>(g, i)).Index)];
      }
    });
  return Status::ok();
}

template <int D>
void divideByRho(const GridField<D, double>& distance, const GridField<D, double>& rho, const Context& ctx,
  GridField<D, double>& scaled)
{
  scaled = distance;
  ctx.parallelFor(0, distance.spec().nodeCount(),
    [&](Index b, Index e)
    {
      for (Index k = b; k < e; ++k)
      {
        const auto i = distance.nodeIndex(k);
        scaled(i) = distance(i) / rho(i);
      }
    });
  scaled.fillGhosts();
}
} // namespace

template <int D>
Status locallyScaledDistance(const GridField<D, double>& distance, const PointLocator<D>& locator,
  const std::vector<double>& sparsity, double reach, const Context& ctx, GridField<D, double>& scaled)
{
  return locallyScaledDistanceSlabs(
    distance, locator, sparsity, reach, wholeSlab(distance.spec().Dims[D - 1]), serialCommunicator(), ctx, scaled);
}

template <int D>
Status locallyScaledDistanceSlabs(const GridField<D, double>& distance, const PointLocator<D>& locator,
  const std::vector<double>& sparsity, double reach, const SlabPlan& slab, const Communicator& comm, const Context& ctx,
  GridField<D, double>& scaled)
{
  // A rank's locator may hold only the points near its window (recon/RunPoints.h):
  // the nodes queried lie within two cell diagonals of the cloud, nearer than they reach.
  const Status sized = sparsity.size() != static_cast<size_t>(locator.cloud().size()) || sparsity.empty()
    ? Status::invalidArgument("locallyScaledDistance: one sparsity factor per cloud point is needed")
    : Status::ok();
  SLTK_RETURN_IF_ERROR(comm.agree(sized));
  const double largest = comm.allReduce(*std::max_element(sparsity.begin(), sparsity.end()), ReduceOp::Max);
  GridField<D, double> rho;
  std::vector<Index> order;
  SLTK_RETURN_IF_ERROR(comm.agree(queryNearCloud(distance, locator, sparsity, largest, reach, ctx, rho, order)));
  // The window's edge rows, when they are ghost rows, take the owners' values;
  // every other node is carried from its neighbours, until no ghost row changes.
  const Index keepBelow = slab.First < slab.Begin ? 1 : 0;
  const Index keepAbove = slab.Stop > slab.End ? slab.windowRows() - 1 : slab.windowRows();
  for (int round = 0;; ++round)
  {
    carryDescent(distance, order, keepBelow, keepAbove, rho);
    bool changed = false;
    exchangeGhostRows(rho, slab, comm, &changed);
    std::int64_t any = changed ? 1 : 0;
    comm.allReduce(&any, 1, ReduceOp::Max);
    if (any == 0)
    {
      break;
    }
    if (round > 4 * comm.size() + 64)
    {
      return Status::numericalFailure(
        "the local offset's sparsity did not settle across the slabs: run without --local-offset");
    }
  }
  divideByRho(distance, rho, ctx, scaled);
  return Status::ok();
}

template <int D>
double largestOwnedFactor(const OwnedPoints<D>& points, const std::vector<double>& sparsity, const Communicator& comm)
{
  double largest = 0.0; // a halo point's factor is its owner's
  for (size_t j = 0; j < points.Mine.size() && j < sparsity.size(); ++j)
  {
    largest = points.Mine[j] ? std::max(largest, sparsity[j]) : largest;
  }
  return comm.allReduce(largest, ReduceOp::Max);
}

template <int D>
Status locallyScaledDistanceOnRanks(const GridField<D, double>& distance, const OwnedPoints<D>& points,
  const std::vector<double>& sparsity, double reach, const Communicator& comm, const Context& ctx,
  GridField<D, double>& scaled)
{
  const std::int64_t total = comm.allReduce(points.Owned, ReduceOp::Sum);
  const Status sized = sparsity.size() != static_cast<size_t>(points.held()) || total == 0
    ? Status::invalidArgument("locallyScaledDistance: one sparsity factor per held point is needed")
    : Status::ok();
  SLTK_RETURN_IF_ERROR(comm.agree(sized));
  const double largest = largestOwnedFactor(points, sparsity, comm);
  GridField<D, double> rho;
  rho.resize(distance.spec(), 0, largest);
  std::vector<Index> queried, order;
  nodesNearCloud(distance, reach, queried, order);
  // The nearest of every rank's points (ties by the lowest global index, as
  // one rank's locator), and its factor from its owner.
  const GridSpec<D>& g = distance.spec();
  std::vector<std::array<double, D>> x(queried.size());
  for (size_t q = 0; q < queried.size(); ++q)
  {
    x[q] = nodePosition<D>(g, distance.nodeIndex(queried[q]));
  }
  std::vector<double> nearest;
  std::vector<std::int64_t> ids;
  nearestOverRanks<D>(points, x, queryRadius(g) * (1.0 + 1e-9), comm, ctx, nearest, ids);
  std::vector<double> factor(queried.size(), 0.0); // factors are >= 1: the owner's is the largest
  for (size_t q = 0; q < queried.size(); ++q)
  {
    const std::int64_t j = points.ownedLocal(ids[q]);
    factor[q] = j >= 0 ? sparsity[static_cast<size_t>(j)] : 0.0;
  }
  comm.allReduce(factor.data(), factor.size(), ReduceOp::Max);
  for (size_t q = 0; q < queried.size(); ++q)
  {
    rho(distance.nodeIndex(queried[q])) = factor[q];
  }
  carryDescent(distance, order, 0, distance.spec().Dims[D - 1], rho);
  divideByRho(distance, rho, ctx, scaled);
  return Status::ok();
}

template Status locallyScaledDistance(const GridField<2, double>&, const PointLocator<2>&, const std::vector<double>&,
  double, const Context&, GridField<2, double>&);
template Status locallyScaledDistance(const GridField<3, double>&, const PointLocator<3>&, const std::vector<double>&,
  double, const Context&, GridField<3, double>&);
template double largestOwnedFactor(const OwnedPoints<2>&, const std::vector<double>&, const Communicator&);
template double largestOwnedFactor(const OwnedPoints<3>&, const std::vector<double>&, const Communicator&);
template Status locallyScaledDistanceOnRanks(const GridField<2, double>&, const OwnedPoints<2>&,
  const std::vector<double>&, double, const Communicator&, const Context&, GridField<2, double>&);
template Status locallyScaledDistanceOnRanks(const GridField<3, double>&, const OwnedPoints<3>&,
  const std::vector<double>&, double, const Communicator&, const Context&, GridField<3, double>&);
template Status locallyScaledDistanceSlabs(const GridField<2, double>&, const PointLocator<2>&,
  const std::vector<double>&, double, const SlabPlan&, const Communicator&, const Context&, GridField<2, double>&);
template Status locallyScaledDistanceSlabs(const GridField<3, double>&, const PointLocator<3>&,
  const std::vector<double>&, double, const SlabPlan&, const Communicator&, const Context&, GridField<3, double>&);

} // namespace sltk
