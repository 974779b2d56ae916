// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/tiled/TiledReconstruction.h"

#include "BandReach.h"
#include "PruneTiles.h"
#include "TileDistribution.h"
#include "TiledDistances.h"
#include "TiledReinitialise.h"
#include "sltk/exec/Memory.h"
#include "sltk/grid/SlabExchange.h"
#include "sltk/levelset/ReinitInterface.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/ReconstructionInterpolator.h"
#include "sltk/recon/StoppingRule.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>

namespace sltk
{

namespace
{
constexpr int Ghost = 2;        ///< ghost layers of the scratch fields (WENO3 / CWENO stencils)
constexpr int StencilReach = 2; ///< nodes beyond a foot's cell the interpolators read
constexpr int DistReach = 1;    ///< nodes around the band the step reads d at (the centred gradient of (4.22)/(4.24))
constexpr int HaloStep = 4;     ///< the step's halo is a multiple of this (fewer scratch shapes)
constexpr int MaxHalo = 32;     ///< the farthest the step reads around a tile
constexpr Index BlockTiles = TileBlockEdge; ///< the step copies blocks of 4^D tile positions (32^D nodes) at once
static_assert(MaxHalo <= MaxGhostLayers * TileEdge, "the ghost layers cover the step's farthest read");

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Index in a scratch block (`tiles`^D tile positions and `halo` nodes around
/// them) of node `local` of the tile at position `offset` (tile units) in the block.
template <int D>
Index scratchNode(Index local, Index halo, const std::array<Index, D>& offset = {}, Index tiles = 1)
{
  const Index edge = tiles * TileEdge + 2 * halo;
  Index k = 0, stride = 1;
  for (int a = 0; a < D; ++a)
  {
    k += (halo + offset[a] * TileEdge + ((local >> (TileBits * a)) & (TileEdge - 1))) * stride;
    stride *= edge;
  }
  return k;
}

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
    m << "run " << run << " of the tiled reconstruction needs " << need / 1048576.0 << " MB for "
      << field.tileCount() + tiles << " tiles"
      << (here > 1 ? ", a rank, on each of the " + std::to_string(here) + " ranks of this machine" : "")
      << ", more than the " << available / 1048576.0 << " MB available: use fewer runs, a larger C_dx"
      << (here > 1 ? " or the ranks on more machines" : "");
    return Status::outOfMemory(m.str());
  }
  return Status::ok();
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

/// Run r's field from run r-1's level set: tiles around its band,
/// phi by Q1 cut at +-gamma, d not yet computed (TiledDistances); every other
/// slot the side of its centre. Distributed, each rank computes its own slots
/// (transferOwners), tells the others, and the tiles are then balanced over the
/// ranks with one ghost layer.
template <int D>
Status transferToTiles(const PreviousLevelSet<D>& previous, double previousGamma, const GridSpec<D>& grid,
  const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field,
  TileDistribution<D>& distribution)
{
  const double gamma = plan.Options.GammaFactor * grid.Spacing[0];
  field.reset(grid, gamma);
  std::vector<std::uint8_t> marked(static_cast<size_t>(field.slotCount()), 0);
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
  if (distribution.distributed())
  {
    distribution.setOwners(field, transferOwners(previous, field, marked, distribution));
  }
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
  { return std::min(gamma, std::max(-gamma, previous.at(field.position(i)))); };
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
  if (distribution.distributed())
  {
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

/// Per-thread scratch of a tile and its neighbourhood.
template <int D>
struct TileScratch
{
  GridField<D> Phi, Dist;
  NodeList Nodes;
  std::vector<double> Values;
};

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

/// The largest displacement of a foot of (4.22)/(4.24) from its node, in the
/// same arithmetic as levelSetStep (the scale (4.32), grad d or, through a
/// tunnel, grad phi, and the spread of the tangent points).
template <int D>
double largestFoot(
  const GridField<D>& phi, const GridField<D>& dist, const NodeList& nodes, const LevelSetStepParameters& par)
{
  double largest = 0.0;
  for (Index k : nodes)
  {
    const auto i = phi.nodeIndex(k);
    const double d = dist(i);
    const double scale = cutOff(phi(i), par.Widths) * (par.P == 1.0 ? 1.0 : std::pow(d / par.Energy, par.P - 1.0));
    const auto gd = detail::centredGradient(dist, dist.pointer(i));
    const auto gp = detail::centredGradient(phi, phi.pointer(i));
    double nd = 0.0, np = 0.0;
    for (int a = 0; a < D; ++a)
    {
      nd += gd[a] * gd[a];
      np += gp[a] * gp[a];
    }
    const double speed = std::sqrt(par.DetectTunnels ? std::max(nd, np) : nd);
    const double spread = std::sqrt(2.0 * scale * par.Eta * d * par.TimeStep / par.P) * std::sqrt(D - 1.0);
    largest = std::max(largest, scale * par.TimeStep * speed + spread);
  }
  return largest;
}

/// Items (band tiles, cloud points) grouped by the block of BlockTiles^D
/// tile positions they lie in: blocks in slot order, items in their order
/// within a block.
template <int D>
struct TileBlocks
{
  std::vector<std::array<Index, D>> First; ///< each block's first tile coordinates
  std::vector<size_t> Begin;               ///< block b's items: Items[Begin[b], Begin[b + 1])
  std::vector<Index> Items;

  /// `keyed`: (block key of the item's tile coordinates, item), in item order.
  TileBlocks(const TiledField<D>& field, std::vector<std::pair<Index, Index>> keyed)
  {
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (size_t j = 0; j < keyed.size(); ++j)
    {
      if (j == 0 || keyed[j].first != keyed[j - 1].first)
      {
        this->Begin.push_back(j);
        this->First.push_back(firstTile(field, keyed[j].first));
      }
      this->Items.push_back(keyed[j].second);
    }
    this->Begin.push_back(keyed.size());
  }

  Index count() const { return static_cast<Index>(this->First.size()); }

  /// The number of block positions over the field's slots (the range of key()).
  static Index positions(const TiledField<D>& field)
  {
    Index n = 1;
    for (int a = 0; a < D; ++a)
    {
      n *= blocksAlong(field, a);
    }
    return n;
  }

  /// The key of the block holding tile coordinates t.
  static Index key(const TiledField<D>& field, const std::array<Index, D>& t)
  {
    Index k = 0;
    for (int a = D - 1; a >= 0; --a)
    {
      k = k * blocksAlong(field, a) + t[a] / BlockTiles;
    }
    return k;
  }

private:
  static Index blocksAlong(const TiledField<D>& field, int a)
  {
    return (field.slotDims()[a] + BlockTiles - 1) / BlockTiles;
  }
  static std::array<Index, D> firstTile(const TiledField<D>& field, Index key)
  {
    std::array<Index, D> first{};
    for (int a = 0; a < D; ++a)
    {
      first[a] = key % blocksAlong(field, a) * BlockTiles;
      key /= blocksAlong(field, a);
    }
    return first;
  }
};

/// The band tiles grouped by block (TileBlocks: items are positions in `band`).
template <int D>
TileBlocks<D> bandBlocks(const TiledField<D>& field, const std::vector<std::int32_t>& band)
{
  std::vector<std::pair<Index, Index>> keyed(band.size());
  for (size_t j = 0; j < band.size(); ++j)
  {
    keyed[j] = { TileBlocks<D>::key(field, field.tileOrigin(band[j])), static_cast<Index>(j) };
  }
  return TileBlocks<D>(field, std::move(keyed));
}

/// The band nodes (|phi| < gamma) of block `block`'s tiles, numbered in the
/// block's copy with `halo` nodes around it (scratchBlock), tile after tile.
template <int D>
void blockBandNodes(const TiledField<D>& field, const std::vector<std::int32_t>& band, const TileBlocks<D>& blocks,
  Index block, Index halo, NodeList& nodes)
{
  nodes.clear();
  const auto& first = blocks.First[static_cast<size_t>(block)];
  for (size_t m = blocks.Begin[static_cast<size_t>(block)]; m < blocks.Begin[static_cast<size_t>(block) + 1]; ++m)
  {
    const std::int32_t id = band[static_cast<size_t>(blocks.Items[m])];
    std::array<Index, D> o = field.tileOrigin(id);
    for (int a = 0; a < D; ++a)
    {
      o[a] -= first[a];
    }
    const double* p = field.phi(id);
    for (Index k = 0; k < TiledField<D>::Nodes; ++k)
    {
      if (std::fabs(p[k]) < field.gamma())
      {
        nodes.push_back(scratchNode<D>(k, halo, o, BlockTiles));
      }
    }
  }
}

/// The largest foot (largestFoot) of block `block`'s band nodes, measured on
/// a copy of the block with `halo` nodes and `ghost` ghost layers around it
/// (left in `s`, its band nodes in s.Nodes).
template <int D>
double blockFoot(const TiledField<D>& field, const std::vector<std::int32_t>& band, const TileBlocks<D>& blocks,
  Index block, Index halo, int ghost, const LevelSetStepParameters& par, TileScratch<D>& s)
{
  field.scratchBlock(
    blocks.First[static_cast<size_t>(block)], BlockTiles, static_cast<int>(halo), ghost, s.Phi, &s.Dist, DistReach);
  blockBandNodes(field, band, blocks, block, halo, s.Nodes);
  return largestFoot(s.Phi, s.Dist, s.Nodes, par);
}

/// The ghost layers (slots) the next step reads around this rank's band
/// tiles `band`: its farthest foot (largestFoot) and the interpolation
/// stencil, over every rank (at least 1, at most MaxGhostLayers; a farther
/// foot is refused by tiledStep). Collective.
template <int D>
int stepGhostLayers(const TiledField<D>& field, const std::vector<std::int32_t>& band,
  const LevelSetStepParameters& par, const Context& ctx, const TileDistribution<D>& distribution)
{
  const TileBlocks<D> blocks = bandBlocks(field, band);
  std::vector<double> feet(static_cast<size_t>(blocks.count()), 0.0);
  ctx.parallelFor(
    0, blocks.count(),
    [&](Index b, Index e)
    {
      TileScratch<D> s;
      for (Index block = b; block < e; ++block)
      {
        feet[static_cast<size_t>(block)] = blockFoot(field, band, blocks, block, 1, 1, par, s);
      }
    },
    1);
  const double foot = distribution.max(feet.empty() ? 0.0 : *std::max_element(feet.begin(), feet.end()));
  // A non-finite or farther foot asks the most layers; tiledStep then refuses it.
  const double reach = std::min(foot / field.grid().Spacing[0], static_cast<double>(MaxHalo));
  const Index need = static_cast<Index>(std::ceil(std::isfinite(reach) ? reach : MaxHalo)) + StencilReach;
  return static_cast<int>(std::min<Index>(std::max<Index>((need + TileEdge - 1) / TileEdge, 1), MaxGhostLayers));
}

/// One step (4.22)/(4.24) on the band, block by block: each block of band
/// tiles gets its new values from the uniform kernel on one copy of the block
/// and the nodes around it that its feet can reach, stored once all blocks
/// are computed. The reach is measured on a copy with the halo this block
/// needed at the last step (`halos`, by block position; 0: none yet, then a
/// copy with one node around): another copy only when it changed.
template <class Interp, int D>
Status tiledStep(TiledField<D>& field, const std::vector<std::int32_t>& band, const LevelSetStepParameters& par,
  const Context& ctx, std::vector<std::uint8_t>& halos)
{
  halos.resize(static_cast<size_t>(TileBlocks<D>::positions(field)), 0);
  const Context serial;
  const double dx = field.grid().Spacing[0];
  const TileBlocks<D> blocks = bandBlocks(field, band);
  // The new values of the band nodes only: tile after tile (band order), each tile's in node order.
  const auto inBand = [&field](double v) { return std::fabs(v) < field.gamma(); };
  std::vector<size_t> valuesStart(band.size() + 1, 0);
  ctx.parallelFor(0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      for (Index j = b; j < e; ++j)
      {
        const double* p = field.phi(band[static_cast<size_t>(j)]);
        valuesStart[static_cast<size_t>(j) + 1] =
          static_cast<size_t>(std::count_if(p, p + TiledField<D>::Nodes, inBand));
      }
    });
  std::partial_sum(valuesStart.begin(), valuesStart.end(), valuesStart.begin());
  std::vector<double> next(valuesStart.back());
  std::vector<Status> failures(static_cast<size_t>(blocks.count()));
  std::vector<double> feet(static_cast<size_t>(blocks.count()), 0.0);
  ctx.parallelFor(
    0, blocks.count(),
    [&](Index b, Index e)
    {
      TileScratch<D> s;
      for (Index block = b; block < e; ++block)
      {
        const auto& first = blocks.First[static_cast<size_t>(block)];
        const auto offset = [&](size_t j)
        {
          std::array<Index, D> o = field.tileOrigin(band[j]);
          for (int a = 0; a < D; ++a)
          {
            o[a] -= first[a];
          }
          return o;
        };
        const auto forEachMember = [&](auto&& f)
        {
          for (size_t m = blocks.Begin[static_cast<size_t>(block)]; m < blocks.Begin[static_cast<size_t>(block) + 1];
               ++m)
          {
            f(static_cast<size_t>(blocks.Items[m]));
          }
        };
        const auto bandNodes = [&](Index halo) { blockBandNodes(field, band, blocks, block, halo, s.Nodes); };
        std::uint8_t& last = halos[static_cast<size_t>(TileBlocks<D>::key(field, first))];
        const Index guess = last;
        const double foot = guess > 0 ? blockFoot(field, band, blocks, block, guess, Ghost, par, s)
                                      : blockFoot(field, band, blocks, block, 1, 1, par, s);
        feet[static_cast<size_t>(block)] = foot;
        if (!(foot <= (MaxHalo - StencilReach) * dx))
        {
          continue; // reported below (also an infinite or NaN foot)
        }
        const Index need = static_cast<Index>(std::ceil(foot / dx)) + StencilReach;
        // The copy's origin enters the feet's coordinates: always the needed halo, so that the
        // result does not depend on the last step's (a wider copy changed the scans' iterations).
        const Index halo = std::max<Index>(HaloStep, (need + HaloStep - 1) / HaloStep * HaloStep);
        last = static_cast<std::uint8_t>(halo);
        if (halo != guess)
        {
          field.scratchBlock(first, BlockTiles, static_cast<int>(halo), Ghost, s.Phi, &s.Dist, DistReach);
          bandNodes(halo);
        }
        failures[static_cast<size_t>(block)] = levelSetStep<Interp, D>(serial, s.Phi, s.Dist, s.Nodes, par, s.Values);
        forEachMember(
          [&](size_t j)
          {
            const auto o = offset(j);
            const double* p = field.phi(band[j]);
            double* out = next.data() + valuesStart[j];
            for (Index k = 0; k < TiledField<D>::Nodes; ++k)
            {
              if (inBand(p[k]))
              {
                *out++ = s.Phi(s.Phi.nodeIndex(scratchNode<D>(k, halo, o, BlockTiles)));
              }
            }
          });
      }
    },
    1);
  for (size_t block = 0; block < feet.size(); ++block)
  {
    if (!(feet[block] <= (MaxHalo - StencilReach) * dx))
    {
      std::ostringstream m;
      m << "a foot of the semi-Lagrangian step moved " << feet[block] / dx << " cells, beyond the "
        << MaxHalo - StencilReach
        << " the tiled reconstruction reads around a tile: use the uniform version or a smaller eta";
      return Status::numericalFailure(m.str());
    }
    SLTK_RETURN_IF_ERROR(failures[block]);
  }
  ctx.parallelFor(0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      for (Index j = b; j < e; ++j)
      {
        double* p = field.phi(band[static_cast<size_t>(j)]);
        const double* in = next.data() + valuesStart[static_cast<size_t>(j)];
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          if (inBand(p[k])) // the band before the step: the nodes the step computed
          {
            p[k] = *in++;
          }
        }
      }
    });
  return Status::ok();
}

/// Err_P (4.35) and the far-point fraction: |I[phi](Q)| at every point, the
/// points grouped by the block of BlockTiles^D tile positions around them,
/// interpolated on one copy of the block (slots without a tile at their
/// +-gamma: a point there can still read a neighbouring tile's nodes, as the
/// uniform version reads them). Points beyond the slots are gamma away.
///
/// Distributed, a rank takes the points in its own slots; the blocks' sums are
/// added in block order over every rank (the one-rank order). Collective.
template <class Interp, int D>
void cloudErrors(const TiledField<D>& field, const PointCloud<D>& cloud, double far, const Context& ctx,
  const TileDistribution<D>& distribution, double& meanError, double& farFraction)
{
  const GridSpec<D>& g = field.grid();
  std::vector<std::pair<Index, Index>> keyed; // (block key, point)
  keyed.reserve(static_cast<size_t>(cloud.size()));
  double sum = 0.0, farCount = 0.0;
  for (Index q = 0; q < cloud.size(); ++q)
  {
    // The point's cell as the interpolator finds it (GridSpec's locate: snapped to a node within
    // rounding), so that its stencil stays within StencilReach nodes of its block.
    const CellLocation<D> at = locate(g, cloud.Points[static_cast<size_t>(q)].data());
    std::array<Index, D> t{};
    bool inside = true;
    for (int a = 0; a < D; ++a)
    {
      t[a] = at.Cell[a] >> TileBits;
      inside = inside && at.Cell[a] >= 0 && t[a] < field.slotDims()[a];
    }
    if (inside)
    {
      if (distribution.ownsSlot(field.slotIndex(t)))
      {
        keyed.emplace_back(TileBlocks<D>::key(field, t), q);
      }
    }
    else
    {
      sum += field.gamma();
      farCount += field.gamma() > far ? 1.0 : 0.0;
    }
  }
  const TileBlocks<D> blocks(field, std::move(keyed));
  std::vector<double> sums(static_cast<size_t>(blocks.count()), 0.0), fars(static_cast<size_t>(blocks.count()), 0.0);
  ctx.parallelFor(
    0, blocks.count(),
    [&](Index b, Index e)
    {
      TileScratch<D> s;
      for (Index block = b; block < e; ++block)
      {
        // A point's cell is in the block's tiles: the interpolator reads StencilReach nodes beyond it.
        field.scratchBlock(blocks.First[static_cast<size_t>(block)], BlockTiles, StencilReach, Ghost, s.Phi, nullptr);
        Interp interp(s.Phi);
        for (size_t j = blocks.Begin[static_cast<size_t>(block)]; j < blocks.Begin[static_cast<size_t>(block) + 1]; ++j)
        {
          const double v =
            std::fabs(interpolate(interp, s.Phi.spec(), cloud.Points[static_cast<size_t>(blocks.Items[j])].data()));
          sums[static_cast<size_t>(block)] += v;
          fars[static_cast<size_t>(block)] += v > far ? 1.0 : 0.0;
        }
      }
    },
    1);
  std::vector<KeyedSums<2>> parts(sums.size());
  for (size_t j = 0; j < sums.size(); ++j)
  {
    const auto first = blocks.First[j];
    parts[j] = { static_cast<std::uint64_t>(TileBlocks<D>::key(field, first)), { sums[j], fars[j] } };
  }
  const std::array<double, 2> total = distribution.orderedSum(std::move(parts), std::array<double, 2>{ sum, farCount });
  meanError = total[0] / static_cast<double>(cloud.size());
  farFraction = total[1] / static_cast<double>(cloud.size());
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

/// The iterations of run `run` >= 2 on its tiled field (the uniform
/// version's iterate()). Distributed (TileDistribution.h), each rank steps,
/// reinitialises and measures its own tiles; every sum is added in the
/// one-rank order and every decision is taken from the same numbers on every
/// rank.
template <int D, class Interp>
Status iterateTiled(const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field,
  TileDistribution<D>& distribution, ReconstructionResult<D>& result, TiledRunRecord& storage, bool& vanished)
{
  vanished = false;
  const ReconstructionOptions& options = plan.Options;
  const auto start = Clock::now();
  const double dx = field.grid().Spacing[0];
  const RunParameters model = options.parameters(run);
  LevelSetStepParameters step;
  step.P = model.P;
  step.Eta = model.Eta;
  step.TimeStep = dx; // (4.36)
  step.Widths = BandWidths::forSpacing(dx, options.BetaFactor, options.GammaFactor);
  step.DetectTunnels = options.DetectTunnels;
  step.TunnelDistance = 2.0 * dx;
  step.TunnelMinDistance = 0.6 * plan.CloudSpacing;
  const double far = std::max(dx * std::ldexp(1.0, run - 1), plan.CloudSpacing);
  double checkedFar = -1.0;
  int nextFarCheck = 0;

  RunRecord<D> record;
  record.Grid = field.grid();
  record.Parameters = model;
  std::vector<std::int32_t> band;
  std::vector<double> energies;
  double bandSizes = 0.0;
  TiledReinitialiser<D> reinit;
  TiledDistances<D> distances;
  std::vector<std::uint8_t> stepHalos; // by block position: the halo its feet needed at the last step
  const auto mine = [&](std::int32_t id) { return distribution.owns(field, id); };
  for (int n = 0; n < options.MaxIterations; ++n)
  {
    bandTiles(field, ctx, band);
    Index added = 0;
    std::vector<std::uint32_t> reached = bandReachOf(field, band, options, ctx);
    std::vector<Index> freed;
    storage.FreedTiles += pruneTiles(
      field, band, reached, ctx, mine, [&](const std::vector<std::uint8_t>& left) { distances.removeTiles(left); },
      freed);
    std::vector<std::int64_t> changes;
    for (Index s : freed)
    {
      distribution.recordChange(changes, s,
        field.slot(s) == TiledField<D>::Inside ? TileDistribution<D>::SlotState::Inside
                                               : TileDistribution<D>::SlotState::Outside);
    }
    SLTK_RETURN_IF_ERROR(
      distribution.agree(extendBand(band, reached, options, run, field, added, distribution, changes)));
    shareBand(field, changes, options, ctx, distribution, distances, band, reached);
    storage.AddedTiles += added;
    storage.PeakTiles = std::max(storage.PeakTiles, field.tileCount());
    storage.ExactDistances += distances.ensure(field, band, reached, *plan.Locator, ctx, mine);
    distribution.exchange(field, true); // the ghosts' new tiles and distances
    const std::vector<std::int32_t> ownBand = distribution.owned(field, band);
    EnergyOptions energyOptions;
    energyOptions.P = model.P;
    energyOptions.SecondP = model.P != 2.0 ? 2.0 : 0.0;
    EnergyResult ep;
    Index bandCount = 0;
    SLTK_RETURN_IF_ERROR(
      distribution.agree(tiledEnergy(field, ownBand, energyOptions, ctx, distribution, ep, bandCount)));
    const double e2 = model.P != 2.0 ? ep.SecondEnergy : ep.Energy;
    if (ep.FrontCells == 0)
    {
      vanished = true;
      return Status::numericalFailure("run " + std::to_string(run) + ": the zero level set vanished (no front cell)");
    }
    energies.push_back(e2);
    if (n >= options.MinIterations && energyStalled(energies, options.EnergyWindow, options.Tolerance) &&
      n >= nextFarCheck)
    {
      if (!options.FollowFarPoints)
      {
        break;
      }
      double error = 0.0, fraction = 0.0;
      cloudErrors<Interp>(field, plan.Cloud, far, ctx, distribution, error, fraction);
      if (!stillApproaching(fraction, checkedFar))
      {
        break;
      }
      checkedFar = fraction;
      nextFarCheck = n + options.EnergyWindow;
    }
    step.Energy = ep.Energy;
    reinit.markBand(field, band, options.ReinitDilation, ctx, distribution); // the band before the step (1.53)
    const auto forget = [&](const std::vector<std::uint8_t>& removed) { distances.removeTiles(removed); };
    const int layers = distribution.distributed() ? stepGhostLayers(field, ownBand, step, ctx, distribution) : 0;
    storage.GhostLayers = std::max(storage.GhostLayers, layers);
    if (layers > 1) // shareBand held one layer
    {
      // The deeper ghosts come after every other tile and go after the step: the ids
      // of band, ownBand and the reinitialisation's nodes stay.
      distribution.holdGhosts(field, layers, forget);
      distribution.exchange(field, true);
      storage.PeakTiles = std::max(storage.PeakTiles, field.tileCount());
    }
    SLTK_RETURN_IF_ERROR(distribution.agree(tiledStep<Interp, D>(field, ownBand, step, ctx, stepHalos)));
    if (layers > 1)
    {
      distribution.holdGhosts(field, 1, forget);
    }
    distribution.exchange(field, false);
    SLTK_RETURN_IF_ERROR(distribution.agree(reinit.run(field, options.Reinit, ctx, distribution)));
    IterationRecord it;
    it.Run = run;
    it.Iteration = n + 1;
    it.Energy = e2;
    it.Change = reinit.relativeChange();
    double fraction = 0.0;
    cloudErrors<Interp>(field, plan.Cloud, far, ctx, distribution, it.CloudError, fraction);
    it.BandSize = bandCount * TiledField<D>::Nodes;
    const auto counts = distribution.storageCounts(field);
    it.StoredNodes = counts.Tiles * TiledField<D>::Nodes;
    it.Leaves = counts.Leaves;
    it.LargestRankLeaves = counts.LargestRankLeaves;
    it.UniformNodes = field.grid().nodeCount();
    it.Seconds = secondsSince(start);
    result.History.push_back(it);
    record.Iterations = n + 1;
    record.Energy = it.Energy;
    record.CloudError = it.CloudError;
    bandSizes += static_cast<double>(it.BandSize);
    const double progress = (run - 1 + double(n + 1) / options.MaxIterations) / options.Runs;
    const bool stop = ctx.interrupter().wasInterrupted(progress);
    if (!distribution.agree(stop ? Status::aborted() : Status::ok()).isOk())
    {
      result.Runs.push_back(record);
      return Status::aborted();
    }
  }
  record.Seconds = secondsSince(start);
  record.MeanBandSize = record.Iterations ? static_cast<Index>(bandSizes / record.Iterations) : 0;
  double error = 0.0;
  cloudErrors<Interp>(field, plan.Cloud, far, ctx, distribution, error, record.FarPoints);
  if (record.Iterations == 0)
  {
    record.CloudError = error;
    record.Energy = energies.empty() ? 0.0 : energies.back();
  }
  const Index tiles = distribution.globalTileCount(field);
  std::ostringstream log;
  log << "run " << run << " (tiled): " << record.Iterations << " iterations, E_2 = " << record.Energy
      << ", Err_P = " << record.CloudError << ", " << tiles << " tiles ("
      << static_cast<double>(tiles) * TiledField<D>::Nodes / static_cast<double>(field.grid().nodeCount()) * 100.0
      << "% of the grid), " << record.Seconds << " s";
  if (distribution.distributed())
  {
    log << "; rank " << distribution.rank() << " of " << distribution.comm().size() << " holds " << field.tileCount()
        << " tiles, ghosts included";
  }
  ctx.logger().log(LogLevel::Info, log.str());
  result.Runs.push_back(record);
  return Status::ok();
}

/// The run's storage record: tiles and node counts over every rank (each
/// tile counted by its owner; AddedTiles, FreedTiles, PeakTiles and
/// ExactDistances summed over the ranks), the bytes this rank holds.
template <int D>
void recordStorage(const TiledField<D>& field, int run, const TiledRunRecord& iterations,
  const TileDistribution<D>& distribution, std::vector<TiledRunRecord>& storage)
{
  TiledRunRecord r = iterations;
  r.Run = run;
  const auto held = distribution.storageCounts(field);
  r.Tiles = held.Tiles;
  r.StoredNodes = r.Tiles * TiledField<D>::Nodes;
  r.Leaves = held.Leaves;
  r.LargestRankLeaves = held.LargestRankLeaves;
  r.UniformNodes = field.grid().nodeCount();
  r.Bytes = field.bytes();
  if (distribution.distributed())
  {
    std::int64_t counts[4] = { r.AddedTiles, r.FreedTiles, r.PeakTiles, r.ExactDistances };
    distribution.comm().allReduce(counts, 4, ReduceOp::Sum);
    r.AddedTiles = counts[0];
    r.FreedTiles = counts[1];
    r.PeakTiles = counts[2];
    r.ExactDistances = counts[3];
  }
  storage.push_back(r);
}

/// The transferred level set reinitialised on its band before run `run`'s
/// iterations; the reinitialiser's per-node arrays are freed on return (they
/// were as large as the tiles on the bunny's run 3).
template <int D>
Status reinitialiseTransferred(const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field,
  TileDistribution<D>& distribution)
{
  std::vector<std::int32_t> band;
  bandTiles(field, ctx, band);
  Index added = 0;
  std::vector<std::int64_t> changes;
  SLTK_RETURN_IF_ERROR(distribution.agree(extendBand(
    band, bandReachOf(field, band, plan.Options, ctx), plan.Options, run, field, added, distribution, changes)));
  distribution.shareChanges(field, changes, NothingToForget); // only new tiles: the band's ids stay
  TiledReinitialiser<D> reinit;
  reinit.markBand(field, band, plan.Options.ReinitDilation, ctx, distribution);
  return distribution.agree(reinit.run(field, plan.Options.Reinit, ctx, distribution));
}

template <int D, class Interp>
Status runTiled(
  const ReconstructionPlan<D>& plan, const Context& ctx, const Communicator& comm, TiledReconstructionResult<D>& result)
{
  ReconstructionResult<D>& records = result.Records;
  TileDistribution<D> distribution(comm);
  // Run 1 is uniform (the coarsest grid), split in slabs over the ranks
  // (reconstruct()'s), then gathered whole on every rank for the transfer.
  SLTK_RETURN_IF_ERROR(reconstructFirstRuns(plan, 1, ctx, records, comm)); // the same status on every rank
  // Run 1 is uniform: every node is a leaf, and each rank owns its slab's rows.
  const GridSpec<D>& firstGrid = records.Runs.front().Grid;
  const Index firstNodes = firstGrid.nodeCount();
  const Index largestSlab = distribution.distributed()
    ? comm.allReduce(
        static_cast<std::int64_t>((records.Slab.End - records.Slab.Begin) * (firstNodes / firstGrid.Dims[D - 1])),
        ReduceOp::Max)
    : firstNodes;
  for (IterationRecord& it : records.History)
  {
    it.StoredNodes = it.Leaves = it.UniformNodes = firstNodes;
    it.LargestRankLeaves = largestSlab;
  }
  GridField<D> first = distribution.distributed()
    ? gatherSlabRows(records.SignedDistance, records.Slab, records.WholeGrid, records.SignedDistance.ghost(), comm)
    : std::move(records.SignedDistance);
  records.SignedDistance = GridField<D>{};
  records.Distance = GridField<D>{};
  first.fillGhosts();
  const double firstGamma = plan.Options.GammaFactor * first.spec().Spacing[0];
  PreviousLevelSet<D> previous;
  previous.Dense = &first;
  TiledField<D> last;
  if (plan.Options.Runs == 1)
  {
    // One run: its uniform result, stored in tiles.
    SLTK_RETURN_IF_ERROR(transferToTiles(previous, firstGamma, first.spec(), plan, 1, ctx, result.Field, distribution));
    recordStorage(result.Field, 1, TiledRunRecord{}, distribution, result.Storage);
    result.Owners = distribution.owners();
    return Status::ok();
  }
  double previousGamma = firstGamma;
  for (int run = 2; run <= plan.Options.Runs; ++run)
  {
    const GridSpec<D>& grid = plan.Grids.Runs[static_cast<size_t>(run - 1)];
    ctx.interrupter().start("run " + std::to_string(run) + "/" + std::to_string(plan.Options.Runs) + " (tiled)");
    const auto setup = Clock::now();
    TiledField<D> field;
    SLTK_RETURN_IF_ERROR(transferToTiles(previous, previousGamma, grid, plan, run, ctx, field, distribution));
    SLTK_RETURN_IF_ERROR(reinitialiseTransferred(plan, run, ctx, field, distribution));
    std::ostringstream log;
    log << "run " << run << " (tiled): " << distribution.globalTileCount(field) << " tiles of " << field.slotCount()
        << " (" << field.bytes() / 1048576.0 << " MB on this rank), set up in " << secondsSince(setup) << " s";
    ctx.logger().log(LogLevel::Info, log.str());
    if (run == 2)
    {
      first = GridField<D>{}; // run 1's grid is no longer needed
    }
    else
    {
      last = TiledField<D>{};
    }
    TiledRunRecord storage;
    storage.PeakTiles = field.tileCount(); // the transfer's and the setup reinitialisation's
    bool vanished = false;
    const Status status = iterateTiled<D, Interp>(plan, run, ctx, field, distribution, records, storage, vanished);
    ctx.interrupter().end();
    recordStorage(field, run, storage, distribution, result.Storage);
    SLTK_RETURN_IF_ERROR(status);
    last = std::move(field);
    previous.Dense = nullptr;
    previous.Tiled = &last;
    previousGamma = last.gamma();
  }
  result.Field = std::move(last);
  result.Owners = distribution.owners();
  return Status::ok();
}
} // namespace

template <int D>
Status reconstructTiled(
  const ReconstructionPlan<D>& plan, const Context& ctx, TiledReconstructionResult<D>& result, const Communicator& comm)
{
  result = TiledReconstructionResult<D>{};
  result.Box = plan.Box;
  if (plan.Options.ReinitDilation >= TileEdge)
  {
    return Status::invalidArgument("the tiled reconstruction takes a reinitialisation dilation of at most " +
      std::to_string(TileEdge - 1) + " nodes (one tile), not " + std::to_string(plan.Options.ReinitDilation) +
      ": use a smaller dilation or the uniform version");
  }
  const Status status = withReconstructionInterpolator<D>(
    plan.Options, [&](auto tag) { return runTiled<D, typename decltype(tag)::type>(plan, ctx, comm, result); });
  recordsToUser(plan.Box, result.Records);
  result.Records.CloudSpacing *= plan.Box.Scale;
  return status;
}

template <int D>
Index completeTiledDistances(const ReconstructionPlan<D>& plan, const Context& ctx, TiledField<D>& field,
  const std::vector<std::int32_t>& owners, int rank)
{
  return TiledDistances<D>::completeAll(
    field, *plan.Locator, ctx, [&](std::int32_t id) { return ownedBy(owners, field.tileSlot(id), rank); });
}

template <int D>
void gatherTiles(TiledReconstructionResult<D>& result, const Communicator& comm, int root)
{
  if (comm.size() == 1)
  {
    return;
  }
  TiledField<D>& field = result.Field;
  std::vector<std::vector<std::int32_t>> going(static_cast<size_t>(comm.size()));
  if (comm.rank() != root)
  {
    field.forEachTileInSlotOrder(
      [&](std::int32_t id)
      {
        if (result.Owners[static_cast<size_t>(field.tileSlot(id))] == comm.rank())
        {
          going[static_cast<size_t>(root)].push_back(id);
        }
      });
  }
  const std::vector<unsigned char> incoming = TileDistribution<D>::sendWholeTiles(field, going, comm);
  if (comm.rank() != root)
  {
    return;
  }
  TileDistribution<D>::storeWholeTiles(field, incoming);
  result.Owners.clear();
}

template Status reconstructTiled(
  const ReconstructionPlan<2>&, const Context&, TiledReconstructionResult<2>&, const Communicator&);
template void gatherTiles(TiledReconstructionResult<2>&, const Communicator&, int);
template void gatherTiles(TiledReconstructionResult<3>&, const Communicator&, int);
template Index completeTiledDistances(
  const ReconstructionPlan<2>&, const Context&, TiledField<2>&, const std::vector<std::int32_t>&, int);
template Index completeTiledDistances(
  const ReconstructionPlan<3>&, const Context&, TiledField<3>&, const std::vector<std::int32_t>&, int);
template Status reconstructTiled(
  const ReconstructionPlan<3>&, const Context&, TiledReconstructionResult<3>&, const Communicator&);

} // namespace sltk
