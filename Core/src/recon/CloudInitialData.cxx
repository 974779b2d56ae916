// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/CloudInitialData.h"

#include "sltk/levelset/FastSweeping.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sltk
{

namespace
{
/// A grid line along `axis`: first node (linear index and storage offset) and steps.
struct Line
{
  Index Node = 0;
  Index Offset = 0;
  Index NodeStep = 0;
  Index OffsetStep = 0;
  Index Length = 0;
};

template <int D>
Line gridLine(const GridField<D, double>& f, int axis, Index line)
{
  const GridSpec<D>& g = f.spec();
  std::array<Index, D> i{};
  for (int a = 0; a < D; ++a)
  {
    if (a != axis)
    {
      i[a] = line % g.Dims[a];
      line /= g.Dims[a];
    }
  }
  Line l;
  Index step = 1;
  for (int a = 0; a < D; ++a)
  {
    l.Node += i[a] * step;
    if (a == axis)
    {
      l.NodeStep = step;
    }
    step *= g.Dims[a];
  }
  l.Offset = f.offset(i);
  l.OffsetStep = f.strides()[axis];
  l.Length = g.Dims[axis];
  return l;
}

/// True for the nodes on the grid's outer boundary (external at every threshold, 4.4.4).
template <int D>
bool onBoundary(const std::array<Index, D>& i, const GridSpec<D>& g)
{
  bool boundary = false;
  for (int a = 0; a < D; ++a)
  {
    boundary = boundary || i[a] == 0 || i[a] == g.Dims[a] - 1;
  }
  return boundary;
}

/// The passes of the external marking (4.4.4): forward then backward along
/// every grid line of every axis, `relax(node, offset, from)` updating node
/// (storage offset `offset` in the distance) from its neighbour `from` and
/// returning true when it changed; rounds over all axes repeat until one
/// changes nothing. Lines along one axis are disjoint: each is relaxed by one
/// chunk, in any order.
template <int D, class Relax>
Status passUntilStable(const GridField<D, double>& distance, const Context& ctx, Relax&& relax, int* rounds)
{
  const GridSpec<D>& g = distance.spec();
  const Index nodes = g.nodeCount();
  int round = 0;
  for (;;)
  {
    double changes = 0.0;
    for (int axis = 0; axis < D; ++axis)
    {
      changes += ctx.parallelSum(0, nodes / g.Dims[axis],
        [&](Index b, Index e)
        {
          double changed = 0.0;
          for (Index line = b; line < e; ++line)
          {
            const Line l = gridLine(distance, axis, line);
            for (int dir = 0; dir < 2; ++dir)
            {
              for (Index s = 1; s < l.Length; ++s)
              {
                const Index t = dir == 0 ? s : l.Length - 1 - s;
                const Index from = dir == 0 ? t - 1 : t + 1;
                changed +=
                  relax(l.Node + t * l.NodeStep, l.Offset + t * l.OffsetStep, l.Node + from * l.NodeStep) ? 1.0 : 0.0;
              }
            }
          }
          return changed;
        });
    }
    ++round;
    if (changes == 0.0)
    {
      break;
    }
    if (ctx.interrupter().wasInterrupted())
    {
      return Status::aborted();
    }
  }
  if (rounds)
  {
    *rounds = round;
  }
  return Status::ok();
}
} // namespace

template <int D>
Status markExternal(const GridField<D, double>& distance, double threshold, const Context& ctx,
  std::vector<std::uint8_t>& external, int* rounds)
{
  const GridSpec<D>& g = distance.spec();
  if (!(threshold > 0.0) || !std::isfinite(threshold))
  {
    return Status::invalidArgument("the threshold gamma_P = K_P h_P must be positive and finite");
  }
  external.assign(static_cast<size_t>(g.nodeCount()), 0);
  ctx.parallelFor(0, g.nodeCount(),
    [&](Index b, Index e)
    {
      for (Index k = b; k < e; ++k)
      {
        external[static_cast<size_t>(k)] = onBoundary<D>(distance.nodeIndex(k), g) ? 1 : 0;
      }
    });
  const double* d = distance.storage().data();
  std::uint8_t* mark = external.data();
  // The marking moves inwards and stops where d(x_i) < gamma_P.
  return passUntilStable(
    distance, ctx,
    [&](Index node, Index offset, Index from)
    {
      if (!mark[node] && mark[from] && d[offset] >= threshold)
      {
        mark[node] = 1;
        return true;
      }
      return false;
    },
    rounds);
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
        bottleneck[static_cast<size_t>(k)] = onBoundary<D>(distance.nodeIndex(k), g) ? inf : -inf;
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
  if (options.Ghost < 0 || options.MaxSweepCycles < 1)
  {
    return Status::invalidArgument("initial data options: Ghost >= 0 and MaxSweepCycles >= 1");
  }
  InitialDataReport local;
  std::vector<std::uint8_t> external;
  SLTK_RETURN_IF_ERROR(markExternal(distance, threshold, ctx, external, &local.MarkingRounds));
  const GridSpec<D>& g = distance.spec();
  const Index nodes = g.nodeCount();
  // Sweep w = -phi0: w = gamma_P - d frozen on external nodes, +infinity inside.
  phi0.resize(g, options.Ghost, std::numeric_limits<double>::infinity());
  const double inf = std::numeric_limits<double>::infinity();
  const double counts = ctx.parallelSum(0, nodes,
    [&](Index b, Index e)
    {
      double ext = 0.0;
      for (Index k = b; k < e; ++k)
      {
        const auto i = phi0.nodeIndex(k);
        phi0(i) = external[static_cast<size_t>(k)] ? threshold - distance(i) : inf;
        ext += external[static_cast<size_t>(k)] ? 1.0 : 0.0;
      }
      return ext;
    });
  local.ExternalNodes = static_cast<Index>(counts);
  FastSweepingOptions sweep;
  sweep.MaxCycles = options.MaxSweepCycles;
  FastSweepingReport swept;
  SLTK_RETURN_IF_ERROR(fastSweep(phi0, external, ctx, sweep, &swept));
  local.SweepCycles = swept.Cycles;
  // phi0 = d - gamma_P outside; the swept values with reversed sign inside.
  const double below = ctx.parallelSum(0, nodes,
    [&](Index b, Index e)
    {
      double count = 0.0;
      for (Index k = b; k < e; ++k)
      {
        const auto i = phi0.nodeIndex(k);
        if (external[static_cast<size_t>(k)])
        {
          phi0(i) = distance(i) - threshold;
          count += phi0(i) < 0.0 ? 1.0 : 0.0;
        }
        else
        {
          phi0(i) = -std::max(phi0(i), 0.0);
        }
      }
      return count;
    });
  local.BoundaryBelowThreshold = static_cast<Index>(below);
  if (options.Ghost > 0)
  {
    phi0.fillGhosts();
  }
  if (report)
  {
    *report = local;
  }
  return Status::ok();
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
