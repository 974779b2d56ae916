// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledField.h
/// A level-set function and the distance to the cloud stored only near the
/// front: the nodes of one run's uniform grid (thesis 4.36) grouped in tiles
/// of 8^D nodes, of which only the tiles that hold or border the narrow band
/// (1.48) are allocated (Documentation/Octree.md, "The tiled band").
///
/// Every other tile is a slot that records on which side of the front it lies:
/// phi is +gamma there outside and -gamma inside, the value the cut-off (1.49)
/// gives the uniform version's nodes away from the front. The slots form a
/// dense grid over the run's grid (one int32 per 8^D nodes: 8 MB for the
/// thesis's finest dragon grid of 295M nodes); the stored tiles cost 16 bytes
/// a node. scratch() and scratchBlock() copy a tile or a block of tiles and
/// the nodes around it (tiles or slots) into a uniform GridField, on which the
/// uniform version's kernels run unchanged.

#include "sltk/grid/GridField.h"

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace sltk
{

constexpr int TileBits = 3;
constexpr Index TileEdge = Index(1) << TileBits; ///< nodes per tile and axis
/// Tile positions per axis of the blocks the level-set step copies at once,
/// the surface is contoured by, and a distributed band never splits between
/// ranks (aligned on multiples of it).
constexpr Index TileBlockEdge = 4;

template <int D>
constexpr Index tileNodes()
{
  Index n = 1;
  for (int a = 0; a < D; ++a)
  {
    n *= TileEdge;
  }
  return n;
}

template <int D>
class TiledField
{
public:
  static constexpr std::int32_t Outside = -1; ///< slot without a tile: phi = +gamma
  static constexpr std::int32_t Inside = -2;  ///< slot without a tile: phi = -gamma
  /// Slot whose tile another rank holds and this one does not (the distributed
  /// band, TileDistribution.h): phi and d read NaN here, so that a read the
  /// ghost layer should have covered shows in the result.
  static constexpr std::int32_t Remote = -4;
  static constexpr Index Nodes = tileNodes<D>();

  /// An empty field over `grid` (every slot Outside) with the cut-off value gamma.
  void reset(const GridSpec<D>& grid, double gamma);

  const GridSpec<D>& grid() const { return this->Grid; }
  double gamma() const { return this->Gamma; }
  const std::array<Index, D>& slotDims() const { return this->SlotDims; }
  Index slotCount() const { return static_cast<Index>(this->Slots.size()); }
  Index tileCount() const { return static_cast<Index>(this->Origins.size()); }
  /// Changes whenever tiles are added or removed (their ids may have changed).
  std::uint64_t generation() const { return this->Generation; }

  /// Slot of tile coordinates t (each in [0, slotDims)).
  Index slotIndex(const std::array<Index, D>& t) const
  {
    Index s = 0;
    for (int a = D - 1; a >= 0; --a)
    {
      s = s * this->SlotDims[a] + t[a];
    }
    return s;
  }
  std::int32_t slot(Index s) const { return this->Slots[static_cast<size_t>(s)]; }
  void setSide(Index s, bool inside) { this->Slots[static_cast<size_t>(s)] = inside ? Inside : Outside; }
  void setRemote(Index s) { this->Slots[static_cast<size_t>(s)] = Remote; }
  /// Tile coordinates of slot s.
  std::array<Index, D> slotCoordinates(Index s) const;

  /// Allocates a tile in slot s (when it has none): its phi is the slot's
  /// +-gamma, its distance NaN (not computed) until set. Returns the tile's id.
  std::int32_t addTile(Index s);
  /// Frees the tiles with remove[id] != 0: with 1 the slot is a side again, the
  /// side of the tile's first node's sign (the caller removes only tiles at
  /// +-gamma throughout); with RemoveToRemote it is Remote (a ghost tile
  /// dropped). The others keep their order and take ids 0, 1, ...
  static constexpr std::uint8_t RemoveToRemote = 2;
  void removeTiles(const std::vector<std::uint8_t>& remove);
  /// Tile coordinates of tile `id`.
  const std::array<Index, D>& tileOrigin(std::int32_t id) const { return this->Origins[static_cast<size_t>(id)]; }
  Index tileSlot(std::int32_t id) const { return this->SlotOf[static_cast<size_t>(id)]; }
  /// Calls f(id) for every tile in slot order: an order that does not depend on
  /// the ids, which follow the order tiles were allocated and freed in.
  template <class F>
  void forEachTileInSlotOrder(F&& f) const
  {
    for (const std::int32_t entry : this->Slots)
    {
      if (entry >= 0)
      {
        f(entry);
      }
    }
  }

  double* phi(std::int32_t id) { return this->values(id); }
  const double* phi(std::int32_t id) const { return this->values(id); }
  double* distance(std::int32_t id) { return this->values(id) + ChunkTiles * Nodes; }
  const double* distance(std::int32_t id) const { return this->values(id) + ChunkTiles * Nodes; }

  /// The octree of a tile (its output as a hyper tree, Documentation/Octree.md):
  /// the tile refined from one cell of TileEdge^D nodes down to one leaf per
  /// node, but for flat cells, which stay leaves. A cell of tile `id` covering
  /// `size` nodes per axis from its node `first` (tile-local) is flat when
  /// every node of it lies in the grid and holds the same cut-off value,
  /// +gamma or -gamma (1.49): one leaf holds it exactly (the thesis coarsens
  /// where phi is flattened to +-gamma, 5.2.3).
  bool flatCell(std::int32_t id, const std::array<Index, D>& first, Index size) const;
  /// Whether the node `first` (tile-local) of tile `id` lies in the grid: a
  /// cell starting beyond it holds no node (masked in the output, no leaf).
  bool nodeInGrid(std::int32_t id, const std::array<Index, D>& first) const
  {
    bool inside = true;
    for (int a = 0; a < D; ++a)
    {
      inside = inside && this->Origins[static_cast<size_t>(id)][a] * TileEdge + first[a] < this->Grid.Dims[a];
    }
    return inside;
  }
  /// Leaves of tile `id`'s octree (flatCell), its nodes beyond the grid left out.
  Index leafCount(std::int32_t id) const;

  /// Grid index of node `local` (x fastest, in [0, Nodes)) of tile `id`.
  std::array<Index, D> node(std::int32_t id, Index local) const
  {
    std::array<Index, D> i{};
    for (int a = 0; a < D; ++a)
    {
      i[a] = this->Origins[static_cast<size_t>(id)][a] * TileEdge + ((local >> (TileBits * a)) & (TileEdge - 1));
    }
    return i;
  }
  std::array<double, D> position(const std::array<Index, D>& i) const
  {
    std::array<double, D> x{};
    for (int a = 0; a < D; ++a)
    {
      x[a] = this->Grid.coordinate(a, i[a]);
    }
    return x;
  }

  /// phi at grid index i (any integers: beyond the slots, +gamma; NaN in a Remote slot).
  double value(const std::array<Index, D>& i) const
  {
    std::array<Index, D> t{};
    Index local = 0;
    for (int a = 0; a < D; ++a)
    {
      if (i[a] < 0 || i[a] >= this->SlotDims[a] * TileEdge)
      {
        return this->Gamma;
      }
      t[a] = i[a] >> TileBits;
      local |= (i[a] & (TileEdge - 1)) << (TileBits * a);
    }
    const std::int32_t entry = this->Slots[static_cast<size_t>(this->slotIndex(t))];
    if (entry >= 0)
    {
      return this->phi(entry)[local];
    }
    return entry == Remote ? std::numeric_limits<double>::quiet_NaN() : (entry == Inside ? -this->Gamma : this->Gamma);
  }

  /// Tile `id` and `halo` nodes around it as a uniform field with `ghost`
  /// ghost layers filled by the grid's boundary policy: phi, and d when
  /// `dist` is not null. Missing tiles read +-gamma (phi) and NaN (d),
  /// Remote ones NaN.
  void scratch(std::int32_t id, int halo, int ghost, GridField<D>& phi, GridField<D>* dist) const
  {
    this->scratchBlock(this->tileOrigin(id), 1, halo, ghost, phi, dist);
  }
  /// The same for the block of `tiles`^D tile positions whose first tile
  /// coordinates are `first` (slots with or without a tile, or beyond them).
  /// Rows up to (MaxScratchSegments - 2) tiles wide, halo included, need no
  /// allocation (the solver's blocks: at most 12). With `distHalo` in
  /// [0, halo), d is copied only within `distHalo` nodes of the block (the SL
  /// step reads it at its band nodes and their axis neighbours, (4.22)/(4.24));
  /// its nodes beyond, and its ghost layers, hold whatever the field held before.
  static constexpr int MaxScratchSegments = 16;
  void scratchBlock(const std::array<Index, D>& first, Index tiles, int halo, int ghost, GridField<D>& phi,
    GridField<D>* dist, int distHalo = -1) const;

  /// Bytes held (tiles and slots).
  double bytes() const
  {
    return static_cast<double>(this->Chunks.size()) * ChunkTiles * Nodes * 2.0 * sizeof(double) +
      static_cast<double>(this->Slots.capacity()) * sizeof(std::int32_t) +
      static_cast<double>(this->Origins.capacity()) * (sizeof(std::array<Index, D>) + sizeof(Index));
  }

private:
  GridSpec<D> Grid;
  double Gamma = 0.0;
  std::uint64_t Generation = 0;
  std::array<Index, D> SlotDims{};
  std::vector<std::int32_t> Slots;
  std::vector<std::array<Index, D>> Origins;
  std::vector<Index> SlotOf;
  /// Tiles are stored in chunks of ChunkTiles (phi of each, then d of each),
  /// so that adding tiles never moves or copies the stored ones (removeTiles
  /// moves the kept ones down: pointers from phi() and distance() then change).
  static constexpr Index ChunkTiles = 64;
  double* values(std::int32_t id) const
  {
    return this->Chunks[static_cast<size_t>(id / ChunkTiles)].get() + (id % ChunkTiles) * Nodes;
  }
  std::vector<std::unique_ptr<double[]>> Chunks;
};

extern template class TiledField<2>;
extern template class TiledField<3>;

} // namespace sltk
