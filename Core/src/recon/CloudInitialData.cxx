// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/CloudInitialData.h"

#include "ExternalMarking.h"
#include "sltk/core/DisjointSets.h"
#include "sltk/core/SortByKey.h"
#include "sltk/recon/CloudInitialDataSlabs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace sltk
{
using marking::onBoundary;

template <int D>
Status markExternal(const GridField<D, double>& distance, double threshold, const Context& ctx,
  std::vector<std::uint8_t>& external, int* rounds)
{
  const Index rows = distance.spec().Dims[D - 1];
  return markExternalSlabs(distance, threshold, wholeSlab(rows), rows, serialCommunicator(), ctx, external, rounds);
}

namespace
{
/// outsideBottleneck() with node ids of type Id (32 bits when the grid allows:
/// half the memory of the forest).
template <int D, class Id>
Status widestWayOut(const GridField<D, double>& distance, const Context& ctx, std::vector<double>& bottleneck)
{
  // The nodes are added in decreasing order of d to a disjoint-set forest of
  // the nodes with d >= t (union by rank, path halving): when a component
  // first touches the boundary at level t = d of the node that joins it,
  // every node of it has a path out whose minimum is t and none whose
  // minimum is larger, so its bottleneck is t. The closed components keep
  // their nodes in a circular list (joined in O(1)) for that moment; each
  // node is assigned once. The values are the d of the nodes or +infinity,
  // chosen by comparisons only: those of the widest paths, bit for bit
  // (ties in d give the same t whatever their order).
  const GridSpec<D>& g = distance.spec();
  const Index nodes = g.nodeCount();
  const double inf = std::numeric_limits<double>::infinity();
  constexpr Id Inactive = std::numeric_limits<Id>::max(), Boundary = Inactive - 1; // parent of a node not in the forest
  std::vector<Id> parent(static_cast<size_t>(nodes), Inactive);
  std::vector<std::uint64_t> key; // decreasing d: the complement of its key
  std::vector<Id> order;
  for (Index k = 0; k < nodes; ++k)
  {
    const std::array<Index, D> i = distance.nodeIndex(k);
    const double d = distance(i);
    const bool edge = onBoundary<D>(i, g, 0, g.Dims[D - 1]);
    parent[static_cast<size_t>(k)] = edge ? Boundary : Inactive;
    if (!edge && !std::isnan(d)) // a NaN is never reached (the widest paths compare it false)
    {
      key.push_back(~orderedKey(d));
      order.push_back(static_cast<Id>(k));
    }
  }
  // Sorted before `bottleneck` and the forest's arrays exist, so that the
  // sort's buffers (16 bytes a node) are the peak; its keys stay for the loop,
  // which takes each node's d from them in order (a cache miss a node at v).
  sortByKey(key, order);
  bottleneck.resize(static_cast<size_t>(nodes));
  for (Index k = 0; k < nodes; ++k)
  {
    const double d = distance(distance.nodeIndex(k));
    const bool edge = parent[static_cast<size_t>(k)] == Boundary;
    bottleneck[static_cast<size_t>(k)] = edge ? inf : std::isnan(d) ? d : -inf; // -inf: not reached yet
  }
  std::vector<Id> next(static_cast<size_t>(nodes));
  std::vector<std::uint8_t> rank(static_cast<size_t>(nodes), 0), open(static_cast<size_t>(nodes), 0);
  const auto assign = [&](Id root, double t)
  {
    Id m = root;
    do
    {
      bottleneck[m] = t;
      m = next[m];
    } while (m != root);
  };
  const auto unite = [&](Id x, Id y)
  {
    if (!open[x] && !open[y])
    {
      std::swap(next[x], next[y]); // one circle of both
    }
    if (rank[x] < rank[y])
    {
      std::swap(x, y);
    }
    rank[x] = static_cast<std::uint8_t>(rank[x] + (rank[x] == rank[y] ? 1 : 0));
    parent[y] = x;
    open[x] = open[x] | open[y];
    return x;
  };
  std::array<Index, D> nodeStride{};
  for (Index a = 0, stride = 1; a < D; stride *= g.Dims[a], ++a)
  {
    nodeStride[a] = stride;
  }
  Index added = 0;
  for (size_t j = 0; j < order.size(); ++j)
  {
    const Id v = order[j];
    const std::array<Index, D> i = distance.nodeIndex(static_cast<Index>(v));
    const double t = fromOrderedKey(~key[j]); // d at v, bit for bit
    parent[v] = v;
    next[v] = v;
    Id root = v;
    bool touches = false;
    for (int a = 0; a < D; ++a)
    {
      for (const int side : { -1, 1 })
      {
        if (i[a] + side < 0 || i[a] + side >= g.Dims[a])
        {
          continue;
        }
        const Id n = static_cast<Id>(static_cast<Index>(v) + side * nodeStride[a]);
        touches = touches || parent[n] == Boundary;
        if (parent[n] == Boundary || parent[n] == Inactive)
        {
          continue;
        }
        const Id r = findRoot(parent, n);
        if (r == root)
        {
          continue;
        }
        if (open[r] != open[root])
        {
          assign(open[r] ? root : r, t); // a closed component joins an open one at level t
        }
        root = unite(root, r);
      }
    }
    if (touches && !open[root])
    {
      assign(root, t);
      open[root] = 1;
    }
    if (++added % (Index(1) << 20) == 0 && ctx.interrupter().wasInterrupted())
    {
      return Status::aborted();
    }
  }
  return Status::ok();
}
} // namespace

template <int D>
Status outsideBottleneck(const GridField<D, double>& distance, const Context& ctx, std::vector<double>& bottleneck)
{
  if (distance.spec().nodeCount() < static_cast<Index>(std::numeric_limits<std::uint32_t>::max()))
  {
    return widestWayOut<D, std::uint32_t>(distance, ctx, bottleneck);
  }
  return widestWayOut<D, std::uint64_t>(distance, ctx, bottleneck);
}

template <int D>
Status cloudInitialData(const GridField<D, double>& distance, double threshold, const Context& ctx,
  GridField<D, double>& phi0, const InitialDataOptions& options, InitialDataReport* report)
{
  const Index rows = distance.spec().Dims[D - 1];
  return cloudInitialDataSlabs(
    distance, threshold, wholeSlab(rows), rows, serialCommunicator(), ctx, phi0, options, report);
}

template <int D>
Ellipsoid<D> boundingSphere(const PointCloud<D>& cloud, double margin)
{
  const Box<D> box = boundingBox(cloud);
  Ellipsoid<D> s;
  for (int a = 0; a < D; ++a)
  {
    s.Centre[a] = 0.5 * (box.Min[a] + box.Max[a]);
  }
  double r2 = 0.0;
  for (const auto& q : cloud.Points)
  {
    double t = 0.0;
    for (int a = 0; a < D; ++a)
    {
      t += (q[a] - s.Centre[a]) * (q[a] - s.Centre[a]);
    }
    r2 = std::max(r2, t);
  }
  s.SemiAxes.fill(std::sqrt(r2) + margin);
  return s;
}

template <int D>
Ellipsoid<D> boundingEllipsoid(const PointCloud<D>& cloud, double margin)
{
  const Box<D> box = boundingBox(cloud);
  Ellipsoid<D> e;
  for (int a = 0; a < D; ++a)
  {
    e.Centre[a] = 0.5 * (box.Min[a] + box.Max[a]);
    // sum_a (h_a / (sqrt(D) h_a))^2 = 1: the box corners lie on the ellipsoid.
    e.SemiAxes[a] = std::sqrt(static_cast<double>(D)) * 0.5 * box.extent(a) + margin;
  }
  return e;
}

template Status markExternal(const GridField<2, double>&, double, const Context&, std::vector<std::uint8_t>&, int*);
template Status markExternal(const GridField<3, double>&, double, const Context&, std::vector<std::uint8_t>&, int*);
template Status outsideBottleneck(const GridField<2, double>&, const Context&, std::vector<double>&);
template Status outsideBottleneck(const GridField<3, double>&, const Context&, std::vector<double>&);
template Status cloudInitialData(const GridField<2, double>&, double, const Context&, GridField<2, double>&,
  const InitialDataOptions&, InitialDataReport*);
template Status cloudInitialData(const GridField<3, double>&, double, const Context&, GridField<3, double>&,
  const InitialDataOptions&, InitialDataReport*);
template Ellipsoid<2> boundingSphere(const PointCloud<2>&, double);
template Ellipsoid<3> boundingSphere(const PointCloud<3>&, double);
template Ellipsoid<2> boundingEllipsoid(const PointCloud<2>&, double);
template Ellipsoid<3> boundingEllipsoid(const PointCloud<3>&, double);

} // namespace sltk
