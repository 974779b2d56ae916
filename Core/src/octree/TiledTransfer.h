// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledTransfer.h
/// Run r's tiled field from run r-1's level set (uniform or tiled): tiles
/// around the previous band, phi by Q1 cut at +-gamma (1.49), every other
/// slot the side of its centre; distributed, the slots shared out over the ranks.
#include "PruneTiles.h"
#include "TileDistribution.h"
#include "TiledBand.h"
#include "sltk/core/IndexBox.h"
#include "sltk/grid/GridField.h"
#include "sltk/interp/Q1.h"
#include "sltk/octree/TiledField.h"
#include "sltk/recon/FarPointSeeds.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sltk
{
namespace octree
{

/// Q1 of a tiled field at x (unit-box units).
template <int D>
double tiledQ1(const TiledField<D>& f, const std::array<double, D>& x)
{
  const GridSpec<D>& g = f.grid();
  std::array<Index, D> cell{};
  double w[D];
  for (int a = 0; a < D; ++a)
  {
    const double u = (x[a] - g.Origin[a]) / g.Spacing[a];
    const double c = std::floor(u);
    cell[a] = static_cast<Index>(c);
    w[a] = u - c;
  }
  double sum = 0.0;
  for (int corner = 0; corner < (1 << D); ++corner)
  {
    std::array<Index, D> i = cell;
    double weight = 1.0;
    for (int a = 0; a < D; ++a)
    {
      const bool up = (corner >> a) & 1;
      i[a] += up ? 1 : 0;
      weight *= up ? w[a] : 1.0 - w[a];
    }
    sum += weight * f.value(i);
  }
  return sum;
}

/// The previous run's phi: run 1's uniform field or a tiled one.
template <int D>
struct PreviousLevelSet
{
  const GridField<D>* Dense = nullptr;
  const TiledField<D>* Tiled = nullptr;

  double spacing(int a) const { return this->Tiled ? this->Tiled->grid().Spacing[a] : this->Dense->spec().Spacing[a]; }

  double at(const std::array<double, D>& x) const
  {
    if (this->Tiled)
    {
      return tiledQ1<D>(*this->Tiled, x);
    }
    Q1Interpolator<D> interp(*this->Dense);
    return interpolate(interp, this->Dense->spec(), x.data());
  }

  /// Calls f(x) at every node of the previous band (|phi| < gamma).
  template <class F>
  void forEachBandNode(double gamma, F&& f) const
  {
    if (this->Tiled)
    {
      const TiledField<D>& t = *this->Tiled;
      for (std::int32_t id = 0; id < t.tileCount(); ++id)
      {
        const double* p = t.phi(id);
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          if (std::fabs(p[k]) < gamma)
          {
            f(t.position(t.node(id, k)));
          }
        }
      }
      return;
    }
    const GridSpec<D>& g = this->Dense->spec();
    for (Index k = 0; k < g.nodeCount(); ++k)
    {
      const auto i = this->Dense->nodeIndex(k);
      if (std::fabs((*this->Dense)(i)) < gamma)
      {
        std::array<double, D> x{};
        for (int a = 0; a < D; ++a)
        {
          x[a] = g.coordinate(a, i[a]);
        }
        f(x);
      }
    }
  }
};

/// Grid index of the node nearest to x.
template <int D>
std::array<Index, D> nearestNode(const GridSpec<D>& g, const std::array<double, D>& x)
{
  std::array<Index, D> i{};
  for (int a = 0; a < D; ++a)
  {
    i[a] = static_cast<Index>(std::lround((x[a] - g.Origin[a]) / g.Spacing[a]));
  }
  return i;
}

/// The centre of the nodes of the slot at tile coordinates t.
template <int D>
std::array<double, D> slotCentre(const GridSpec<D>& grid, const std::array<Index, D>& t)
{
  std::array<double, D> x{};
  for (int a = 0; a < D; ++a)
  {
    x[a] = grid.Origin[a] + (static_cast<double>(t[a] * TileEdge) + 0.5 * (TileEdge - 1)) * grid.Spacing[a];
  }
  return x;
}

/// The seeds' balls (recon/FarPointSeeds.h) by slot: the seeds whose ball,
/// widened by gamma, reaches each slot's nodes (slots in CSR order).
template <int D>
class SeedsBySlot
{
public:
  SeedsBySlot(const FarPointSeeds<D>& seeds, const TiledField<D>& field, double gamma)
    : Seeds(seeds)
  {
    if (seeds.empty())
    {
      return;
    }
    const GridSpec<D>& g = field.grid();
    const double outer = seeds.Radius + gamma;
    std::vector<std::pair<Index, std::int32_t>> pairs; // (slot, seed)
    for (size_t c = 0; c < seeds.Centres.size(); ++c)
    {
      std::array<Index, D> lo{}, hi{};
      for (int a = 0; a < D; ++a)
      {
        const double x = seeds.Centres[c][a];
        lo[a] = std::max<Index>(0, static_cast<Index>(std::ceil(g.indexCoordinate(a, x - outer))) >> TileBits);
        hi[a] = std::min<Index>(
          field.slotDims()[a] - 1, static_cast<Index>(std::floor(g.indexCoordinate(a, x + outer))) >> TileBits);
      }
      forEachIndexInBox<D>(lo, hi,
        [&](const std::array<Index, D>& t) { pairs.emplace_back(field.slotIndex(t), static_cast<std::int32_t>(c)); });
    }
    std::sort(pairs.begin(), pairs.end());
    this->First.assign(static_cast<size_t>(field.slotCount()) + 1, 0);
    for (const auto& [slot, seed] : pairs)
    {
      ++this->First[static_cast<size_t>(slot) + 1];
      this->Items.push_back(seed);
    }
    for (size_t s = 1; s < this->First.size(); ++s)
    {
      this->First[s] += this->First[s - 1];
    }
  }

  /// Whether a seed's ball reaches slot s.
  bool reaches(Index s) const
  {
    return !this->First.empty() && this->First[static_cast<size_t>(s) + 1] > this->First[static_cast<size_t>(s)];
  }

  /// phi united with the balls that reach slot s, at x.
  double unite(Index s, const std::array<double, D>& x, double phi) const
  {
    if (this->First.empty())
    {
      return phi;
    }
    for (Index j = this->First[static_cast<size_t>(s)]; j < this->First[static_cast<size_t>(s) + 1]; ++j)
    {
      const auto& c = this->Seeds.Centres[static_cast<size_t>(this->Items[static_cast<size_t>(j)])];
      double r2 = 0.0;
      for (int a = 0; a < D; ++a)
      {
        r2 += (x[a] - c[a]) * (x[a] - c[a]);
      }
      phi = std::min(phi, std::sqrt(r2) - this->Seeds.Radius);
    }
    return phi;
  }

private:
  const FarPointSeeds<D>& Seeds;
  std::vector<Index> First; // slot s's seeds: Items[First[s] .. First[s + 1])
  std::vector<std::int32_t> Items;
};

/// Does nothing with the per-tile state of removed tiles (no state yet).
constexpr auto NothingToForget = [](const std::vector<std::uint8_t>&) {};

/// The owners of the new run's slots when the band is distributed: run 1's
/// field is on every rank, so the marked slots are shared out in Morton order
/// at once; a tiled previous run gives each slot to the owner of the previous
/// slot at its centre (that rank holds the previous values around it), and
/// migrate() balances them after the transfer.
template <int D>
std::vector<std::int32_t> transferOwners(const PreviousLevelSet<D>& previous, const TiledField<D>& field,
  const std::vector<std::uint8_t>& marked, const TileDistribution<D>& distribution)
{
  if (!previous.Tiled)
  {
    return distribution.balancedOwners(field, marked);
  }
  const TiledField<D>& before = *previous.Tiled;
  const GridSpec<D>& grid = field.grid();
  std::vector<std::int32_t> owners(static_cast<size_t>(field.slotCount()));
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    const std::array<double, D> x = slotCentre<D>(grid, field.slotCoordinates(s));
    std::array<Index, D> p{};
    for (int a = 0; a < D; ++a)
    {
      const Index node = static_cast<Index>(std::floor((x[a] - before.grid().Origin[a]) / before.grid().Spacing[a]));
      p[a] = std::min(std::max<Index>(node >> TileBits, 0), before.slotDims()[a] - 1);
    }
    owners[static_cast<size_t>(s)] = distribution.ownerOf(before.slotIndex(p));
  }
  return owners;
}

