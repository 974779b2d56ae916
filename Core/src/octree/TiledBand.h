// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledBand.h
/// The band storage of a tiled run (recon/RunIterations.h): the band's tiles
/// found, freed and added as the front moves (PruneTiles.h), d made exact
/// where the band reads it (TiledDistances.h), the energy (4.29)/(4.30), the
/// step (TiledStep.h) and the reinitialisation (TiledReinitialise.h) tile by
/// tile, distributed over the ranks by TileDistribution.h.

#include "BandReach.h"
#include "PruneTiles.h"
#include "TileDistribution.h"
#include "TiledDistances.h"
#include "TiledReinitialise.h"
#include "TiledStep.h"
#include "sltk/exec/Memory.h"
#include "sltk/levelset/IsolatedNodes.h"
#include "sltk/octree/TiledReconstruction.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/Reconstruction.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace sltk
{
namespace octree
{

/// The memory of `tiles` more tiles, refused when it does not fit: with a
/// MemoryBudget, this machine's ranks (ReconstructionOptions::RanksHere) each
/// holding as much as this one, tiles held and new, within the budget; without
/// one, their new tiles within the memory available now (which the held tiles
/// already left).
template <int D>
Status checkTileMemory(const TiledField<D>& field, Index tiles, const ReconstructionOptions& options, int run)
{
  const int here = std::max(1, options.RanksHere);
  const double added = static_cast<double>(tiles) * TiledField<D>::Nodes * 2.0 * sizeof(double);
  const double need = here * (options.MemoryBudget ? field.bytes() + added : added);
  const double available = static_cast<double>(options.MemoryBudget ? options.MemoryBudget : availableMemoryBytes());
  if (available > 0.0 && need > available)
  {
    std::ostringstream m;
    m.precision(3);
    m << "run " << run << " of the octree reconstruction needs " << need / 1048576.0 << " MB for "
      << field.tileCount() + tiles << " tiles"
      << (here > 1 ? ", a rank, on each of the " + std::to_string(here) + " ranks of this machine" : "")
      << ", more than the " << available / 1048576.0 << " MB available: use fewer runs, a larger C_dx"
      << (here > 1 ? " or the ranks on more machines" : "");
    return Status::outOfMemory(m.str());
  }
  return Status::ok();
}

/// Tiles with a node in the band |phi| < gamma (1.48).
template <int D>
void bandTiles(const TiledField<D>& field, const Context& ctx, std::vector<std::int32_t>& tiles)
{
  std::vector<std::uint8_t> in(static_cast<size_t>(field.tileCount()), 0);
  ctx.parallelFor(0, field.tileCount(),
    [&](Index b, Index e)
    {
      for (Index id = b; id < e; ++id)
      {
        const double* p = field.phi(static_cast<std::int32_t>(id));
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          if (std::fabs(p[k]) < field.gamma())
          {
            in[static_cast<size_t>(id)] = 1;
            break;
          }
        }
      }
    });
  // In slot order: the energy's sums then do not depend on the tiles' ids (PruneTiles.h).
  tiles.clear();
  field.forEachTileInSlotOrder(
    [&](std::int32_t id)
    {
      if (in[static_cast<size_t>(id)])
      {
        tiles.push_back(id);
      }
    });
}

/// Gives tiles to the slots `reached` (bandReach) from the band tiles (new tiles:
/// the slot's +-gamma, d not yet computed): the nodes the reinitialisation's
/// dilated band (1.53) writes and the step's and the energy's distance
/// stencils read. Elsewhere the step reads the slots' +-gamma, the value the
/// uniform version holds there. Distributed, a rank fills its own slots (its
/// ghosts' band reaches them too) and records them in `changes`. Returns the
/// number of tiles added through `added`.
template <int D>
Status extendBand(const std::vector<std::int32_t>& band, const std::vector<std::uint32_t>& reached,
  const ReconstructionOptions& options, int run, TiledField<D>& field, Index& added,
  const TileDistribution<D>& distribution, std::vector<std::int64_t>& changes)
{
  added = 0;
  std::vector<Index> missing;
  for (size_t j = 0; j < band.size(); ++j)
  {
    forEachReachedSlot(field, band[j], reached[j],
      [&](Index s)
      {
        const std::int32_t entry = field.slot(s);
        if (entry < 0 && entry != TiledField<D>::Remote && distribution.ownsSlot(s))
        {
          missing.push_back(s);
        }
      });
  }
  if (missing.empty())
  {
    return Status::ok();
  }
  std::sort(missing.begin(), missing.end());
  missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
  SLTK_RETURN_IF_ERROR(checkTileMemory(field, static_cast<Index>(missing.size()), options, run));
  for (Index s : missing)
  {
    field.addTile(s);
    distribution.recordChange(changes, s, TileDistribution<D>::SlotState::Tile);
  }
  added = static_cast<Index>(missing.size());
  return Status::ok();
}

/// The slots around the band tiles that get tiles (extendBand) and whose d
/// may be needed (TiledDistances): those within the reinitialisation's
/// dilation of a band node, and at least the one node of the distance stencils.
template <int D>
std::vector<std::uint32_t> bandReachOf(const TiledField<D>& field, const std::vector<std::int32_t>& band,
  const ReconstructionOptions& options, const Context& ctx)
{
  return bandReach(field, band, std::max<Index>(options.ReinitDilation, 1), ctx);
}

/// E_p (and E_2) of (4.29)/(4.30) over the band's cells, tile by tile
/// (`band`: this rank's band tiles, in slot order), added in slot order over
/// every rank; `bandTiles` receives the band tiles of every rank.
template <int D>
Status tiledEnergy(const TiledField<D>& field, const std::vector<std::int32_t>& band, const EnergyOptions& options,
  const Context& ctx, const TileDistribution<D>& distribution, EnergyResult& result, Index& bandTiles)
{
  const Context serial;
  std::vector<EnergyResult> parts(band.size());
  std::vector<Status> failures(band.size());
  ctx.parallelFor(
    0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      TileScratch<D> s;
      for (Index j = b; j < e; ++j)
      {
        const std::int32_t id = band[static_cast<size_t>(j)];
        field.scratch(id, 1, 0, s.Phi, &s.Dist); // no ghost layers: the energy reads none (EnergyFunctional.h)
        s.Nodes.clear();
        const double* p = field.phi(id);
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          if (std::fabs(p[k]) < field.gamma())
          {
            s.Nodes.push_back(scratchNode<D>(k, 1));
          }
        }
        failures[static_cast<size_t>(j)] =
          energyFunctional(s.Phi, s.Dist, s.Nodes, serial, parts[static_cast<size_t>(j)], options);
      }
    },
    16);
  Status failed = Status::ok();
  std::vector<KeyedSums<4>> tiles(band.size());
  for (size_t j = 0; j < parts.size(); ++j)
  {
    failed = failed.isOk() ? failures[j] : failed;
    tiles[j] = { static_cast<std::uint64_t>(field.tileSlot(band[j])),
      { parts[j].Integral, parts[j].SecondIntegral, static_cast<double>(parts[j].FrontCells), 1.0 } };
  }
  const std::array<double, 4> sums = distribution.orderedSum(std::move(tiles), std::array<double, 4>{});
  result = EnergyResult{};
  result.Integral = sums[0];
  result.SecondIntegral = sums[1];
  result.FrontCells = static_cast<Index>(sums[2]);
  bandTiles = static_cast<Index>(sums[3]);
  energiesFromIntegrals(result, options);
  return failed;
}

