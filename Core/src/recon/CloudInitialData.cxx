// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/CloudInitialData.h"

#include "ExternalMarking.h"
#include "sltk/recon/CloudInitialDataSlabs.h"

#include <algorithm>
#include <array>
#include <cmath>
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

template <int D>
Status outsideBottleneck(const GridField<D, double>& distance, const Context& ctx, std::vector<double>& bottleneck)
{
  // The widest paths from the boundary, widest first (Dijkstra's order with
  // max-min for plus-min): a node is final when it leaves the queue, so each
  // is expanded once, O(n log n), where repeated passes along the axes need
  // as many rounds as the widest paths turn. The values are the d of the
  // nodes or +infinity, chosen by comparisons only: the fixed point of the
  // passes, bit for bit.
  const GridSpec<D>& g = distance.spec();
  const double inf = std::numeric_limits<double>::infinity();
  bottleneck.assign(static_cast<size_t>(g.nodeCount()), -inf);
  using Entry = std::pair<double, Index>; // (width, node)
  std::vector<Entry> heap;
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    if (onBoundary<D>(distance.nodeIndex(k), g, 0, g.Dims[D - 1]))
    {
      bottleneck[static_cast<size_t>(k)] = inf;
      heap.emplace_back(inf, k);
    }
  }
  std::array<Index, D> nodeStride{};
  for (Index a = 0, stride = 1; a < D; stride *= g.Dims[a], ++a)
  {
    nodeStride[a] = stride;
  }
  std::make_heap(heap.begin(), heap.end());
  Index expanded = 0;
  while (!heap.empty())
  {
    std::pop_heap(heap.begin(), heap.end());
    const auto [width, node] = heap.back();
    heap.pop_back();
    if (width < bottleneck[static_cast<size_t>(node)])
    {
      continue; // a stale entry: the node left the queue wider
    }
    const std::array<Index, D> i = distance.nodeIndex(node);
    for (int a = 0; a < D; ++a)
    {
      for (const int side : { -1, 1 })
      {
        const Index j = i[a] + side;
        if (j < 0 || j >= g.Dims[a])
        {
          continue;
        }
        const Index next = node + side * nodeStride[a];
        std::array<Index, D> n = i;
        n[a] = j;
        const double through = std::min(distance(n), width);
        if (through > bottleneck[static_cast<size_t>(next)])
        {
          bottleneck[static_cast<size_t>(next)] = through;
          heap.emplace_back(through, next);
          std::push_heap(heap.begin(), heap.end());
        }
      }
    }
    if (++expanded % (Index(1) << 20) == 0 && ctx.interrupter().wasInterrupted())
    {
      return Status::aborted();
    }
  }
  return Status::ok();
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
