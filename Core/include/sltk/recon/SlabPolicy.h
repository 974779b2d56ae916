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
#include <numeric>
#include <utility>
#include <vector>

namespace sltk
{

/// Ghost rows on each inner side of every run's slabs: the stencils of the
/// band, the reinitialisation and the usual feet fit; the feet beyond are
/// interpolated by their owners (FarFeetExchange.h).
constexpr Index SlabGhostRows = 6;

/// Run 1's split gives every rank the same weight of cloud points and rows,
/// a row weighing this many times the mean points per row: the band's work
/// follows the surface the cloud samples, the fields follow the rows. Bunny,
/// 2 ranks, side by side: 2 left 56% of the band on one rank (1.67x, largest
/// rank 0.61 of one rank's memory), 0.25 with the later runs' cuts following
/// the band gives 52% (1.79x, 0.63): Documentation/Distributed.md.
constexpr double SlabRowWeight = 0.25;

/// How far a cut may move from the even split of the rows, as a fraction of
/// a rank's even share: the band decides where the work balances, but the
/// fields follow the rows, so no rank gets more than a quarter more rows than
/// the even split gives it. Fandisk (its band is uneven along z), 2 ranks,
/// side by side: a tenth: 1.37x, largest rank 0.66 of one rank's memory; a
/// quarter: 1.54x, 0.69; a half: 1.73x, 0.80; no limit: 1.74x, 0.79.
constexpr double SlabRowShareSlack = 0.25;

/// The cut between ranks r - 1 and r moved no farther than SlabRowShareSlack
/// of a rank's even share of `rows` from the even cut.
inline Index limitRowShare(Index cut, Index rows, int r, int ranks)
{
  const Index even = evenSlabBegin(rows, r, ranks);
  const Index slack = static_cast<Index>(SlabRowShareSlack * static_cast<double>(rows) / ranks);
  return std::clamp(cut, even - slack, even + slack);
}

/// `boundaries` with every inner cut limited by limitRowShare(), keeping
/// SlabGhostRows a rank.
inline std::vector<Index> limitRowShares(std::vector<Index> boundaries)
{
  const int ranks = static_cast<int>(boundaries.size()) - 1;
  const Index rows = boundaries.back();
  for (int r = 1; r < ranks; ++r)
  {
    Index& cut = boundaries[static_cast<size_t>(r)];
    cut = std::clamp(limitRowShare(cut, rows, r, ranks), boundaries[static_cast<size_t>(r) - 1] + SlabGhostRows,
      rows - SlabGhostRows * (ranks - r));
  }
  return boundaries;
}

/// The row of `whole` at the floor of last-axis coordinate z, clamped to its
/// rows: where a point weighs (run 1's split) and whose owner interpolates a
/// far foot (FarFeetExchange.h).
template <int D>
Index slabRowAt(const GridSpec<D>& whole, double z)
{
  const double row = std::floor(whole.indexCoordinate(D - 1, z));
  return static_cast<Index>(std::clamp(row, 0.0, static_cast<double>(whole.Dims[D - 1] - 1)));
}

/// The (fractional) row of `whole` at row `previousRow` of `previousWhole`,
/// the grid of the run before: where a later run's cuts are placed from the
/// previous run's.
template <int D>
double rowOfPreviousRow(const GridSpec<D>& whole, const GridSpec<D>& previousWhole, double previousRow)
{
  return whole.indexCoordinate(D - 1, previousWhole.coordinate(D - 1, 0) + previousRow * previousWhole.Spacing[D - 1]);
}

/// The rows of `whole` where a later run may cut between two ranks whose
/// previous run (on `previousWhole`) was cut at `previousCut`: each rank's
/// owned rows must lie inside its previous window, SlabGhostRows beyond the
/// cut, with a row to spare (the transfer, Reconstruction.cxx, checks it).
/// First and last row the upper rank may start at.
template <int D>
std::pair<Index, Index> laterCutRange(const GridSpec<D>& whole, const GridSpec<D>& previousWhole, Index previousCut)
{
  const auto rowOf = [&](Index previousRow)
  { return rowOfPreviousRow(whole, previousWhole, static_cast<double>(previousRow)); };
  return { static_cast<Index>(std::ceil(rowOf(previousCut - SlabGhostRows + 2))),
    static_cast<Index>(std::floor(rowOf(previousCut + SlabGhostRows - 3))) + 1 };
}

/// The row of `whole` at the last-axis coordinate where the previous run's
/// band (`previousBand`, nodes per row of `previousWhole`, summed over the
/// ranks) reaches `share` of its nodes; -1 without a band.
template <int D>
Index bandShareRow(
  const GridSpec<D>& whole, const GridSpec<D>& previousWhole, const std::vector<double>& previousBand, double share)
{
  const double total = std::accumulate(previousBand.begin(), previousBand.end(), 0.0);
  if (!(total > 0.0))
  {
    return -1;
  }
  const double goal = share * total;
  double below = 0.0;
  for (size_t row = 0; row < previousBand.size(); ++row)
  {
    if (below + previousBand[row] >= goal && previousBand[row] > 0.0)
    {
      // Rows as cells of one spacing: the goal's place inside this row.
      const double at = static_cast<double>(row) - 0.5 + (goal - below) / previousBand[row];
      return static_cast<Index>(std::lround(rowOfPreviousRow(whole, previousWhole, at)));
    }
    below += previousBand[row];
  }
  return -1;
}

/// Every rank's first row of `whole`, and its row count, over `ranks` ranks.
/// Run 1 (`previous` null): balanced by the cloud's points plus SlabRowWeight.
/// A later run follows the `previous` run's slabs (on `previousWhole`): each
/// cut moves from where the previous slabs meet towards an equal share of
/// the previous run's band (`previousBand`, nodes per previous row summed
/// over the ranks; the band is the work of an iteration), as far as
/// limitRowShare() and laterCutRange() (the transfer stays local) let it;
/// run 1's cuts are limited alike; the even split when the
/// rows are too few (planSlabAt then refuses).
template <int D>
std::vector<Index> slabBoundaries(const GridSpec<D>& whole, int ranks, const PointCloud<D>& cloud,
  const GridSpec<D>* previousWhole = nullptr, const std::vector<Index>* previous = nullptr,
  const std::vector<double>* previousBand = nullptr)
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
      const Index cut = (*previous)[static_cast<size_t>(r)];
      Index row = static_cast<Index>(std::lround(rowOfPreviousRow(whole, *previousWhole, static_cast<double>(cut))));
      const Index balanced =
        previousBand ? bandShareRow(whole, *previousWhole, *previousBand, static_cast<double>(r) / ranks) : -1;
      const auto [low, high] = laterCutRange(whole, *previousWhole, cut);
      if (balanced >= 0 && low <= high)
      {
        row = std::clamp(limitRowShare(balanced, rows, r, ranks), low, high);
      }
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
  return limitRowShares(balancedSlabBoundaries(weights, ranks, SlabGhostRows));
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

/// The most nodes a rank's window may hold in a later run cut after the
/// `previous` run's boundaries (on `previousWhole`), wherever the band moves
/// its cuts (slabBoundaries(): towards the band's shares, limited by
/// limitRowShare() and laterCutRange()): from the lowest row its first cut
/// may take to the highest its last may take, plus the ghost rows.
template <int D>
double largestLaterSlabWindowNodes(
  const GridSpec<D>& whole, const GridSpec<D>& previousWhole, const std::vector<Index>& previous)
{
  const Index rows = whole.Dims[D - 1];
  const int ranks = static_cast<int>(previous.size()) - 1;
  std::vector<Index> lowest(static_cast<size_t>(ranks) + 1, 0), highest(static_cast<size_t>(ranks) + 1, rows);
  for (int r = 1; r < ranks; ++r)
  {
    const Index cut = previous[static_cast<size_t>(r)];
    const Index met = static_cast<Index>(std::lround(rowOfPreviousRow(whole, previousWhole, static_cast<double>(cut))));
    const auto [low, high] = laterCutRange(whole, previousWhole, cut);
    const Index down = std::clamp(limitRowShare(0, rows, r, ranks), low, std::max(low, high));
    const Index up = std::clamp(limitRowShare(rows, rows, r, ranks), low, std::max(low, high));
    lowest[static_cast<size_t>(r)] = std::clamp<Index>(std::min(met, down), 0, rows);
    highest[static_cast<size_t>(r)] = std::clamp<Index>(std::max(met, up), 0, rows);
  }
  Index largest = 0;
  for (size_t r = 0; r + 1 < lowest.size(); ++r)
  {
    largest =
      std::max(largest, std::min(rows, highest[r + 1] + SlabGhostRows) - std::max<Index>(0, lowest[r] - SlabGhostRows));
  }
  return static_cast<double>(whole.nodeCount() / rows) * static_cast<double>(largest);
}

} // namespace sltk
