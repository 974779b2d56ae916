// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/CloudInitialData.h"

#include "ExternalMarking.h"
#include "sltk/recon/CloudInitialDataSlabs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sltk
{
using marking::onBoundary;
using marking::passUntilStable;

template <int D>
Status markExternal(const GridField<D, double>& distance, double threshold, const Context& ctx,
  std::vector<std::uint8_t>& external, int* rounds)
{
  const Index rows = distance.spec().Dims[D - 1];
  return markExternalSlabs(distance, threshold, wholeSlab(rows), rows, serialCommunicator(), ctx, external, rounds);
}

template <int D>
Status outsideBottleneck(
  const GridField<D, double>& distance, const Context& ctx, std::vector<double>& bottleneck, int* rounds)
{
  const GridSpec<D>& g = distance.spec();
  const double inf = std::numeric_limits<double>::infinity();
  bottleneck.assign(static_cast<size_t>(g.nodeCount()), -inf);
  ctx.parallelFor(0, g.nodeCount(),
    [&](Index b, Index e)
    {
      for (Index k = b; k < e; ++k)
      {
        bottleneck[static_cast<size_t>(k)] = onBoundary<D>(distance.nodeIndex(k), g, 0, g.Dims[D - 1]) ? inf : -inf;
      }
    });
  const double* d = distance.storage().data();
  double* wide = bottleneck.data();
  // A node takes the narrower of its own d and its neighbour's way out, when wider than its own.
  return passUntilStable(
    distance, ctx,
    [&](Index node, Index offset, Index from)
    {
      const double through = std::min(d[offset], wide[from]);
      if (through > wide[node])
      {
        wide[node] = through;
        return true;
      }
      return false;
    },
    rounds);
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
template Status outsideBottleneck(const GridField<2, double>&, const Context&, std::vector<double>&, int*);
template Status outsideBottleneck(const GridField<3, double>&, const Context&, std::vector<double>&, int*);
template Status cloudInitialData(const GridField<2, double>&, double, const Context&, GridField<2, double>&,
  const InitialDataOptions&, InitialDataReport*);
template Status cloudInitialData(const GridField<3, double>&, double, const Context&, GridField<3, double>&,
  const InitialDataOptions&, InitialDataReport*);
template Ellipsoid<2> boundingSphere(const PointCloud<2>&, double);
template Ellipsoid<3> boundingSphere(const PointCloud<3>&, double);
template Ellipsoid<2> boundingEllipsoid(const PointCloud<2>&, double);
template Ellipsoid<3> boundingEllipsoid(const PointCloud<3>&, double);

} // namespace sltk
