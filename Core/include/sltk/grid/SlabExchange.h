// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SlabExchange.h
/// The halo exchange of a slab decomposition (Slabs.h): every rank sends its
/// first owned rows down and its last owned rows up, and receives its
/// neighbours' into its ghost rows (two paired sendReceive calls, no deadlock,
/// nothing at the domain's edges). One exchange moves 2 Ghost rows each way
/// per inner boundary.

#include "sltk/exec/Communicator.h"
#include "sltk/grid/GridField.h"
#include "sltk/grid/Slabs.h"

#include <vector>

namespace sltk
{

/// Overwrites the ghost rows of `window` (rows slab.First .. slab.Stop - 1 of
/// the last axis) with the owners' values; `changed` (optional) tells whether
/// any of this rank's ghost values changed. A collective call.
template <int D, class T>
void exchangeGhostRows(GridField<D, T>& window, const SlabPlan& slab, const Communicator& comm, bool* changed = nullptr)
{
  const Index rows = window.spec().Dims[D - 1];
  const Index rowNodes = window.spec().nodeCount() / rows;
  const Index below = slab.Begin - slab.First, above = slab.Stop - slab.End; // ghost rows on each side
  const int rank = comm.rank(), size = comm.size();
  const int down = rank > 0 ? rank - 1 : -1, up = rank + 1 < size ? rank + 1 : -1;
  std::vector<T> send, receive;
  bool differs = false;
  // Reads or writes the rows [first, first + count) of the window.
  auto rowsOf = [&](Index first, Index count, std::vector<T>& values, bool write)
  {
    values.resize(static_cast<size_t>(count * rowNodes));
    for (Index k = 0; k < count * rowNodes; ++k)
    {
      T& value = window(window.nodeIndex(first * rowNodes + k));
      if (write)
      {
        differs = differs || !(value == values[static_cast<size_t>(k)]);
        value = values[static_cast<size_t>(k)];
      }
      else
      {
        values[static_cast<size_t>(k)] = value;
      }
    }
  };
  for (const bool toDown : { true, false })
  {
    // My ghost rows on a side are as many as the neighbour's on mine (slab.Ghost; none at the domain's edge).
    const Index sentRows = toDown ? below : above, gotRows = toDown ? above : below;
    rowsOf(toDown ? below : rows - above - sentRows, sentRows, send, false);
    receive.resize(static_cast<size_t>(gotRows * rowNodes));
    comm.sendReceive(send.data(), send.size() * sizeof(T), toDown ? down : up, receive.data(),
      receive.size() * sizeof(T), toDown ? up : down);
    rowsOf(toDown ? rows - above : 0, gotRows, receive, true);
  }
  if (changed)
  {
    *changed = differs;
  }
}

} // namespace sltk
