// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/tiled/TiledReconstruction.h"

#include "BandReach.h"
#include "PruneTiles.h"
#include "TiledDistances.h"
#include "TiledReinitialise.h"
#include "sltk/exec/Memory.h"
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
constexpr int HaloStep = 4;     ///< the step's halo is a multiple of this (fewer scratch shapes)
constexpr int MaxHalo = 32;     ///< the farthest the step reads around a tile
constexpr Index BlockTiles = 4; ///< the step copies blocks of 4^D tile positions (32^D nodes) at once

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

/// The memory of `tiles` more tiles, refused when it does not fit.
template <int D>
Status checkTileMemory(const TiledField<D>& field, Index tiles, const ReconstructionOptions& options, int run)
{
  const double need = field.bytes() + static_cast<double>(tiles) * TiledField<D>::Nodes * 2.0 * sizeof(double);
  const double available = static_cast<double>(options.MemoryBudget ? options.MemoryBudget : availableMemoryBytes());
  if (available > 0.0 && need > available)
  {
    std::ostringstream m;
    m.precision(3);
    m << "run " << run << " of the tiled reconstruction needs " << need / 1048576.0 << " MB for "
      << field.tileCount() + tiles << " tiles, more than the " << available / 1048576.0
      << " MB available: use fewer runs or a larger C_dx";
    return Status::outOfMemory(m.str());
  }
  return Status::ok();
}