/// The other ranks' changes of this iteration's band (prune, extend)
/// applied here, the ghosts held one layer deep again and the band tiles
/// and their reach found again (ids changed). Nothing on one rank.
template <int D>
void shareBand(TiledField<D>& field, const std::vector<std::int64_t>& changes, const ReconstructionOptions& options,
  const Context& ctx, TileDistribution<D>& distribution, TiledDistances<D>& distances, std::vector<std::int32_t>& band,
  std::vector<std::uint32_t>& reached)
{
  if (!distribution.distributed())
  {
    return;
  }
  const auto forget = [&](const std::vector<std::uint8_t>& removed) { distances.removeTiles(removed); };
  distribution.shareChanges(field, changes, forget);
  distribution.holdGhosts(field, 1, forget);
  bandTiles(field, ctx, band);
  reached = bandReachOf(field, band, options, ctx);
}

/// The band storage of a run >= 2 on its tiled field (recon/RunIterations.h).
/// Distributed (TileDistribution.h), each rank steps, reinitialises and
/// measures its own tiles; every sum is added in the one-rank order, so every
/// decision is taken from the same numbers on every rank. `Storage` collects
/// the run's tile counts.
template <int D, class Interp>
class TiledBand
{
public:
  TiledBand(const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field,
    TileDistribution<D>& distribution, TiledRunRecord& storage)
    : Plan(plan)
    , Options(plan.Options)
    , RunNumber(run)
    , Ctx(ctx)
    , Field(field)
    , Distribution(distribution)
    , Storage(storage)
  {
  }

