// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Slabs.h
/// The block decomposition of SLTK's distributed uniform-grid solvers
/// (Documentation/Distributed.md): the last axis' rows are cut into one slab
/// per rank, evenly (HJB: rank r owns rows [rows r / P, rows (r + 1) / P)) or
/// at given boundaries (the reconstruction balances its band), and each rank
/// works on a window of its owned rows plus `ghost` rows on each side (fewer
/// at the domain's edges), at the whole grid's coordinates (GridSpec::Offset).
/// A periodic last axis (HJB, thesis 3.5) wraps: every rank has ghost rows on
/// both sides, the first rank's below row 0 (rows -Ghost .. -1 are rows
/// rows - Ghost .. rows - 1) and the last rank's past the last row.

#include "sltk/core/Index.h"
#include "sltk/core/Status.h"

#include <algorithm>
#include <string>
#include <vector>

namespace sltk
{

/// This rank's slab: owned rows [Begin, End) of the last axis, worked on
/// [First, Stop) (Ghost rows on each side, fewer at the domain's edges unless
/// Periodic: then First may be negative and Stop past the last row, the rows
/// of the other end of the axis).
struct SlabPlan
{
  Index First = 0, Begin = 0, End = 0, Stop = 0, Ghost = 0;
  bool Periodic = false; ///< the last axis wraps: the first and the last ranks are neighbours
  Index windowRows() const { return this->Stop - this->First; }
};

/// The first row rank `rank` of `size` owns in the even split (rank == size: the row after the last).
inline Index evenSlabBegin(Index rows, int rank, int size)
{
  return rows * rank / size;
}

/// Rank `rank`'s slab of `boundaries` (size + 1 rows, ascending: rank r owns
/// rows [boundaries[r], boundaries[r + 1])) with `ghost` ghost rows; refuses
/// fewer than `ghost` owned rows a rank, naming `why` the ghost rows are
/// needed and the fix. `periodic`: the last axis wraps (SlabPlan::Periodic).
inline Status planSlabAt(const std::vector<Index>& boundaries, Index ghost, int rank, const std::string& why,
  SlabPlan& plan, bool periodic = false)
{
  const int size = static_cast<int>(boundaries.size()) - 1;
  const Index rows = boundaries.back(), least = std::max<Index>(ghost, 1);
  for (int r = 0; r < size; ++r)
  {
    if (boundaries[static_cast<size_t>(r) + 1] - boundaries[static_cast<size_t>(r)] < least)
    {
      return Status::invalidArgument("the grid has " + std::to_string(rows) + " rows along its last axis for " +
        std::to_string(size) + " ranks, fewer than the " + std::to_string(least) + " each needs (" + why +
        "): use fewer ranks or more nodes");
    }
  }
  plan.Ghost = ghost;
  plan.Begin = boundaries[static_cast<size_t>(rank)];
  plan.End = boundaries[static_cast<size_t>(rank) + 1];
  plan.Periodic = periodic && size > 1;
  plan.First = plan.Periodic ? plan.Begin - ghost : std::max<Index>(0, plan.Begin - ghost);
  plan.Stop = plan.Periodic ? plan.End + ghost : std::min(rows, plan.End + ghost);
  return Status::ok();
}

/// One rank's slab holding every row of `rows` (no ghost rows): the slab
/// functions' one-rank call, so that one rank runs the code of many.
inline SlabPlan wholeSlab(Index rows)
{
  SlabPlan plan;
  plan.End = plan.Stop = rows;
  return plan;
}

/// The even boundaries of `rows` rows over `size` ranks (evenSlabBegin).
inline std::vector<Index> evenSlabBoundaries(Index rows, int size)
{
  std::vector<Index> boundaries(static_cast<size_t>(size) + 1);
  for (int r = 0; r <= size; ++r)
  {
    boundaries[static_cast<size_t>(r)] = evenSlabBegin(rows, r, size);
  }
  return boundaries;
}

/// The rank owning `row` of slabs cut at `boundaries` (every rank's first
/// row, and the row count); rows beyond the grid belong to the edge ranks.
inline int slabOwnerOfRow(const std::vector<Index>& boundaries, Index row)
{
  return static_cast<int>(
    std::upper_bound(boundaries.begin() + 1, boundaries.end() - 1, row) - (boundaries.begin() + 1));
}

/// Boundaries that give every rank about the same share of `weights` (one
/// per row, >= 0, e.g. the work a row makes) and at least `least` rows each
/// where the rows allow it (else the even split, which planSlabAt refuses).
inline std::vector<Index> balancedSlabBoundaries(const std::vector<double>& weights, int size, Index least)
{
  const Index rows = static_cast<Index>(weights.size());
  if (rows < least * size)
  {
    return evenSlabBoundaries(rows, size);
  }
  double total = 0.0;
  for (const double w : weights)
  {
    total += w;
  }
  std::vector<Index> boundaries(static_cast<size_t>(size) + 1, rows);
  boundaries[0] = 0;
  double sum = 0.0;
  Index row = 0;
  for (int r = 1; r < size; ++r)
  {
    const double target = total * r / size;
    while (row < rows && sum + weights[static_cast<size_t>(row)] <= target)
    {
      sum += weights[static_cast<size_t>(row++)];
    }
    // At least `least` rows for this rank and for each rank above it.
    const Index b = std::clamp(row, boundaries[static_cast<size_t>(r) - 1] + least, rows - least * (size - r));
    for (; row < b; ++row)
    {
      sum += weights[static_cast<size_t>(row)];
    }
    for (; row > b; --row)
    {
      sum -= weights[static_cast<size_t>(row) - 1];
    }
    boundaries[static_cast<size_t>(r)] = b;
  }
  return boundaries;
}

/// Rank `rank` of `size`'s slab of `rows` rows, split evenly, with `ghost`
/// ghost rows (planSlabAt; `periodic`: the last axis wraps).
inline Status planSlab(
  Index rows, Index ghost, int rank, int size, const std::string& why, SlabPlan& plan, bool periodic = false)
{
  return planSlabAt(evenSlabBoundaries(rows, size), ghost, rank, why, plan, periodic);
}

} // namespace sltk