/// Run r's field from run r-1's level set: tiles around its band,
/// phi by Q1 cut at +-gamma, d not yet computed (TiledDistances); every other
/// slot the side of its centre.
template <int D>
Status transferToTiles(const PreviousLevelSet<D>& previous, double previousGamma, const GridSpec<D>& grid,
  const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field)
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
  Index count = 0;
  for (std::uint8_t m : marked)
  {
    count += m;
  }
  SLTK_RETURN_IF_ERROR(checkTileMemory(field, count, plan.Options, run));
  // Sides of the slots without tiles: the sign of the previous phi at their centre.
  ctx.parallelFor(0, field.slotCount(),
    [&](Index b, Index e)
    {
      for (Index s = b; s < e; ++s)
      {
        if (!marked[static_cast<size_t>(s)])
        {
          const auto t = field.slotCoordinates(s);
          std::array<double, D> x{};
          for (int a = 0; a < D; ++a)
          {
            x[a] = grid.Origin[a] + (static_cast<double>(t[a] * TileEdge) + 0.5 * (TileEdge - 1)) * grid.Spacing[a];
          }
          field.setSide(s, previous.at(x) < 0.0);
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
    if (marked[static_cast<size_t>(s)])
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
/// uniform version holds there. Returns the number of tiles added.
template <int D>
Status extendBand(const std::vector<std::int32_t>& band, const std::vector<std::uint32_t>& reached,
  const ReconstructionOptions& options, int run, TiledField<D>& field, Index& added)
{
  added = 0;
  std::vector<Index> missing;
  for (size_t j = 0; j < band.size(); ++j)
  {
    forEachReachedSlot(field, band[j], reached[j],
      [&](Index s)
      {
        if (field.slot(s) < 0)
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

/// E_p (and E_2) of (4.29)/(4.30) over the band's cells, tile by tile.
template <int D>
Status tiledEnergy(const TiledField<D>& field, const std::vector<std::int32_t>& band, const EnergyOptions& options,
  const Context& ctx, EnergyResult& result)
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
        field.scratch(id, 1, 1, s.Phi, &s.Dist);
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
  result = EnergyResult{};
  for (size_t j = 0; j < parts.size(); ++j)
  {
    SLTK_RETURN_IF_ERROR(failures[j]);
    result.Integral += parts[j].Integral;
    result.SecondIntegral += parts[j].SecondIntegral;
    result.FrontCells += parts[j].FrontCells;
  }
  energiesFromIntegrals(result, options);
  return Status::ok();
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
  std::vector<std::pair<Index, Index>> keyed(band.size());
  for (size_t j = 0; j < band.size(); ++j)
  {
    keyed[j] = { TileBlocks<D>::key(field, field.tileOrigin(band[j])), static_cast<Index>(j) };
  }
  const TileBlocks<D> blocks(field, std::move(keyed));
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
        const auto bandNodes = [&](Index halo)
        {
          s.Nodes.clear();
          forEachMember(
            [&](size_t j)
            {
              const double* p = field.phi(band[j]);
              const auto o = offset(j);
              for (Index k = 0; k < TiledField<D>::Nodes; ++k)
              {
                if (inBand(p[k]))
                {
                  s.Nodes.push_back(scratchNode<D>(k, halo, o, BlockTiles));
                }
              }
            });
        };
        std::uint8_t& last = halos[static_cast<size_t>(TileBlocks<D>::key(field, first))];
        const Index guess = last;
        if (guess > 0)
        {
          field.scratchBlock(first, BlockTiles, static_cast<int>(guess), Ghost, s.Phi, &s.Dist);
        }
        else
        {
          field.scratchBlock(first, BlockTiles, 1, 1, s.Phi, &s.Dist);
        }
        bandNodes(std::max<Index>(guess, 1));
        const double foot = largestFoot(s.Phi, s.Dist, s.Nodes, par);
        feet[static_cast<size_t>(block)] = foot;
        const Index need = static_cast<Index>(std::ceil(foot / dx)) + StencilReach;
        if (need > MaxHalo)
        {
          continue; // reported below
        }
        // The copy's origin enters the feet's coordinates: always the needed halo, so that the
        // result does not depend on the last step's (a wider copy changed the scans' iterations).
        const Index halo = std::max<Index>(HaloStep, (need + HaloStep - 1) / HaloStep * HaloStep);
        last = static_cast<std::uint8_t>(halo);
        if (halo != guess)
        {
          field.scratchBlock(first, BlockTiles, static_cast<int>(halo), Ghost, s.Phi, &s.Dist);
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
    if (feet[block] > (MaxHalo - StencilReach) * dx)
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
template <class Interp, int D>
void cloudErrors(const TiledField<D>& field, const PointCloud<D>& cloud, double far, const Context& ctx,
  double& meanError, double& farFraction)
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
      keyed.emplace_back(TileBlocks<D>::key(field, t), q);
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
  for (size_t j = 0; j < sums.size(); ++j)
  {
    sum += sums[j];
    farCount += fars[j];
  }
  meanError = sum / static_cast<double>(cloud.size());
  farFraction = farCount / static_cast<double>(cloud.size());
}

/// The iterations of run `run` >= 2 on its tiled field (the uniform version's iterate()).
template <int D, class Interp>
Status iterateTiled(const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field,
  ReconstructionResult<D>& result, TiledRunRecord& storage, bool& vanished)
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
  for (int n = 0; n < options.MaxIterations; ++n)
  {
    bandTiles(field, ctx, band);
    Index added = 0;
    const std::vector<std::uint32_t> reached = bandReachOf(field, band, options, ctx);
    storage.FreedTiles += pruneTiles(
      field, band, reached, ctx, [&](const std::vector<std::uint8_t>& left) { distances.removeTiles(left); });
    SLTK_RETURN_IF_ERROR(extendBand(band, reached, options, run, field, added));
    storage.AddedTiles += added;
    storage.PeakTiles = std::max(storage.PeakTiles, field.tileCount());
    storage.ExactDistances += distances.ensure(field, band, reached, *plan.Locator, ctx);
    EnergyOptions energyOptions;
    energyOptions.P = model.P;
    energyOptions.SecondP = model.P != 2.0 ? 2.0 : 0.0;
    EnergyResult ep;
    SLTK_RETURN_IF_ERROR(tiledEnergy(field, band, energyOptions, ctx, ep));
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
      cloudErrors<Interp>(field, plan.Cloud, far, ctx, error, fraction);
      if (!stillApproaching(fraction, checkedFar))
      {
        break;
      }
      checkedFar = fraction;
      nextFarCheck = n + options.EnergyWindow;
    }
    step.Energy = ep.Energy;
    reinit.markBand(field, band, options.ReinitDilation, ctx); // the band before the step, dilated (1.53)
    SLTK_RETURN_IF_ERROR((tiledStep<Interp, D>(field, band, step, ctx, stepHalos)));
    SLTK_RETURN_IF_ERROR(reinit.run(field, options.Reinit, ctx));
    IterationRecord it;
    it.Run = run;
    it.Iteration = n + 1;
    it.Energy = e2;
    it.Change = reinit.relativeChange();
    double fraction = 0.0;
    cloudErrors<Interp>(field, plan.Cloud, far, ctx, it.CloudError, fraction);
    it.BandSize = static_cast<Index>(band.size()) * TiledField<D>::Nodes;
    it.StoredNodes = field.tileCount() * TiledField<D>::Nodes;
    it.Seconds = secondsSince(start);
    result.History.push_back(it);
    record.Iterations = n + 1;
    record.Energy = it.Energy;
    record.CloudError = it.CloudError;
    bandSizes += static_cast<double>(it.BandSize);
    const double progress = (run - 1 + double(n + 1) / options.MaxIterations) / options.Runs;
    if (ctx.interrupter().wasInterrupted(progress))
    {
      result.Runs.push_back(record);
      return Status::aborted();
    }
  }
  record.Seconds = secondsSince(start);
  record.MeanBandSize = record.Iterations ? static_cast<Index>(bandSizes / record.Iterations) : 0;
  double error = 0.0;
  cloudErrors<Interp>(field, plan.Cloud, far, ctx, error, record.FarPoints);
  if (record.Iterations == 0)
  {
    record.CloudError = error;
    record.Energy = energies.empty() ? 0.0 : energies.back();
  }
  std::ostringstream log;
  log << "run " << run << " (tiled): " << record.Iterations << " iterations, E_2 = " << record.Energy
      << ", Err_P = " << record.CloudError << ", " << field.tileCount() << " tiles ("
      << static_cast<double>(field.tileCount()) * TiledField<D>::Nodes / static_cast<double>(field.grid().nodeCount()) *
      100.0
      << "% of the grid), " << record.Seconds << " s";
  ctx.logger().log(LogLevel::Info, log.str());
  result.Runs.push_back(record);
  return Status::ok();
}

template <int D>
void recordStorage(
  const TiledField<D>& field, int run, const TiledRunRecord& iterations, std::vector<TiledRunRecord>& storage)
{
  TiledRunRecord r = iterations;
  r.Run = run;
  r.Tiles = field.tileCount();
  r.StoredNodes = field.tileCount() * TiledField<D>::Nodes;
  r.UniformNodes = field.grid().nodeCount();
  r.Bytes = field.bytes();
  storage.push_back(r);
}

/// The transferred level set reinitialised on its band before run `run`'s
/// iterations; the reinitialiser's per-node arrays are freed on return (they
/// were as large as the tiles on the bunny's run 3).
template <int D>
Status reinitialiseTransferred(const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field)
{
  std::vector<std::int32_t> band;
  bandTiles(field, ctx, band);
  Index added = 0;
  SLTK_RETURN_IF_ERROR(extendBand(band, bandReachOf(field, band, plan.Options, ctx), plan.Options, run, field, added));
  TiledReinitialiser<D> reinit;
  reinit.markBand(field, band, plan.Options.ReinitDilation, ctx);
  return reinit.run(field, plan.Options.Reinit, ctx);
}

template <int D, class Interp>
Status runTiled(const ReconstructionPlan<D>& plan, const Context& ctx, TiledReconstructionResult<D>& result)
{
  ReconstructionResult<D>& records = result.Records;
  SLTK_RETURN_IF_ERROR(reconstructFirstRuns(plan, 1, ctx, records));
  for (IterationRecord& it : records.History)
  {
    it.StoredNodes = records.Runs.front().Grid.nodeCount(); // run 1 is uniform
  }
  GridField<D> first = std::move(records.SignedDistance);
  records.Distance = GridField<D>{};
  first.fillGhosts();
  const double firstGamma = plan.Options.GammaFactor * first.spec().Spacing[0];
  PreviousLevelSet<D> previous;
  previous.Dense = &first;
  TiledField<D> last;
  if (plan.Options.Runs == 1)
  {
    // One run: its uniform result, stored in tiles.
    SLTK_RETURN_IF_ERROR(transferToTiles(previous, firstGamma, first.spec(), plan, 1, ctx, result.Field));
    recordStorage(result.Field, 1, TiledRunRecord{}, result.Storage);
    return Status::ok();
  }
  double previousGamma = firstGamma;
  for (int run = 2; run <= plan.Options.Runs; ++run)
  {
    const GridSpec<D>& grid = plan.Grids.Runs[static_cast<size_t>(run - 1)];
    ctx.interrupter().start("run " + std::to_string(run) + "/" + std::to_string(plan.Options.Runs) + " (tiled)");
    const auto setup = Clock::now();
    TiledField<D> field;
    SLTK_RETURN_IF_ERROR(transferToTiles(previous, previousGamma, grid, plan, run, ctx, field));
    SLTK_RETURN_IF_ERROR(reinitialiseTransferred(plan, run, ctx, field));
    std::ostringstream log;
    log << "run " << run << " (tiled): " << field.tileCount() << " tiles of " << field.slotCount() << " ("
        << field.bytes() / 1048576.0 << " MB), set up in " << secondsSince(setup) << " s";
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
    const Status status = iterateTiled<D, Interp>(plan, run, ctx, field, records, storage, vanished);
    ctx.interrupter().end();
    recordStorage(field, run, storage, result.Storage);
    SLTK_RETURN_IF_ERROR(status);
    last = std::move(field);
    previous.Dense = nullptr;
    previous.Tiled = &last;
    previousGamma = last.gamma();
  }
  result.Field = std::move(last);
  return Status::ok();
}
} // namespace

template <int D>
Status reconstructTiled(const ReconstructionPlan<D>& plan, const Context& ctx, TiledReconstructionResult<D>& result)
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
    plan.Options, [&](auto tag) { return runTiled<D, typename decltype(tag)::type>(plan, ctx, result); });
  recordsToUser(plan.Box, result.Records);
  result.Records.CloudSpacing *= plan.Box.Scale;
  return status;
}

template <int D>
Index completeTiledDistances(const ReconstructionPlan<D>& plan, const Context& ctx, TiledField<D>& field)
{
  return TiledDistances<D>::completeAll(field, *plan.Locator, ctx);
}

template Status reconstructTiled(const ReconstructionPlan<2>&, const Context&, TiledReconstructionResult<2>&);
template Index completeTiledDistances(const ReconstructionPlan<2>&, const Context&, TiledField<2>&);
template Index completeTiledDistances(const ReconstructionPlan<3>&, const Context&, TiledField<3>&);
template Status reconstructTiled(const ReconstructionPlan<3>&, const Context&, TiledReconstructionResult<3>&);

} // namespace sltk