  const GridSpec<D>& grid() const { return this->Field.grid(); }

  /// The band tiles (1.48), tiles freed where the band left and added where it
  /// reaches (PruneTiles.h, extendBand), every rank's changes shared, and d
  /// exact where the band reads it (TiledDistances.h).
  Status prepare()
  {
    TiledField<D>& field = this->Field;
    bandTiles(field, this->Ctx, this->Band);
    std::vector<std::uint32_t> reached = bandReachOf(field, this->Band, this->Options, this->Ctx);
    std::vector<Index> freed;
    const auto mine = [&](std::int32_t id) { return this->Distribution.owns(field, id); };
    this->Storage.FreedTiles += pruneTiles(
      field, this->Band, reached, this->Ctx, mine,
      [&](const std::vector<std::uint8_t>& left) { this->Distances.removeTiles(left); }, freed);
    std::vector<std::int64_t> changes;
    for (Index s : freed)
    {
      this->Distribution.recordChange(changes, s,
        field.slot(s) == TiledField<D>::Inside ? TileDistribution<D>::SlotState::Inside
                                               : TileDistribution<D>::SlotState::Outside);
    }
    Index added = 0;
    SLTK_RETURN_IF_ERROR(this->Distribution.agree(
      extendBand(this->Band, reached, this->Options, this->RunNumber, field, added, this->Distribution, changes)));
    shareBand(field, changes, this->Options, this->Ctx, this->Distribution, this->Distances, this->Band, reached);
    this->Storage.AddedTiles += added;
    this->Storage.PeakTiles = std::max(this->Storage.PeakTiles, field.tileCount());
    this->Storage.ExactDistances +=
      this->Distances.ensure(field, this->Band, reached, *this->Plan.Locator, this->Ctx, mine);
    this->Distribution.exchange(field, true); // the ghosts' new tiles and distances
    this->OwnBand = this->Distribution.owned(field, this->Band);
    return Status::ok();
  }

  Status energy(const EnergyOptions& options, EnergyResult& ep)
  {
    return this->Distribution.agree(
      tiledEnergy(this->Field, this->OwnBand, options, this->Ctx, this->Distribution, ep, this->BandCount));
  }

  double farFraction(double far) const
  {
    double error = 0.0, fraction = 0.0;
    cloudErrors<Interp>(this->Field, this->Plan.Cloud, far, this->Ctx, this->Distribution, error, fraction);
    return fraction;
  }

  /// This rank's points (those in its own slots) with I[phi](Q) > threshold.
  std::vector<PlacedPoint<D>> outsidePoints(double threshold) const
  {
    double error = 0.0, fraction = 0.0;
    PointsOutside outside;
    outside.Threshold = threshold;
    cloudErrors<Interp>(this->Field, this->Plan.Cloud, 0.0, this->Ctx, this->Distribution, error, fraction, &outside);
    return placedPoints(outside.Points, this->Plan.Cloud, [](Index k) { return k; });
  }

  /// The step on this rank's band tiles, with as many ghost layers as its feet reach.
  Status step(const LevelSetStepParameters& step)
  {
    TiledField<D>& field = this->Field;
    TileDistribution<D>& distribution = this->Distribution;
    this->Reinit.markBand(field, this->Band, this->Options.ReinitDilation, this->Ctx, distribution); // (1.53)
    const auto forget = [&](const std::vector<std::uint8_t>& removed) { this->Distances.removeTiles(removed); };
    const int layers =
      distribution.distributed() ? stepGhostLayers(field, this->OwnBand, step, this->Ctx, distribution) : 0;
    this->Storage.GhostLayers = std::max(this->Storage.GhostLayers, layers);
    if (layers > 1) // shareBand held one layer
    {
      // The deeper ghosts come after every other tile and go after the step: the ids
      // of the band, the own band and the reinitialisation's nodes stay.
      distribution.holdGhosts(field, layers, forget);
      distribution.exchange(field, true);
      this->Storage.PeakTiles = std::max(this->Storage.PeakTiles, field.tileCount());
    }
    SLTK_RETURN_IF_ERROR(
      distribution.agree(tiledStep<Interp, D>(field, this->OwnBand, step, this->Ctx, this->StepHalos)));
    if (layers > 1)
    {
      distribution.holdGhosts(field, 1, forget);
    }
    distribution.exchange(field, false);
    return Status::ok();
  }

