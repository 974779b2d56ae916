// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SlabExchange.h
/// The halo exchange of a slab decomposition (Slabs.h): every rank sends its
/// first owned rows down and its last owned rows up, and receives its
/// neighbours' into its ghost rows (two paired sendReceive calls, no deadlock,
/// nothing at the domain's edges; across them when the slabs wrap,
/// SlabPlan::Periodic). One exchange moves Ghost rows (or the
/// `depth` nearest the owned rows) each way per inner boundary.

#include "sltk/exec/Communicator.h"
#include "sltk/grid/GridField.h"
#include "sltk/grid/Slabs.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace sltk
{

/// The largest buffer one message of an exchange holds: the rows go in
/// chunks of at most this many bytes (at least one row), so a wide halo (the
/// reconstruction's later runs: 24 rows of 112k nodes each way) costs no
/// whole-halo copy on top of the window (Documentation/Distributed.md).
constexpr std::size_t SlabExchangeChunkBytes = std::size_t(4) << 20;

/// The exchange over any storage of the window's rows (local row numbers,
/// slab.First is row 0): read(firstRow, rows, T* to) copies those rows' nodes
/// out (x fastest), merge(firstRow, rows, const T* from) takes the
/// neighbour's values into the ghost rows. `depth` (default: all of them)
/// limits the exchange to the ghost rows nearest the owned rows, e.g. 1 for
/// a stencil that reads one row beyond. Both neighbours cut a side's rows
/// into the same chunks (of at most chunkBytes). A collective call.
template <class T, class Read, class Merge>
void exchangeSlabRows(const SlabPlan& slab, Index rowNodes, const Communicator& comm, Read&& read, Merge&& merge,
  Index depth = std::numeric_limits<Index>::max(), std::size_t chunkBytes = SlabExchangeChunkBytes)
{
  const Index rows = slab.windowRows();
  const Index below = slab.Begin - slab.First, above = slab.Stop - slab.End; // ghost rows on each side
  const int rank = comm.rank(), size = comm.size();
  const int down = rank > 0 ? rank - 1 : slab.Periodic ? size - 1 : -1;
  const int up = rank + 1 < size ? rank + 1 : slab.Periodic ? 0 : -1;
  const Index chunkRows = std::max<Index>(1, static_cast<Index>(chunkBytes / sizeof(T)) / std::max<Index>(1, rowNodes));
  std::vector<T> send, receive;
  for (const bool toDown : { true, false })
  {
    // My ghost rows on a side are as many as the neighbour's on mine (slab.Ghost; none at the domain's edge).
    const Index sentRows = std::min(toDown ? below : above, depth), gotRows = std::min(toDown ? above : below, depth);
    const Index firstSent = toDown ? below : rows - above - sentRows,
                firstGot = toDown ? rows - above : below - gotRows;
    for (Index done = 0; done < std::max(sentRows, gotRows); done += chunkRows)
    {
      const Index sent = std::clamp<Index>(sentRows - done, 0, chunkRows),
                  got = std::clamp<Index>(gotRows - done, 0, chunkRows);
      send.resize(static_cast<size_t>(sent * rowNodes));
      receive.resize(static_cast<size_t>(got * rowNodes));
      read(firstSent + done, sent, send.data());
      comm.sendReceive(send.data(), send.size() * sizeof(T), sent > 0 ? (toDown ? down : up) : -1, receive.data(),
        receive.size() * sizeof(T), got > 0 ? (toDown ? up : down) : -1);
      merge(firstGot + done, got, static_cast<const T*>(receive.data()));
    }
  }
}

/// Calls line(T* first, Index count, Index node) for every x-line of the rows
/// [firstRow, firstRow + rows) of the last axis of `window` (window numbering;
/// `node` the line's first node number, x fastest): the contiguous runs of
/// storage those rows are made of. `Field` may be const.
template <class Field, class Line>
void forEachRowLine(Field& window, Index firstRow, Index rows, Line&& line)
{
  constexpr int D = std::decay_t<Field>::Dim;
  const auto& dims = window.spec().Dims;
  const Index length = D == 1 ? 1 : dims[0];
  const Index linesPerRow = D == 1 ? 1 : window.spec().nodeCount() / dims[D - 1] / length;
  for (Index l = firstRow * linesPerRow; l < (firstRow + rows) * linesPerRow; ++l)
  {
    std::array<Index, D> i{};
    Index rest = l;
    for (int a = D == 1 ? 0 : 1; a < D; ++a)
    {
      i[static_cast<size_t>(a)] = rest % dims[static_cast<size_t>(a)];
      rest /= dims[static_cast<size_t>(a)];
    }
    line(window.pointer(i), length, l * length);
  }
}

/// Overwrites the ghost rows of `window` (rows slab.First .. slab.Stop - 1 of
/// the last axis), or the `depth` nearest the owned rows, with the owners'
/// values; `changed` (optional) tells whether any of this rank's ghost values
/// changed. A collective call; chunkBytes as exchangeSlabRows.
template <int D, class T>
void exchangeGhostRows(GridField<D, T>& window, const SlabPlan& slab, const Communicator& comm, bool* changed = nullptr,
  Index depth = std::numeric_limits<Index>::max(), std::size_t chunkBytes = SlabExchangeChunkBytes)
{
  const Index rowNodes = window.spec().nodeCount() / window.spec().Dims[D - 1];
  bool differs = false;
  exchangeSlabRows<T>(
    slab, rowNodes, comm,
    [&](Index first, Index count, T* to)
    {
      forEachRowLine(window, first, count,
        [&](const T* line, Index length, Index node)
        { std::copy(line, line + length, to + (node - first * rowNodes)); });
    },
    [&](Index first, Index count, const T* from)
    {
      forEachRowLine(window, first, count,
        [&](T* line, Index length, Index node)
        {
          const T* in = from + (node - first * rowNodes);
          if (changed && !differs)
          {
            differs = !std::equal(line, line + length, in);
          }
          std::copy(in, in + length, line);
        });
    },
    depth, chunkBytes);
  if (changed)
  {
    *changed = differs;
  }
}

/// The whole grid `whole` on every rank from each rank's owned rows of its
/// `window` (slab.Begin .. slab.End - 1; the slabs tile the rows in rank
/// order), with `ghost` ghost layers (not filled). A collective call: the
/// tiled reconstruction's run 1, computed on slabs and small, read whole by
/// every rank's transfer (octree/TiledReconstruction.h).
template <int D, class T>
GridField<D, T> gatherSlabRows(
  const GridField<D, T>& window, const SlabPlan& slab, const GridSpec<D>& whole, int ghost, const Communicator& comm)
{
  static_assert(std::is_trivially_copyable<T>::value, "rows are sent as raw bytes");
  const Index rowNodes = whole.nodeCount() / whole.Dims[D - 1];
  std::vector<T> mine(static_cast<size_t>((slab.End - slab.Begin) * rowNodes));
  forEachRowLine(window, slab.Begin - slab.First, slab.End - slab.Begin,
    [&](const T* line, Index length, Index node)
    { std::copy(line, line + length, mine.data() + (node - (slab.Begin - slab.First) * rowNodes)); });
  const std::vector<T> all = comm.allGatherV(mine);
  GridField<D, T> field(whole, ghost);
  forEachRowLine(field, 0, whole.Dims[D - 1],
    [&](T* line, Index length, Index node) { std::copy(all.data() + node, all.data() + node + length, line); });
  return field;
}

} // namespace sltk
