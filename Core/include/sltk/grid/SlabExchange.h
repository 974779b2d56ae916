// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SlabExchange.h
/// The halo exchange of a slab decomposition (Slabs.h): every rank sends its
/// first owned rows down and its last owned rows up, and receives its
/// neighbours' into its ghost rows (two paired sendReceive calls, no deadlock,
/// nothing at the domain's edges). One exchange moves Ghost rows each way per
/// inner boundary and direction.

#include "sltk/exec/Communicator.h"
#include "sltk/grid/GridField.h"
#include "sltk/grid/Slabs.h"

#include <vector>

namespace sltk
{

/// The exchange over any storage of the window's rows (local row numbers,
/// slab.First is row 0): read(firstRow, rows, T* to) copies those rows' nodes
/// out (x fastest), merge(firstRow, rows, const T* from) takes the
/// neighbour's values into the ghost rows. A collective call.
template <class T, class Read, class Merge>
void exchangeSlabRows(const SlabPlan& slab, Index rowNodes, const Communicator& comm, Read&& read, Merge&& merge)
{
  const Index rows = slab.windowRows();
  const Index below = slab.Begin - slab.First, above = slab.Stop - slab.End; // ghost rows on each side
  const int rank = comm.rank(), size = comm.size();
  const int down = rank > 0 ? rank - 1 : -1, up = rank + 1 < size ? rank + 1 : -1;
  std::vector<T> send, receive;
  for (const bool toDown : { true, false })
  {
    // My ghost rows on a side are as many as the neighbour's on mine (slab.Ghost; none at the domain's edge).
    const Index sentRows = toDown ? below : above, gotRows = toDown ? above : below;
    send.resize(static_cast<size_t>(sentRows * rowNodes));
    receive.resize(static_cast<size_t>(gotRows * rowNodes));
    read(toDown ? below : rows - above - sentRows, sentRows, send.data());
    comm.sendReceive(send.data(), send.size() * sizeof(T), toDown ? down : up, receive.data(),
      receive.size() * sizeof(T), toDown ? up : down);
    merge(toDown ? rows - above : 0, gotRows, static_cast<const T*>(receive.data()));
  }
}

/// Overwrites the ghost rows of `window` (rows slab.First .. slab.Stop - 1 of
/// the last axis) with the owners' values; `changed` (optional) tells whether
/// any of this rank's ghost values changed. A collective call.
template <int D, class T>
void exchangeGhostRows(GridField<D, T>& window, const SlabPlan& slab, const Communicator& comm, bool* changed = nullptr)
{
  const Index rowNodes = window.spec().nodeCount() / window.spec().Dims[D - 1];
  bool differs = false;
  exchangeSlabRows<T>(
    slab, rowNodes, comm,
    [&](Index first, Index count, T* to)
    {
      for (Index k = 0; k < count * rowNodes; ++k)
      {
        to[k] = window(window.nodeIndex(first * rowNodes + k));
      }
    },
    [&](Index first, Index count, const T* from)
    {
      for (Index k = 0; k < count * rowNodes; ++k)
      {
        T& value = window(window.nodeIndex(first * rowNodes + k));
        differs = differs || !(value == from[k]);
        value = from[k];
      }
    });
  if (changed)
  {
    *changed = differs;
  }
}

} // namespace sltk
