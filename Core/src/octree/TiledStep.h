// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledStep.h
/// The tiled band's SL step (4.22)/(4.24) and its Err_P (4.35), block by
/// block: each block of BlockTiles^D tile positions is copied once with the
/// halo its feet reach (Documentation/Octree.md, "The tiled band"), and the
/// uniform kernels run on the copy.
#include "TileDistribution.h"
#include "sltk/octree/TiledField.h"
#include "sltk/recon/FarPointSeeds.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/ReconstructionInterpolator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace sltk
{
namespace octree
{

constexpr int Ghost = 2;        ///< ghost layers of the scratch fields (WENO3 / CWENO stencils)
constexpr int StencilReach = 2; ///< nodes beyond a foot's cell the interpolators read
constexpr int DistReach = 1;    ///< nodes around the band the step reads d at (the centred gradient of (4.22)/(4.24))
constexpr int HaloStep = 4;     ///< the step's halo is a multiple of this (fewer scratch shapes)
constexpr int MaxHalo = 32;     ///< the farthest the step reads around a tile
constexpr Index BlockTiles = TileBlockEdge; ///< the step copies blocks of 4^D tile positions (32^D nodes) at once
/// Blocks of one chunk of the step share its scratch: its copies take no new allocation nor zero fill.
constexpr Index BlocksPerChunk = 4;
static_assert(MaxHalo <= MaxGhostLayers * TileEdge, "the ghost layers cover the step's farthest read");

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

/// Per-thread scratch of a tile and its neighbourhood.
template <int D>
struct TileScratch
{
  GridField<D> Phi, Dist;
  NodeList Nodes;
  std::vector<double> Values;
};

/// The largest displacement of a foot of (4.22)/(4.24) from its node, in the
/// same arithmetic as levelSetStep (the scale (4.32), grad d or, through a
/// tunnel, grad phi, and the spread of the tangent points). Only the nodes
/// that take feet count (|phi| <= FeetWithin): the others' linearised step
/// reads one node around them.
template <int D>
double largestFoot(
  const GridField<D>& phi, const GridField<D>& dist, const NodeList& nodes, const LevelSetStepParameters& par)
{
  double largest = 0.0;
  for (Index k : nodes)
  {
    const auto i = phi.nodeIndex(k);
    if (std::fabs(phi(i)) > par.FeetWithin)
    {
      continue;
    }
    const double d = dist(i);
    const double scale = detail::stepScale(phi(i), d, par);
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
    BlocksPerChunk);
  for (size_t block = 0; block < feet.size(); ++block)
  {
    if (!(feet[block] <= (MaxHalo - StencilReach) * dx))
    {
      std::ostringstream m;
      m << "a foot of the semi-Lagrangian step moved " << feet[block] / dx << " cells, beyond the "
        << MaxHalo - StencilReach
        << " the octree reconstruction reads around a tile: use the uniform version or a smaller eta";
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

/// The points a query of cloudErrors() finds outside the zero level set by more than Threshold.
struct PointsOutside
{
  double Threshold = 0.0;
  std::vector<OutsidePoint> Points;
};

/// Err_P (4.35) and the far-point fraction: |I[phi](Q)| at every point, the
/// points grouped by the block of BlockTiles^D tile positions around them,
/// interpolated on one copy of the block (slots without a tile at their
/// +-gamma: a point there can still read a neighbouring tile's nodes, as the
/// uniform version reads them). Points beyond the slots are gamma away.
///
/// Distributed, a rank takes the points in its own slots; the blocks' sums are
/// added in block order over every rank (the one-rank order). Collective.
/// With `outside`, also this rank's points with I[phi](Q) > outside->Threshold
/// (recon/FarPointSeeds.h), in block order.
template <class Interp, int D>
void cloudErrors(const TiledField<D>& field, const PointCloud<D>& cloud, double far, const Context& ctx,
  const TileDistribution<D>& distribution, double& meanError, double& farFraction, PointsOutside* outside = nullptr)
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
  std::vector<std::vector<OutsidePoint>> outsideByBlock(outside ? static_cast<size_t>(blocks.count()) : 0);
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
          const double signedValue =
            interpolate(interp, s.Phi.spec(), cloud.Points[static_cast<size_t>(blocks.Items[j])].data());
          const double v = std::fabs(signedValue);
          sums[static_cast<size_t>(block)] += v;
          fars[static_cast<size_t>(block)] += v > far ? 1.0 : 0.0;
          if (outside && signedValue > outside->Threshold)
          {
            outsideByBlock[static_cast<size_t>(block)].push_back({ blocks.Items[j], signedValue });
          }
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
  for (const std::vector<OutsidePoint>& points : outsideByBlock)
  {
    outside->Points.insert(outside->Points.end(), points.begin(), points.end());
  }
}

} // namespace octree
} // namespace sltk
