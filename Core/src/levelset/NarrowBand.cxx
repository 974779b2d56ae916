// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/NarrowBand.h"

#include "sltk/grid/NodeIndexer.h"
#include "sltk/levelset/CutOff.h"

#include <algorithm>
#include <cmath>

namespace sltk
{

namespace
{
/// Offset of the k-th interior node (x-fastest) from the field's storage().data().
template <int D>
Index storageOffset(const GridField<D, double>& f, Index k)
{
  return f.offset(f.nodeIndex(k));
}

/// Deterministic parallel compaction over the items [0, n) in fixed chunks of
/// `grain`: count(j) is how many entries item j gives, emit(j, to) writes them at
/// `to` and returns the end; out holds them in item order, on any thread count
/// (two passes: count, then write at the prefix offsets).
template <class Count, class Emit>
void compactBy(const Context& ctx, Index n, Index grain, Count count, Emit emit, NodeList& out)
{
  const Index chunks = n > 0 ? (n + grain - 1) / grain : 0;
  std::vector<Index> start(static_cast<size_t>(chunks) + 1, 0);
  ctx.parallelFor(
    0, n,
    [&](Index b, Index e)
    {
      Index c = 0;
      for (Index j = b; j < e; ++j)
      {
        c += count(j);
      }
      start[static_cast<size_t>(b / grain) + 1] = c;
    },
    grain);
  for (size_t c = 1; c < start.size(); ++c)
  {
    start[c] += start[c - 1];
  }
  out.resize(static_cast<size_t>(start.back()));
  ctx.parallelFor(
    0, n,
    [&](Index b, Index e)
    {
      Index* to = out.data() + start[static_cast<size_t>(b / grain)];
      for (Index j = b; j < e; ++j)
      {
        to = emit(j, to);
      }
    },
    grain);
}

/// out = [item(j) for j in [0, n) if keep(j)], in order (compactBy).
template <class Keep, class Item>
void compact(const Context& ctx, Index n, Keep keep, Item item, NodeList& out)
{
  compactBy(
    ctx, n, std::max<Index>(4096, (n + 63) / 64), [&](Index j) -> Index { return keep(j) ? 1 : 0; },
    [&](Index j, Index* to)
    {
      if (keep(j))
      {
        *to++ = item(j);
      }
      return to;
    },
    out);
}
} // namespace

template <int D>
void collectBand(const GridField<D, double>& phi, double gamma, const Context& ctx, NodeList& band)
{
  // By x lines, whose nodes are consecutive in storage: one offset a line, not a
  // multi-index a node.
  const double* p = phi.storage().data();
  const Index nx = phi.spec().Dims[0];
  const Index lines = phi.spec().nodeCount() / nx;
  const auto line = [&](Index l) { return p + storageOffset(phi, l * nx); };
  const auto inBand = [gamma](double v) { return std::fabs(v) < gamma; }; // (1.48)
  NodeList out;
  compactBy(
    ctx, lines, std::max<Index>(16, (lines + 63) / 64),
    [&](Index l)
    {
      const double* q = line(l);
      Index count = 0;
      for (Index i = 0; i < nx; ++i)
      {
        count += inBand(q[i]) ? 1 : 0;
      }
      return count;
    },
    [&](Index l, Index* to)
    {
      const double* q = line(l);
      for (Index i = 0; i < nx; ++i)
      {
        if (inBand(q[i]))
        {
          *to++ = l * nx + i;
        }
      }
      return to;
    },
    out);
  band.swap(out);
}

template <int D>
void filterBand(
  const GridField<D, double>& phi, const NodeList& candidates, double gamma, const Context& ctx, NodeList& band)
{
  const double* p = phi.storage().data();
  NodeList out;
  compact(
    ctx, static_cast<Index>(candidates.size()),
    [&](Index j) { return std::fabs(p[storageOffset(phi, candidates[static_cast<size_t>(j)])]) < gamma; },
    [&](Index j) { return candidates[static_cast<size_t>(j)]; }, out);
  band.swap(out);
}

template <int D>
void dilateBand(const GridSpec<D>& grid, const NodeList& band, int k, std::vector<std::uint8_t>& scratch,
  NodeList& dilated, const NodeList* more)
{
  const Index nodes = grid.nodeCount();
  if (static_cast<Index>(scratch.size()) != nodes)
  {
    scratch.assign(static_cast<size_t>(nodes), 0);
  }
  // The ball of radius k cells (1.53), as index offsets.
  std::vector<std::array<Index, D>> ball;
  {
    std::array<Index, D> o;
    o.fill(-k);
    for (;;)
    {
      Index r2 = 0;
      for (int a = 0; a < D; ++a)
      {
        r2 += o[a] * o[a];
      }
      if (r2 <= static_cast<Index>(k) * k)
      {
        ball.push_back(o);
      }
      int a = 0;
      for (; a < D; ++a)
      {
        if (++o[a] <= k)
        {
          break;
        }
        o[a] = -k;
      }
      if (a == D)
      {
        break;
      }
    }
  }
  std::array<Index, D> stride;
  Index s = 1;
  for (int a = 0; a < D; ++a)
  {
    stride[a] = s;
    s *= grid.Dims[a];
  }
  const NodeIndexer<D> indexer(grid.Dims);
  // The marked nodes are read back row by row, in ascending order, between each
  // x line's first and last mark: the sorted list without a sort (a sort of the
  // dilated band was the largest serial part of an iteration, Profile.md).
  const Index nx = grid.Dims[0];
  const Index rows = nodes / nx;
  std::array<Index, D> rowStride{}; // an x line's index from the node's other coordinates
  for (int a = 1; a < D; ++a)
  {
    rowStride[a] = stride[a] / nx;
  }
  std::vector<std::int32_t> first(static_cast<size_t>(rows), static_cast<std::int32_t>(nx)),
    last(static_cast<size_t>(rows), -1);
  const auto mark = [&](const Index node)
  {
    if (node < 0 || node >= nodes)
    {
      return; // not a node of this grid
    }
    const std::array<Index, D> i = indexer(node);
    for (const auto& o : ball)
    {
      bool inside = true;
      Index lin = node, row = 0;
      for (int a = 0; a < D; ++a)
      {
        const Index j = i[a] + o[a];
        inside = inside && j >= 0 && j < grid.Dims[a];
        lin += o[a] * stride[a];
        row += j * rowStride[a];
      }
      if (inside)
      {
        scratch[static_cast<size_t>(lin)] = 1;
        const auto x = static_cast<std::int32_t>(i[0] + o[0]);
        first[static_cast<size_t>(row)] = std::min(first[static_cast<size_t>(row)], x);
        last[static_cast<size_t>(row)] = std::max(last[static_cast<size_t>(row)], x);
      }
    }
  };
  for (const Index node : band)
  {
    mark(node);
  }
  if (more)
  {
    for (const Index node : *more)
    {
      mark(node);
    }
  }
  dilated.clear();
  dilated.reserve(band.size() * 2);
  for (Index row = 0; row < rows; ++row)
  {
    for (Index x = first[static_cast<size_t>(row)]; x <= last[static_cast<size_t>(row)]; ++x)
    {
      std::uint8_t& marked = scratch[static_cast<size_t>(row * nx + x)];
      if (marked)
      {
        marked = 0;
        dilated.push_back(row * nx + x);
      }
    }
  }
}

template <int D>
void cutLevelSet(GridField<D, double>& phi, const NodeList& nodes, double gamma, const Context& ctx)
{
  double* p = phi.storage().data();
  ctx.parallelFor(0, static_cast<Index>(nodes.size()),
    [&](Index b, Index e)
    {
      for (Index j = b; j < e; ++j)
      {
        double& v = p[storageOffset(phi, nodes[static_cast<size_t>(j)])];
        v = cutLevel(v, gamma); // (1.49)
      }
    });
}

template <int D>
void cutLevelSet(GridField<D, double>& phi, double gamma, const Context& ctx)
{
  double* p = phi.storage().data();
  const Index nx = phi.spec().Dims[0];
  const Index lines = phi.spec().nodeCount() / nx;
  ctx.parallelFor(0, lines,
    [&](Index b, Index e)
    {
      for (Index l = b; l < e; ++l)
      {
        double* q = p + storageOffset(phi, l * nx);
        for (Index i = 0; i < nx; ++i)
        {
          q[i] = cutLevel(q[i], gamma); // (1.49)
        }
      }
    });
}

template void collectBand(const GridField<2, double>&, double, const Context&, NodeList&);
template void collectBand(const GridField<3, double>&, double, const Context&, NodeList&);
template void filterBand(const GridField<2, double>&, const NodeList&, double, const Context&, NodeList&);
template void filterBand(const GridField<3, double>&, const NodeList&, double, const Context&, NodeList&);
template void dilateBand(
  const GridSpec<2>&, const NodeList&, int, std::vector<std::uint8_t>&, NodeList&, const NodeList*);
template void dilateBand(
  const GridSpec<3>&, const NodeList&, int, std::vector<std::uint8_t>&, NodeList&, const NodeList*);
template void cutLevelSet(GridField<2, double>&, const NodeList&, double, const Context&);
template void cutLevelSet(GridField<3, double>&, const NodeList&, double, const Context&);
template void cutLevelSet(GridField<2, double>&, double, const Context&);
template void cutLevelSet(GridField<3, double>&, double, const Context&);

} // namespace sltk
