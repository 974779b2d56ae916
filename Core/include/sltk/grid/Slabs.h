// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Slabs.h
/// The block decomposition of SLTK's distributed uniform-grid solvers
/// (Documentation/Distributed.md): the last axis' rows are cut into one slab
/// per rank, rank r owning rows [rows r / P, rows (r + 1) / P), and each rank
/// works on a window of its owned rows plus `ghost` rows on each side (fewer
/// at the domain's edges), at the whole grid's coordinates (GridSpec::Offset).

#include "sltk/core/Index.h"
#include "sltk/core/Status.h"

#include <algorithm>
#include <string>

namespace sltk
{

/// This rank's slab: owned rows [Begin, End) of the last axis, worked on
/// [First, Stop) (Ghost rows on each side, fewer at the domain's edges).
struct SlabPlan
{
  Index First = 0, Begin = 0, End = 0, Stop = 0, Ghost = 0;
  Index windowRows() const { return this->Stop - this->First; }
};

/// The first row rank `rank` of `size` owns (rank == size: the row after the last).
inline Index slabBegin(Index rows, int rank, int size)
{
  return rows * rank / size;
}

/// Rank `rank` of `size`'s slab of `rows` rows with `ghost` ghost rows;
/// refuses fewer than `ghost` owned rows a rank, naming `why` the ghost rows
/// are needed and the fix.
inline Status planSlab(Index rows, Index ghost, int rank, int size, const std::string& why, SlabPlan& plan)
{
  if (rows / size < std::max<Index>(ghost, 1))
  {
    return Status::invalidArgument("the grid has " + std::to_string(rows) + " rows along its last axis for " +
      std::to_string(size) + " ranks, fewer than the " + std::to_string(std::max<Index>(ghost, 1)) + " each needs (" +
      why + "): use fewer ranks or more nodes");
  }
  plan.Ghost = ghost;
  plan.Begin = slabBegin(rows, rank, size);
  plan.End = slabBegin(rows, rank + 1, size);
  plan.First = std::max<Index>(0, plan.Begin - ghost);
  plan.Stop = std::min(rows, plan.End + ghost);
  return Status::ok();
}

} // namespace sltk
