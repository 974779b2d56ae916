// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/NarrowBand.h"

#include "sltk/core/ResizeForOverwrite.h"
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
/// `grain`: countChunk(b, e) is how many entries the items [b, e) give,
/// emitChunk(b, e, to) writes them at `to`; out holds them in item order, on
/// any thread count (two passes: count, then write at the prefix offsets;
/// ThreadPool.h: chunk c is [c grain, (c + 1) grain)). `out` is written in
/// place (its capacity reused), so it must not be an input of the callbacks.
template <class CountChunk, class EmitChunk>
void compactChunks(const Context& ctx, Index n, Index grain, CountChunk countChunk, EmitChunk emitChunk, NodeList& out)
{
  const Index chunks = n > 0 ? (n + grain - 1) / grain : 0;
  std::vector<Index> start(static_cast<size_t>(chunks) + 1, 0);
  ctx.parallelFor(
    0, n, [&](Index b, Index e) { start[static_cast<size_t>(b / grain) + 1] = countChunk(b, e); }, grain);
  for (size_t c = 1; c < start.size(); ++c)
  {
    start[c] += start[c - 1];
  }
  resizeForOverwrite(out, static_cast<size_t>(start.back()));
  ctx.parallelFor(
    0, n, [&](Index b, Index e) { emitChunk(b, e, out.data() + start[static_cast<size_t>(b / grain)]); }, grain);
}

/// compactChunks() item by item: count(j) is how many entries item j gives,
/// emit(j, to) writes them at `to` and returns the end.
template <class Count, class Emit>
void compactBy(const Context& ctx, Index n, Index grain, Count count, Emit emit, NodeList& out)
{
  compactChunks(
    ctx, n, grain,
    [&](Index b, Index e)
    {
      Index c = 0;
      for (Index j = b; j < e; ++j)
      {
        c += count(j);
      }
      return c;
    },
    [&](Index b, Index e, Index* to)
    {
      for (Index j = b; j < e; ++j)
      {
        to = emit(j, to);
      }
    },
    out);
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

/// write(list) fills `output` in place, or a new list swapped in when `output`
/// is also an input of the call (`isInput`), which write() reads while it writes.
template <class Write>
void writeList(NodeList& output, bool isInput, Write write)
{
  NodeList fresh;
  write(isInput ? fresh : output);
  if (isInput)
  {
    output.swap(fresh);
  }
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
    band); // written in place: its capacity from the previous call is reused (no new pages)
}

template <int D>
void filterBand(
  const GridField<D, double>& phi, const NodeList& candidates, double gamma, const Context& ctx, NodeList& band)
{
  const double* p = phi.storage().data();
  writeList(band, &band == &candidates,
    [&](NodeList& out)
    {
      compact(
        ctx, static_cast<Index>(candidates.size()),
        [&](Index j) { return std::fabs(p[storageOffset(phi, candidates[static_cast<size_t>(j)])]) < gamma; },
        [&](Index j) { return candidates[static_cast<size_t>(j)]; }, out);
    });
}

namespace
{
/// The ball of radius k cells (1.53) grouped by x line: for each offset of the
/// other coordinates (o_1, ..., o_{D-1}), the half-width m of its x offsets
/// -m..m (those with |o|^2 <= k^2).
template <int D>
struct BallRows
{
  std::vector<std::array<Index, D>> Rows; ///< [0] unused
  std::vector<Index> HalfWidth;

