// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledDistances.h (private)
/// Exact distance to the cloud on a TiledField where the level-set step
/// needs it, computed on demand: the tiled counterpart of the uniform
/// version's ExactDistanceCache (ExactDistanceCache.h). A new tile's d is NaN
/// (not computed); ensure() gives the nearest-point distance to every stored
/// node within one node (diagonals included) of a band node (|phi| < gamma,
/// 1.48). That covers every d the iteration reads: the band node for the scale
/// (4.32), its axis neighbours for grad d in the feet (4.22)/(4.24), the
/// other corners of its cells for the energy (4.29)/(4.30). Work: one
/// nearest-point query per node the band reaches, once while its tile is kept
/// (a tile freed and allocated again, PruneTiles.h, computes its d again).

#include "BandReach.h"
#include "sltk/cloud/PointLocator.h"
#include "sltk/exec/Context.h"
#include "sltk/octree/TiledField.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sltk
{

template <int D>
class TiledDistances
{
public:
  /// Makes d exact within one node of `band`'s band nodes (`band`: the tiles
  /// with a band node; `reached`: the directions from each in which slots lie
  /// within one node or more of its band nodes, bandReach, and hold tiles,
  /// extendBand), in the tiles for which `mine(id)` (distributed: the
  /// rank's own, TileDistribution.h). Returns how many nodes were computed.
  template <class Mine>
  Index ensure(TiledField<D>& field, const std::vector<std::int32_t>& band, const std::vector<std::uint32_t>& reached,
    const PointLocator<D>& locator, const Context& ctx, Mine&& mine)
  {
    this->Complete.resize(static_cast<size_t>(field.tileCount()), 0);
    this->collectCandidates(field, band, reached, mine);
    std::vector<Index> computed(this->Candidates.size(), 0);
    ctx.parallelFor(
      0, static_cast<Index>(this->Candidates.size()),
      [&](Index b, Index e)
      {
        GridField<D> phi;
        Mask near{};
        Batch batch;
        for (Index c = b; c < e; ++c)
        {
          computed[static_cast<size_t>(c)] =
            this->ensureTile(field, this->Candidates[static_cast<size_t>(c)], locator, phi, near, batch);
        }
      },
      8);
    Index total = 0;
    for (Index n : computed)
    {
      total += n;
    }
    return total;
  }

  /// Makes d exact at every stored node (for an output of the whole field).
  /// Returns how many nodes were computed.
  /// Every stored node's distance of the tiles `mine(id)` accepts.
  template <class Mine>
  static Index completeAll(TiledField<D>& field, const PointLocator<D>& locator, const Context& ctx, Mine&& mine)
  {
    return static_cast<Index>(ctx.parallelSum(
      0, field.tileCount(),
      [&](Index b, Index e)
      {
        double computed = 0.0;
        Batch batch;
        for (Index id = b; id < e; ++id)
        {
          const auto tile = static_cast<std::int32_t>(id);
          if (!mine(tile))
          {
            continue;
          }
          const double* d = field.distance(tile);
          batch.Nodes.clear();
          for (Index k = 0; k < TiledField<D>::Nodes; ++k)
          {
            if (std::isnan(d[k]))
            {
              batch.Nodes.push_back(k);
            }
          }
          computed += static_cast<double>(batch.Nodes.size());
          batch.compute(field, tile, locator);
        }
        return computed;
      },
      8));
  }

private:
  /// The nearest-point distances of some nodes of one tile at once
  /// (PointLocator::nearestDistances): per thread.
  struct Batch
  {
    std::vector<Index> Nodes; ///< the tile's nodes (node order) to compute
    std::vector<std::array<double, D>> Positions;
    std::vector<double> Distances;
    std::vector<std::int64_t> Candidates;

    /// d at `Nodes` of tile `id`, each bit for bit the nearest point's distance.
    void compute(TiledField<D>& field, std::int32_t id, const PointLocator<D>& locator)
    {
      const size_t n = this->Nodes.size();
      if (n == 0)
      {
        return;
      }
      this->Positions.resize(n);
      this->Distances.resize(n);
      for (size_t i = 0; i < n; ++i)
      {
        this->Positions[i] = field.position(field.node(id, this->Nodes[i]));
      }
      locator.nearestDistances(
        this->Positions.data(), static_cast<std::int64_t>(n), this->Distances.data(), this->Candidates);
      double* d = field.distance(id);
      for (size_t i = 0; i < n; ++i)
      {
        d[this->Nodes[i]] = this->Distances[i];
      }
    }
  };

  /// The tiles (not yet complete) that may hold a node within one node of a
  /// band node: each band tile and the neighbours its band nodes reach.
  template <class Mine>
  void collectCandidates(const TiledField<D>& field, const std::vector<std::int32_t>& band,
    const std::vector<std::uint32_t>& reach, Mine&& mine)
  {
    this->Marked.assign(static_cast<size_t>(field.tileCount()), 0);
    this->Candidates.clear();
    for (size_t j = 0; j < band.size(); ++j)
    {
      forEachReachedSlot(field, band[j], reach[j],
        [&](Index slot)
        {
          const std::int32_t id = field.slot(slot);
          if (id >= 0 && !this->Complete[static_cast<size_t>(id)] && !this->Marked[static_cast<size_t>(id)] && mine(id))
          {
            this->Marked[static_cast<size_t>(id)] = 1;
            this->Candidates.push_back(id);
          }
        });
    }
  }

  static constexpr Index Edge = TileEdge + 2; ///< a tile and one node around it
  static constexpr Index BlockNodes = D == 2 ? Edge * Edge : Edge * Edge * Edge;
  using Mask = std::array<std::uint8_t, static_cast<size_t>(BlockNodes)>;

  /// d at the nodes of tile `id` within one node of a band node, where not known.
  Index ensureTile(
    TiledField<D>& field, std::int32_t id, const PointLocator<D>& locator, GridField<D>& phi, Mask& near, Batch& batch)
  {
    field.scratch(id, 1, 0, phi, nullptr); // no ghost layer: storage in node order
    const double* values = phi.storage().data();
    for (Index k = 0; k < BlockNodes; ++k)
    {
      near[static_cast<size_t>(k)] = std::fabs(values[k]) < field.gamma();
    }
    Index stride = 1;
    for (int a = 0; a < D; ++a) // the 3^D ball, one axis at a time
    {
      dilateAlong(near, stride);
      stride *= Edge;
    }
    const double* d = field.distance(id);
    Index unknown = 0;
    batch.Nodes.clear();
    for (Index k = 0; k < TiledField<D>::Nodes; ++k)
    {
      if (!std::isnan(d[k]))
      {
        continue;
      }
      Index b = 0, s = 1;
      for (int a = 0; a < D; ++a)
      {
        b += (1 + ((k >> (TileBits * a)) & (TileEdge - 1))) * s;
        s *= Edge;
      }
      if (near[static_cast<size_t>(b)])
      {
        batch.Nodes.push_back(k);
      }
      else
      {
        ++unknown;
      }
    }
    batch.compute(field, id, locator);
    if (unknown == 0)
    {
      this->Complete[static_cast<size_t>(id)] = 1;
    }
    return static_cast<Index>(batch.Nodes.size());
  }

  /// One pass of a 3-node dilation of `mask` along the axis of `stride`: a
  /// node is set when it or an axis neighbour was. The lines along the axis
  /// start at the nodes whose index along it is 0: `inner` below the axis,
  /// `outer` above it (no division a node).
  static void dilateAlong(Mask& mask, Index stride)
  {
    const Index span = stride * Edge;
    for (Index outer = 0; outer < BlockNodes; outer += span)
    {
      for (Index inner = 0; inner < stride; ++inner)
      {
        std::uint8_t before = 0;
        for (Index n = 0; n < Edge; ++n)
        {
          const size_t at = static_cast<size_t>(outer + inner + n * stride);
          const std::uint8_t here = mask[at];
          const std::uint8_t after = n + 1 < Edge ? mask[at + static_cast<size_t>(stride)] : 0;
          mask[at] = here | before | after;
          before = here;
        }
      }
    }
  }

public:
  /// Follows TiledField::removeTiles(remove): the kept tiles' state, renumbered.
  void removeTiles(const std::vector<std::uint8_t>& remove)
  {
    size_t kept = 0;
    for (size_t id = 0; id < this->Complete.size(); ++id)
    {
      if (!remove[id])
      {
        this->Complete[kept++] = this->Complete[id];
      }
    }
    this->Complete.resize(kept);
  }

private:
  std::vector<std::uint8_t> Complete; ///< per tile: d is known at every node
  std::vector<std::uint8_t> Marked;   ///< per tile: a candidate of this call
  std::vector<std::int32_t> Candidates;
};

} // namespace sltk