/// Run r's field from run r-1's level set: tiles around its band and around
/// the seeds' balls (recon/FarPointSeeds.h), phi by Q1 united with the balls
/// and cut at +-gamma, d not yet computed (TiledDistances); every other
/// slot the side of its centre. Distributed, each rank computes its own slots
/// (transferOwners), tells the others, and the tiles are then balanced over the
/// ranks with one ghost layer.
template <int D>
Status transferToTiles(const PreviousLevelSet<D>& previous, double previousGamma, const FarPointSeeds<D>& seeds,
  const GridSpec<D>& grid, const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field,
  TileDistribution<D>& distribution)
{
  const double gamma = plan.Options.GammaFactor * grid.Spacing[0];
  field.reset(grid, gamma);
  std::vector<std::uint8_t> marked(static_cast<size_t>(field.slotCount()), 0);
  const SeedsBySlot<D> balls(seeds, field, gamma);
  // A node where the transferred phi is inside the new band has a previous
  // band node among the corners of its previous cell (elsewhere Q1 gives
  // +-gamma): within one previous spacing per axis, one node more for the
  // rounding to the nearest node.
  std::array<Index, D> reach{};
  for (int a = 0; a < D; ++a)
  {
    reach[a] = static_cast<Index>(std::ceil(previous.spacing(a) / grid.Spacing[a])) + 1;
  }
  previous.forEachBandNode(previousGamma,
    [&](const std::array<double, D>& x)
    {
      const std::array<Index, D> i = nearestNode<D>(grid, x);
      std::array<Index, D> lo{}, hi{};
      for (int a = 0; a < D; ++a)
      {
        lo[a] = std::max<Index>((i[a] - reach[a]) >> TileBits, 0);
        hi[a] = std::min<Index>((i[a] + reach[a]) >> TileBits, field.slotDims()[a] - 1);
        if (lo[a] > hi[a])
        {
          return; // beyond the new grid
        }
      }
      forEachIndexInBox<D>(
        lo, hi, [&](const std::array<Index, D>& t) { marked[static_cast<size_t>(field.slotIndex(t))] = 1; });
    });
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    marked[static_cast<size_t>(s)] |= balls.reaches(s) ? 1 : 0;
  }
  distribution.setOwners(field, transferOwners(previous, field, marked, distribution));
  Index count = 0;
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    count += marked[static_cast<size_t>(s)] && distribution.ownsSlot(s) ? 1 : 0;
  }
  SLTK_RETURN_IF_ERROR(distribution.agree(checkTileMemory(field, count, plan.Options, run)));
  // Sides of the slots without tiles: the sign of the previous phi at their centre.
  ctx.parallelFor(0, field.slotCount(),
    [&](Index b, Index e)
    {
      for (Index s = b; s < e; ++s)
      {
        if (!marked[static_cast<size_t>(s)] && distribution.ownsSlot(s))
        {
          field.setSide(s, previous.at(slotCentre<D>(grid, field.slotCoordinates(s))) < 0.0);
        }
      }
    });
  // A marked slot whose transferred phi is one +-gamma throughout gets no
  // tile, only that side (PruneTiles.h: extendBand allocates it again,
  // at the same values, where the band reaches).
  std::vector<Index> candidates;
  candidates.reserve(static_cast<size_t>(count));
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    if (marked[static_cast<size_t>(s)] && distribution.ownsSlot(s))
    {
      candidates.push_back(s);
    }
  }
  const auto transferred = [&](const std::array<Index, D>& i)
  {
    std::array<Index, D> t{};
    for (int a = 0; a < D; ++a)
    {
      t[a] = i[a] >> TileBits;
    }
    const std::array<double, D> x = field.position(i);
    return std::min(gamma, std::max(-gamma, balls.unite(field.slotIndex(t), x, previous.at(x))));
  };
  std::vector<std::int8_t> side(candidates.size(), 0); // -1 / +1: one side throughout; 0: a tile
  ctx.parallelFor(0, static_cast<Index>(candidates.size()),
    [&](Index b, Index e)
    {
      std::array<double, TiledField<D>::Nodes> values;
      for (Index c = b; c < e; ++c)
      {
        const auto t = field.slotCoordinates(candidates[static_cast<size_t>(c)]);
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          std::array<Index, D> i{};
          for (int a = 0; a < D; ++a)
          {
            i[a] = t[a] * TileEdge + ((k >> (TileBits * a)) & (TileEdge - 1));
          }
          values[static_cast<size_t>(k)] = transferred(i);
        }
        side[static_cast<size_t>(c)] = static_cast<std::int8_t>(oneSideOf(values.data(), TiledField<D>::Nodes, gamma));
      }
    });
  for (size_t c = 0; c < candidates.size(); ++c)
  {
    if (side[c] == 0)
    {
      field.addTile(candidates[c]);
    }
    else
    {
      field.setSide(candidates[c], side[c] < 0);
    }
  }
  ctx.parallelFor(
    0, field.tileCount(),
    [&](Index b, Index e)
    {
      for (Index id = b; id < e; ++id)
      {
        const auto tile = static_cast<std::int32_t>(id);
        double* p = field.phi(tile);
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          p[k] = transferred(field.node(tile, k));
        }
      }
    },
    1);
  using State = typename TileDistribution<D>::SlotState;
  std::vector<std::int64_t> changes;
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    if (distribution.ownsSlot(s) && (field.slot(s) >= 0 || field.slot(s) == TiledField<D>::Inside))
    {
      distribution.recordChange(changes, s, field.slot(s) >= 0 ? State::Tile : State::Inside);
    }
  }
  distribution.shareChanges(field, changes, NothingToForget);
  if (previous.Tiled)
  {
    distribution.migrate(
      field, distribution.balancedOwners(field, TileDistribution<D>::tileSlots(field)), NothingToForget);
  }
  distribution.holdGhosts(field, 1, NothingToForget);
  distribution.exchange(field, true);
  return Status::ok();
}

} // namespace octree
} // namespace sltk
