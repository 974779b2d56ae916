// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ExternalMarking.h
/// The pieces of the external marking and of phi0 (CloudInitialData.h, thesis
/// 4.4.4) that the one-rank and the slab versions (CloudInitialDataSlabs.h)
/// share: grid lines, the whole grid's boundary seen from a window, the
/// passes until nothing changes, and phi0 from the marks and a sweep.

#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/levelset/FastSweeping.h"
#include "sltk/recon/CloudInitialData.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace sltk
{
namespace marking
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

/// True for the nodes on the whole grid's outer boundary (external at every
/// threshold, 4.4.4): `g` holds the rows [firstRow, firstRow + g.Dims[D-1])
/// of a grid of `rows` rows along the last axis (a slab's window; the whole
/// grid: 0 and g.Dims[D-1]).
template <int D>
bool onBoundary(const std::array<Index, D>& i, const GridSpec<D>& g, Index firstRow, Index rows)
{
  bool boundary = i[D - 1] + firstRow == 0 || i[D - 1] + firstRow == rows - 1;
  for (int a = 0; a + 1 < D; ++a)
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

/// external[k] = 1 on the whole grid's boundary nodes of `distance`'s grid
/// (rows from `firstRow` of `rows`), 0 elsewhere.
template <int D>
void markBoundary(const GridField<D, double>& distance, Index firstRow, Index rows, const Context& ctx,
  std::vector<std::uint8_t>& external)
{
  const GridSpec<D>& g = distance.spec();
  external.assign(static_cast<size_t>(g.nodeCount()), 0);
  ctx.parallelFor(0, g.nodeCount(),
    [&](Index b, Index e)
    {
      for (Index k = b; k < e; ++k)
      {
        external[static_cast<size_t>(k)] = onBoundary<D>(distance.nodeIndex(k), g, firstRow, rows) ? 1 : 0;
      }
    });
}

/// The marking moves inwards from the marked nodes and stops where d(x_i) < gamma_P.
template <int D>
Status spreadExternal(const GridField<D, double>& distance, double threshold, const Context& ctx,
  std::vector<std::uint8_t>& external, int* rounds)
{
  const double* d = distance.storage().data();
  std::uint8_t* mark = external.data();
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

/// The options' checks, and the sweep's options (CloudInitialData.h).
inline Status checkInitialDataOptions(const InitialDataOptions& options)
{
  if (options.Ghost < 0 || options.MaxSweepCycles < 1 || !(options.SweepTolerance >= 0.0))
  {
    return Status::invalidArgument("initial data options: Ghost >= 0, MaxSweepCycles >= 1 and SweepTolerance >= 0");
  }
  return Status::ok();
}

inline FastSweepingOptions sweepOptions(const InitialDataOptions& options)
{
  FastSweepingOptions sweep;
  sweep.MaxCycles = options.MaxSweepCycles;
  sweep.Tolerance = options.SweepTolerance;
  return sweep;
}

/// Step 2 of CloudInitialData.h from the marks: w = gamma_P - d frozen on the
/// external nodes, +infinity inside, swept by `sweep(phi0, frozen)` (one rank
/// or slabs), then phi0 = d - gamma_P outside and -w inside.
template <int D, class Sweep>
Status initialDataFromMarks(const GridField<D, double>& distance, double threshold,
  const std::vector<std::uint8_t>& external, const Context& ctx, GridField<D, double>& phi0,
  const InitialDataOptions& options, InitialDataReport& local, Sweep&& sweep)
{
  const GridSpec<D>& g = distance.spec();
  const Index nodes = g.nodeCount();
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
  SLTK_RETURN_IF_ERROR(sweep(phi0, external, local.SweepCycles));
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
  return Status::ok();
}

} // namespace marking
} // namespace sltk
