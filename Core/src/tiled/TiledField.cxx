// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/tiled/TiledField.h"

#include <algorithm>

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
  this->Phi.clear();
  this->Dist.clear();
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
  this->Phi.resize(this->Phi.size() + static_cast<size_t>(Nodes), fill);
  this->Dist.resize(this->Dist.size() + static_cast<size_t>(Nodes), 0.0);
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
    return this->Phi[static_cast<size_t>(entry) * Nodes + static_cast<size_t>(local)];
  }
  return entry == Inside ? -this->Gamma : this->Gamma;
}

template <int D>
bool TiledField<D>::surrounded(std::int32_t id) const
{
  const std::array<Index, D>& o = this->Origins[static_cast<size_t>(id)];
  constexpr int Neighbours = D == 2 ? 9 : 27;
  for (int n = 0; n < Neighbours; ++n)
  {
    std::array<Index, D> t{};
    bool beyond = false;
    int rest = n;
    for (int a = 0; a < D; ++a)
    {
      t[a] = o[a] + (rest % 3) - 1;
      rest /= 3;
      beyond = beyond || t[a] < 0 || t[a] >= this->SlotDims[a];
    }
    if (!beyond && this->Slots[static_cast<size_t>(this->slotIndex(t))] < 0)
    {
      return false;
    }
  }
  return true;
}

template <int D>
void TiledField<D>::scratch(std::int32_t id, int halo, int ghost, GridField<D>& phi, GridField<D>* dist) const
{
  const std::array<Index, D>& o = this->Origins[static_cast<size_t>(id)];
  const Index h = halo;
  const Index edge = TileEdge + 2 * h;
  GridSpec<D> block = this->Grid;
  for (int a = 0; a < D; ++a)
  {
    block.Dims[a] = edge;
    block.Origin[a] = this->Grid.coordinate(a, o[a] * TileEdge - h);
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
  // Row by row along x: each row crosses at most three tiles.
  Index rows = 1;
  for (int a = 1; a < D; ++a)
  {
    rows *= edge;
  }
  for (Index row = 0; row < rows; ++row)
  {
    std::array<Index, D> i{}; // block index of the row's first node
    std::array<Index, D> t = o;
    std::array<Index, D> inTile{};
    bool beyond = false;
    Index rest = row;
    for (int a = 1; a < D; ++a)
    {
      i[a] = rest % edge;
      rest /= edge;
      const Index g = o[a] * TileEdge - h + i[a]; // grid index
      const Index tile = g >= 0 ? g / TileEdge : -((TileEdge - 1 - g) / TileEdge); // floor(g / TileEdge)
      t[a] = tile;
      inTile[a] = g - tile * TileEdge;
      beyond = beyond || tile < 0 || tile >= this->SlotDims[a];
    }
    double* rowPhi = &phi(i);
    double* rowDist = dist ? &(*dist)(i) : nullptr;
    Index x = 0;
    const Index reach = (h + TileEdge - 1) / TileEdge; // tiles on each side along x
    for (Index part = -reach; part <= reach; ++part)
    {
      // Nodes [first, last) of tile o[0] + part, in grid indices relative to the tile's first node.
      const Index first = std::max<Index>(-h - part * TileEdge, 0);
      const Index last = std::min<Index>(TileEdge + h - part * TileEdge, TileEdge);
      if (first >= last)
      {
        continue;
      }
      t[0] = o[0] + part;
      const bool out = beyond || t[0] < 0 || t[0] >= this->SlotDims[0];
      const std::int32_t entry = out ? Outside : this->Slots[static_cast<size_t>(this->slotIndex(t))];
      Index local = 0;
      for (int a = 1; a < D; ++a)
      {
        local |= inTile[a] << (TileBits * a);
      }
      if (entry >= 0)
      {
        const double* p = this->phi(entry) + local;
        const double* q = this->distance(entry) + local;
        for (Index k = first; k < last; ++k, ++x)
        {
          rowPhi[x] = p[k];
          if (rowDist)
          {
            rowDist[x] = q[k];
          }
        }
      }
      else
      {
        const double fill = entry == Inside ? -this->Gamma : this->Gamma;
        for (Index k = first; k < last; ++k, ++x)
        {
          rowPhi[x] = fill;
          if (rowDist)
          {
            rowDist[x] = 0.0;
          }
        }
      }
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