  explicit BallRows(int k)
  {
    const Index k2 = static_cast<Index>(k) * k;
    std::array<Index, D> o;
    o.fill(-k);
    for (;;)
    {
      Index r2 = 0;
      for (int a = 1; a < D; ++a)
      {
        r2 += o[a] * o[a];
      }
      if (r2 <= k2)
      {
        Index m = 0;
        while (r2 + (m + 1) * (m + 1) <= k2)
        {
          ++m;
        }
        this->Rows.push_back(o);
        this->HalfWidth.push_back(m);
      }
      int a = 1;
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
};

/// A list of grid nodes by x line: line r's nodes are Nodes[Begin[r], Begin[r + 1]),
/// ascending (a copy is sorted when the list is not); nodes outside the grid are left out.
struct NodesByLine
{
  const NodeList* Nodes = nullptr;
  NodeList Sorted;
  std::vector<Index> Begin;

  NodesByLine(const NodeList& nodes, Index nodeCount, Index nx, const Context& ctx)
  {
    this->Nodes = &nodes;
    if (!std::is_sorted(nodes.begin(), nodes.end()))
    {
      this->Sorted = nodes;
      std::sort(this->Sorted.begin(), this->Sorted.end());
      this->Nodes = &this->Sorted;
    }
    const Index lines = nodeCount / nx;
    this->Begin.resize(static_cast<size_t>(lines) + 1);
    const NodeList& list = *this->Nodes;
    ctx.parallelFor(0, lines + 1,
      [&](Index b, Index e)
      {
        for (Index r = b; r < e; ++r)
        {
          this->Begin[static_cast<size_t>(r)] =
            std::lower_bound(list.begin(), list.end(), r * nx) - list.begin(); // r * nx: the grid's end at r = lines
        }
      });
  }
};
} // namespace

template <int D>
void dilateBand(
  const GridSpec<D>& grid, const NodeList& band, int k, const Context& ctx, NodeList& dilated, const NodeList* more)
{
  // x line by x line (x fastest, so lines and the nodes in them are in
  // ascending order): line r's dilation is its own band nodes and those of the
  // lines the ball reaches, shifted along x. A line's marks live in a scratch
  // line of nx bytes, not in a mask over the grid, and the lines are
  // independent: both threads work, and the list comes out sorted without a sort.
  const Index nodes = grid.nodeCount();
  const Index nx = grid.Dims[0];
  const Index lines = nodes / nx;
  const BallRows<D> ball(k);
  std::vector<NodesByLine> lists;
  lists.emplace_back(band, nodes, nx, ctx);
  if (more)
  {
    lists.emplace_back(*more, nodes, nx, ctx);
  }
  // Marks line r in `marks` (nx bytes, all zero), returns the marked x range.
  const auto markLine = [&](Index r, std::uint8_t* marks, Index& lo, Index& hi)
  {
    std::array<Index, D> at{}; // line r's coordinates 1..D-1
    Index rest = r;
    for (int a = 1; a < D; ++a)
    {
      at[a] = rest % grid.Dims[a];
      rest /= grid.Dims[a];
    }
    lo = nx;
    hi = -1;
    for (size_t g = 0; g < ball.Rows.size(); ++g)
    {
      Index source = 0, stride = 1;
      bool inside = true;
      for (int a = 1; a < D; ++a)
      {
        const Index j = at[a] - ball.Rows[g][a];
        inside = inside && j >= 0 && j < grid.Dims[a];
        source += j * stride;
        stride *= grid.Dims[a];
      }
      if (!inside)
      {
        continue;
      }
      const Index m = ball.HalfWidth[g];
      for (const NodesByLine& list : lists)
      {
        const Index begin = list.Begin[static_cast<size_t>(source)], end = list.Begin[static_cast<size_t>(source) + 1];
        if (begin == end)
        {
          continue;
        }
        const Index* x = list.Nodes->data();
        const Index origin = source * nx;
        lo = std::min(lo, std::max<Index>(0, x[begin] - origin - m)); // the line's nodes ascend
        hi = std::max(hi, std::min(nx - 1, x[end - 1] - origin + m));
        for (Index p = begin; p < end; ++p)
        {
          const Index first = std::max<Index>(0, x[p] - origin - m), last = std::min(nx - 1, x[p] - origin + m);
          for (Index to = first; to <= last; ++to)
          {
            marks[to] = 1;
          }
        }
      }
    }
  };
  // The lines in chunks of fixed size (compactChunks: the same list on any
  // thread count): each chunk marks its lines to count their nodes, then again
  // to write them straight into the output. Lists per chunk would hold the
  // dilation a second time beside the run's other per-node arrays
  // (Documentation/Profile.md, "Page faults of the per-iteration arrays").
  const Index grain = std::max<Index>(16, (lines + 63) / 64);
  // The lines [b, e): their nodes written at `to`, or only counted when it is null.
  const auto sweepLines = [&](Index b, Index e, Index* to)
  {
    std::vector<std::uint8_t> marks(static_cast<size_t>(nx), 0);
    Index count = 0;
    for (Index r = b; r < e; ++r)
    {
      Index lo = 0, hi = -1;
      markLine(r, marks.data(), lo, hi);
      for (Index x = lo; x <= hi; ++x)
      {
        if (marks[static_cast<size_t>(x)])
        {
          marks[static_cast<size_t>(x)] = 0;
          if (to)
          {
            to[count] = r * nx + x;
          }
          ++count;
        }
      }
    }
    return count;
  };
  writeList(dilated, &dilated == &band || &dilated == more,
    [&](NodeList& out)
    {
      compactChunks(
        ctx, lines, grain, [&](Index b, Index e) { return sweepLines(b, e, nullptr); },
        [&](Index b, Index e, Index* to) { sweepLines(b, e, to); }, out);
    });
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
template void dilateBand(const GridSpec<2>&, const NodeList&, int, const Context&, NodeList&, const NodeList*);
template void dilateBand(const GridSpec<3>&, const NodeList&, int, const Context&, NodeList&, const NodeList*);
template void cutLevelSet(GridField<2, double>&, const NodeList&, double, const Context&);
template void cutLevelSet(GridField<3, double>&, const NodeList&, double, const Context&);
template void cutLevelSet(GridField<2, double>&, double, const Context&);
template void cutLevelSet(GridField<3, double>&, double, const Context&);

} // namespace sltk
