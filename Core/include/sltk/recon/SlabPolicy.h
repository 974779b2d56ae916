// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SlabPolicy.h
/// How the reconstruction cuts every run's grid into slabs of the last axis
/// over the ranks (src/recon/RunSlab.h, Documentation/Distributed.md): the
/// boundaries every rank computes alike from the plan, and the largest window
/// a rank then holds, which the memory check sizes before any work
/// (planRunGrids, ReconstructionPlan.h).

#include "sltk/cloud/PointCloud.h"
#include "sltk/grid/GridSpec.h"
#include "sltk/grid/Slabs.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sltk
{

/// Ghost rows on each inner side of every run's slabs: the stencils of the
/// band, the reinitialisation and the usual feet fit; the feet beyond are
/// interpolated by their owners (FarFeetExchange.h).
constexpr Index SlabGhostRows = 6;

/// Run 1's split gives every rank the same weight of cloud points and rows,
/// a row weighing this many times the mean points per row: the band's work
/// follows the surface the cloud samples, the fields, the ghost-row scans and
/// the exchanges follow the rows. Bunny, 2 ranks: 0.1 made the largest rank 5%
/// bigger for no speed, even rows were 6% slower (Documentation/Distributed.md).
constexpr double SlabRowWeight = 2.0;

/// The row of `whole` at the floor of last-axis coordinate z, clamped to its
/// rows: where a point weighs (run 1's split) and whose owner interpolates a
/// far foot (FarFeetExchange.h).
template <int D>
Index slabRowAt(const GridSpec<D>& whole, double z)
{
  const double row = std::floor(whole.indexCoordinate(D - 1, z));
  return static_cast<Index>(std::clamp(row, 0.0, static_cast<double>(whole.Dims[D - 1] - 1)));
}

/// Every rank's first row of `whole`, and its row count, over `ranks` ranks.
/// Run 1 (`previous` null): balanced by the cloud's points plus SlabRowWeight.
/// A later run cuts its finer grid where the `previous` run's slabs (on
/// `previousWhole`) meet, so that each rank's owned rows lie in its previous
/// window (the transfer is local); the even split when the rows are too few
/// (planSlabAt then refuses).
template <int D>
std::vector<Index> slabBoundaries(const GridSpec<D>& whole, int ranks, const PointCloud<D>& cloud,
  const GridSpec<D>* previousWhole = nullptr, const std::vector<Index>* previous = nullptr)
{
  const Index rows = whole.Dims[D - 1];
  if (ranks <= 1)
  {
    return { 0, rows };
  }
  if (previous && rows >= SlabGhostRows * ranks)
  {
    std::vector<Index> boundaries(static_cast<size_t>(ranks) + 1, rows);
    boundaries[0] = 0;
    for (int r = 1; r < ranks; ++r)
    {
      const double z = previousWhole->coordinate(D - 1, (*previous)[static_cast<size_t>(r)]);
      const Index row = static_cast<Index>(std::lround(whole.indexCoordinate(D - 1, z)));
      boundaries[static_cast<size_t>(r)] =
        std::clamp(row, boundaries[static_cast<size_t>(r) - 1] + SlabGhostRows, rows - SlabGhostRows * (ranks - r));
    }
    return boundaries;
  }
  if (previous)
  {
    return evenSlabBoundaries(rows, ranks);
  }
  std::vector<double> weights(static_cast<size_t>(rows), SlabRowWeight * static_cast<double>(cloud.size()) / rows);
  for (const auto& p : cloud.Points)
  {
    weights[static_cast<size_t>(slabRowAt(whole, p[D - 1]))] += 1.0;
  }
  return balancedSlabBoundaries(weights, ranks, SlabGhostRows);
}

/// The most nodes a rank's window holds (its owned rows and SlabGhostRows on
/// each inner side) on `whole` cut at `boundaries`.
template <int D>
double largestSlabWindowNodes(const GridSpec<D>& whole, const std::vector<Index>& boundaries)
{
  const Index rows = whole.Dims[D - 1];
  const double rowNodes = static_cast<double>(whole.nodeCount() / rows);
  Index largest = 0;
  for (size_t r = 0; r + 1 < boundaries.size(); ++r)
  {
    const Index first = std::max<Index>(0, boundaries[r] - SlabGhostRows);
    const Index stop = std::min(rows, boundaries[r + 1] + SlabGhostRows);
    largest = std::max(largest, stop - first);
  }
  return rowNodes * static_cast<double>(largest);
}

} // namespace sltk
