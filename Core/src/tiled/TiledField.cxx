// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/tiled/TiledField.h"

#include <algorithm>
#include <limits>

namespace sltk
{

template <int D>
void TiledField<D>::reset(const GridSpec<D>& grid, double gamma)
{
  this->Grid = grid;
  this->Gamma = gamma;
  Index slots = 1;
  for (int a = 0; a < D; ++a)
  {
    this->SlotDims[a] = (grid.Dims[a] + TileEdge - 1) / TileEdge;
    slots *= this->SlotDims[a];
  }
  this->Slots.assign(static_cast<size_t>(slots), Outside);
  this->Origins.clear();
  this->SlotOf.clear();
  this->Chunks.clear();
}

template <int D>
std::array<Index, D> TiledField<D>::slotCoordinates(Index s) const
{
  std::array<Index, D> t{};
  for (int a = 0; a < D; ++a)
  {
    t[a] = s % this->SlotDims[a];
    s /= this->SlotDims[a];
  }
  return t;
}

template <int D>
std::int32_t TiledField<D>::addTile(Index s)
{
  std::int32_t& entry = this->Slots[static_cast<size_t>(s)];
  if (entry >= 0)
  {
    return entry;
  }
  const double fill = entry == Inside ? -this->Gamma : this->Gamma;
  const std::int32_t id = static_cast<std::int32_t>(this->Origins.size());
  this->Origins.push_back(this->slotCoordinates(s));
  this->SlotOf.push_back(s);
  if (id % ChunkTiles == 0)
  {
    this->Chunks.emplace_back(new double[static_cast<size_t>(2 * ChunkTiles * Nodes)]);
  }
  std::fill_n(this->phi(id), Nodes, fill);
  std::fill_n(this->distance(id), Nodes, std::numeric_limits<double>::quiet_NaN());
  entry = id;
  return id;
}

template <int D>
double TiledField<D>::value(const std::array<Index, D>& i) const
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
  return entry == Inside ? -this->Gamma : this->Gamma;
}

template <int D>
void TiledField<D>::scratchBlock(
  const std::array<Index, D>& first, Index tiles, int halo, int ghost, GridField<D>& phi, GridField<D>* dist) const
{
  const Index h = halo;
  const Index edge = tiles * TileEdge + 2 * h;
  GridSpec<D> block = this->Grid;
  std::array<Index, D> start{}; // grid index of the block's first node
  for (int a = 0; a < D; ++a)
  {
    start[a] = first[a] * TileEdge - h;
    block.Dims[a] = edge;
    block.Origin[a] = this->Grid.coordinate(a, start[a]);
  }
  const auto shape = [&](GridField<D>& f)
  {
    if (f.spec().Dims != block.Dims || f.ghost() != ghost)
    {
      f.resize(block, ghost);
    }
    f.setGeometry(block.Origin, block.Spacing);
  };
  shape(phi);
  if (dist)
  {
    shape(*dist);
  }
  const auto floorTile = [](Index g) { return g >= 0 ? g / TileEdge : -((TileEdge - 1 - g) / TileEdge); };
  const double unknown = std::numeric_limits<double>::quiet_NaN();
  // Row by row along x, tile by tile along the row.
  Index rows = 1;
  for (int a = 1; a < D; ++a)
  {
    rows *= edge;
  }
  for (Index row = 0; row < rows; ++row)
  {
    std::array<Index, D> i{}; // block index of the row's first node
    std::array<Index, D> t{};
    bool beyond = false;
    Index local = 0; // the row's node offset inside its tiles
    Index rest = row;
    for (int a = 1; a < D; ++a)
    {
      i[a] = rest % edge;
      rest /= edge;
      const Index g = start[a] + i[a];
      t[a] = floorTile(g);
      local |= (g - t[a] * TileEdge) << (TileBits * a);
      beyond = beyond || t[a] < 0 || t[a] >= this->SlotDims[a];
    }
    double* rowPhi = &phi(i);
    double* rowDist = dist ? &(*dist)(i) : nullptr;
    for (Index g = start[0]; g < start[0] + edge;)
    {
      // Nodes [g, end) of the row lie in tile t[0], from its node `from`.
      t[0] = floorTile(g);
      const Index from = g - t[0] * TileEdge;
      const Index end = std::min(start[0] + edge, (t[0] + 1) * TileEdge);
      const Index count = end - g;
      const Index x = g - start[0];
      const bool out = beyond || t[0] < 0 || t[0] >= this->SlotDims[0];
      const std::int32_t entry = out ? Outside : this->Slots[static_cast<size_t>(this->slotIndex(t))];
      if (entry >= 0)
      {
        std::copy_n(this->phi(entry) + local + from, count, rowPhi + x);
        if (rowDist)
        {
          std::copy_n(this->distance(entry) + local + from, count, rowDist + x);
        }
      }
      else
      {
        std::fill_n(rowPhi + x, count, entry == Inside ? -this->Gamma : this->Gamma);
        if (rowDist)
        {
          std::fill_n(rowDist + x, count, unknown);
        }
      }
      g = end;
    }
  }
  phi.fillGhosts();
  if (dist)
  {
    dist->fillGhosts();
  }
}

template class TiledField<2>;
template class TiledField<3>;

} // namespace sltk
