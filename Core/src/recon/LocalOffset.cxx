// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/LocalOffset.h"

#include <algorithm>
#include <cmath>

namespace sltk
{

template <int D>
Status locallyScaledDistance(const GridField<D, double>& distance, const PointLocator<D>& locator,
  const std::vector<double>& sparsity, double reach, const Context& ctx, GridField<D, double>& scaled)
{
  const PointCloud<D>& cloud = locator.cloud();
  if (sparsity.size() != static_cast<size_t>(cloud.size()) || sparsity.empty())
  {
    return Status::invalidArgument("locallyScaledDistance: one sparsity factor per cloud point is needed");
  }
  const double largest = *std::max_element(sparsity.begin(), sparsity.end());
  const GridSpec<D>& g = distance.spec();
  const Index nodes = g.nodeCount();
  double near = 0.0;
  for (int a = 0; a < D; ++a)
  {
    near += g.Spacing[a] * g.Spacing[a];
  }
  near = 2.0 * std::sqrt(near); // two cell diagonals: a nearest-point query is cheap there
  // rho at every node with d < reach: queried near the cloud, and farther carried
  // down the steepest descent of d (the axis neighbour with the smallest d, which
  // is nearer the same points), in increasing order of d.
  std::vector<double> rho(static_cast<size_t>(nodes), largest);
  std::vector<Index> order;
  for (Index k = 0; k < nodes; ++k)
  {
    const double d = distance(distance.nodeIndex(k));
    if (d >= near && d < reach)
    {
      order.push_back(k);
    }
  }
  ctx.parallelFor(0, nodes,
    [&](Index b, Index e)
    {
      std::array<double, D> x;
      for (Index k = b; k < e; ++k)
      {
        const auto i = distance.nodeIndex(k);
        if (distance(i) < near)
        {
          for (int a = 0; a < D; ++a)
          {
            x[a] = g.coordinate(a, i[a]);
          }
          rho[static_cast<size_t>(k)] = sparsity[static_cast<size_t>(locator.nearest(x).Index)];
        }
      }
    });
  std::sort(order.begin(), order.end(),
    [&](Index p, Index q)
    {
      const double dp = distance(distance.nodeIndex(p)), dq = distance(distance.nodeIndex(q));
      return dp < dq || (dp == dq && p < q);
    });
  for (const Index k : order)
  {
    const auto i = distance.nodeIndex(k);
    double lowest = distance(i);
    Index stride = 1;
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
            rho[static_cast<size_t>(k)] = rho[static_cast<size_t>(k + side * stride)];
          }
        }
      }
      stride *= g.Dims[a];
    }
  }
  scaled = distance;
  ctx.parallelFor(0, nodes,
    [&](Index b, Index e)
    {
      for (Index k = b; k < e; ++k)
      {
        const auto i = distance.nodeIndex(k);
        scaled(i) = distance(i) / rho[static_cast<size_t>(k)];
      }
    });
  scaled.fillGhosts();
  return Status::ok();
}

template Status locallyScaledDistance(const GridField<2, double>&, const PointLocator<2>&, const std::vector<double>&,
  double, const Context&, GridField<2, double>&);
template Status locallyScaledDistance(const GridField<3, double>&, const PointLocator<3>&, const std::vector<double>&,
  double, const Context&, GridField<3, double>&);

} // namespace sltk