  Status reinitialise()
  {
    return this->Distribution.agree(this->Reinit.run(this->Field, this->Options.Reinit, this->Ctx, this->Distribution));
  }

  bool measure(IterationRecord& it, bool interrupted) const
  {
    it.Change = this->Reinit.relativeChange();
    double fraction = 0.0;
    cloudErrors<Interp>(this->Field, this->Plan.Cloud, 0.0, this->Ctx, this->Distribution, it.CloudError, fraction);
    it.BandSize = this->BandCount * TiledField<D>::Nodes;
    const auto counts = this->Distribution.storageCounts(this->Field);
    it.StoredNodes = counts.Tiles * TiledField<D>::Nodes;
    it.Leaves = counts.Leaves;
    it.LargestRankLeaves = counts.LargestRankLeaves;
    it.UniformNodes = this->Field.grid().nodeCount();
    return !this->Distribution.agree(interrupted ? Status::aborted() : Status::ok()).isOk();
  }

  /// Gives the single-node specks (IsolatedNodes.h) of this rank's tiles their
  /// neighbours' mean (neighbours in other tiles read through the slots, the
  /// ghosts' faces held by the last exchange), ghosts exchanged after; returns
  /// their count over every rank. A change's Node is tile id * Nodes + the tile's node.
  Index mergeIsolatedNodes()
  {
    TiledField<D>& field = this->Field;
    std::vector<NodeChange> changes;
    for (std::int32_t id = 0; id < field.tileCount(); ++id)
    {
      if (!this->Distribution.owns(field, id))
      {
        continue;
      }
      const double* p = field.phi(id);
      for (Index k = 0; k < TiledField<D>::Nodes; ++k)
      {
        if (!(std::fabs(p[k]) < field.gamma())) // a speck lies in the band (1.48)
        {
          continue;
        }
        const std::array<Index, D> i = field.node(id, k);
        if (!hasAllAxisNeighbours<D>(i, field.grid().Dims))
        {
          continue;
        }
        const auto at = [&](int a, int side)
        {
          std::array<Index, D> n = i;
          n[a] += side;
          return field.value(n);
        };
        double merged = 0.0;
        if (isolatedNodeValue<D>(p[k], at, merged))
        {
          changes.push_back({ id * TiledField<D>::Nodes + k, merged });
        }
      }
    }
    for (const NodeChange& c : changes)
    {
      field.phi(static_cast<std::int32_t>(c.Node / TiledField<D>::Nodes))[c.Node % TiledField<D>::Nodes] = c.Value;
    }
    this->Distribution.exchange(field, false);
    return static_cast<Index>(this->Distribution.comm().allReduce(static_cast<double>(changes.size()), ReduceOp::Sum));
  }

  void finish(RunRecord<D>& record, double far) const
  {
    double error = 0.0;
    cloudErrors<Interp>(this->Field, this->Plan.Cloud, far, this->Ctx, this->Distribution, error, record.FarPoints);
    record.PointsHeld = this->Plan.Cloud.size(); // every rank reads the whole cloud here
    if (record.Iterations == 0)
    {
      record.CloudError = error;
    }
  }

  /// The tiles held (and this rank's share, distributed).
  std::string describe() const
  {
    const Index tiles = this->Distribution.globalTileCount(this->Field);
    std::ostringstream s;
    s << "; " << tiles << " tiles ("
      << static_cast<double>(tiles) * TiledField<D>::Nodes / static_cast<double>(this->Field.grid().nodeCount()) * 100.0
      << "% of the grid)";
    if (this->Distribution.distributed())
    {
      s << "; rank " << this->Distribution.rank() << " of " << this->Distribution.comm().size() << " holds "
        << this->Field.tileCount() << " tiles, ghosts included";
    }
    return s.str();
  }

private:
  const ReconstructionPlan<D>& Plan;
  const ReconstructionOptions& Options;
  const int RunNumber;
  const Context& Ctx;
  TiledField<D>& Field;
  TileDistribution<D>& Distribution;
  TiledRunRecord& Storage;
  std::vector<std::int32_t> Band, OwnBand; // every rank's band tiles held here; this rank's own
  Index BandCount = 0;                     // band tiles over every rank
  TiledReinitialiser<D> Reinit;
  TiledDistances<D> Distances;
  std::vector<std::uint8_t> StepHalos; // by block position: the halo its feet needed at the last step
};

} // namespace octree
} // namespace sltk
