// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/octree/TiledField.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

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
  ++this->Generation;
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
  ++this->Generation;
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
void TiledField<D>::removeTiles(const std::vector<std::uint8_t>& remove)
{
  std::int32_t kept = 0;
  ++this->Generation;
  for (std::int32_t id = 0; id < this->tileCount(); ++id)
  {
    const Index s = this->SlotOf[static_cast<size_t>(id)];
    if (remove[static_cast<size_t>(id)])
    {
      this->Slots[static_cast<size_t>(s)] =
        remove[static_cast<size_t>(id)] == RemoveToRemote ? Remote : (this->phi(id)[0] < 0.0 ? Inside : Outside);
      continue;
    }
    if (kept != id)
    {
      std::copy_n(this->phi(id), Nodes, this->phi(kept));
      std::copy_n(this->distance(id), Nodes, this->distance(kept));
      this->Origins[static_cast<size_t>(kept)] = this->Origins[static_cast<size_t>(id)];
      this->SlotOf[static_cast<size_t>(kept)] = s;
      this->Slots[static_cast<size_t>(s)] = kept;
    }
    ++kept;
  }
  this->Origins.resize(static_cast<size_t>(kept));
  this->SlotOf.resize(static_cast<size_t>(kept));
  this->Chunks.resize(static_cast<size_t>((kept + ChunkTiles - 1) / ChunkTiles)); // the emptied chunks freed
}

namespace
{
/// A tile row's `count` (<= TileEdge) values without a library call: a whole
/// row (most of them) as one fixed-size copy, a part of one (the halo's) value
/// by value.
inline void copyRow(const double* from, Index count, double* to)
{
  if (count == TileEdge)
  {
    std::memcpy(to, from, TileEdge * sizeof(double)); // inlined: a fixed size, no overlap
    return;
  }
  for (Index k = 0; k < TileEdge; ++k)
  {
    if (k < count)
    {
      to[k] = from[k];
    }
  }
}
} // namespace

template <int D>
void TiledField<D>::scratchBlock(const std::array<Index, D>& first, Index tiles, int halo, int ghost, GridField<D>& phi,
  GridField<D>* dist, int distHalo) const
{
  const Index h = halo;
  const Index edge = tiles * TileEdge + 2 * h;
  // d's nodes along every axis: [distFrom, distTo) of the block's copy.
  const Index distFrom = distHalo >= 0 && distHalo < halo ? h - distHalo : 0;
  const Index distTo = edge - distFrom;
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
      f.reshape(block, ghost); // every value read is written below (see the header)
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
  // A row along x crosses the same tile columns in every row: its segments
  // (nodes [x, x + count) from node `from` of tile column t) once.
  struct Segment
  {
    Index Column, From, Count, X;
  };
  // A row crosses at most edge / TileEdge + 2 tile columns: on the stack for the
  // blocks the solver copies, on the heap for wider ones.
  std::array<Segment, MaxScratchSegments> stackSegments{};
  std::array<std::int32_t, MaxScratchSegments> stackEntries{};
  std::vector<Segment> heapSegments;
  std::vector<std::int32_t> heapEntries;
  Segment* segments = stackSegments.data();
  std::int32_t* entries = stackEntries.data();
  const size_t columns = static_cast<size_t>(edge / TileEdge + 2);
  if (columns > static_cast<size_t>(MaxScratchSegments))
  {
    heapSegments.resize(columns);
    heapEntries.resize(columns);
    segments = heapSegments.data();
    entries = heapEntries.data();
  }
  int segmentCount = 0;
  for (Index g = start[0]; g < start[0] + edge; ++segmentCount)
  {
    const Index t = floorTile(g);
    const Index end = std::min(start[0] + edge, (t + 1) * TileEdge);
    segments[static_cast<size_t>(segmentCount)] = { t, g - t * TileEdge, end - g, g - start[0] };
    g = end;
  }
  // Row by row along x, tile by tile along the row; the rows of one row of
  // tiles share their tiles' entries.
  Index rows = 1;
  for (int a = 1; a < D; ++a)
  {
    rows *= edge;
  }
  Index lastBase = -2;
  std::array<Index, D> i{}; // block index of the row's first node, counted like an odometer
  for (Index row = 0; row < rows; ++row)
  {
    if (row > 0)
    {
      for (int a = 1; a < D && ++i[a] == edge; ++a)
      {
        i[a] = 0;
      }
    }
    bool beyond = false;
    Index local = 0; // the row's node offset inside its tiles
    Index base = 0;  // slotIndex of the row's tiles with t[0] = 0
    Index stride = 1;
    bool distRow = dist != nullptr;
    for (int a = 1; a < D; ++a)
    {
      distRow = distRow && i[a] >= distFrom && i[a] < distTo;
      const Index g = start[a] + i[a];
      const Index t = floorTile(g);
      local |= (g - t * TileEdge) << (TileBits * a);
      beyond = beyond || t < 0 || t >= this->SlotDims[a];
      stride *= this->SlotDims[a - 1];
      base += t * stride;
    }
    if (beyond)
    {
      base = -1;
    }
    if (base != lastBase)
    {
      for (int k = 0; k < segmentCount; ++k)
      {
        const Index t = segments[static_cast<size_t>(k)].Column;
        entries[static_cast<size_t>(k)] =
          beyond || t < 0 || t >= this->SlotDims[0] ? Outside : this->Slots[static_cast<size_t>(base + t)];
      }
      lastBase = base;
    }
    double* rowPhi = &phi(i);
    double* rowDist = distRow ? &(*dist)(i) : nullptr;
    for (int k = 0; k < segmentCount; ++k)
    {
      const Segment& seg = segments[static_cast<size_t>(k)];
      const std::int32_t entry = entries[static_cast<size_t>(k)];
      // The segment's part within d's nodes: [x0, x1) of the row.
      const Index x0 = std::max(seg.X, distFrom), x1 = std::min(seg.X + seg.Count, distTo);
      if (entry >= 0)
      {
        copyRow(this->phi(entry) + local + seg.From, seg.Count, rowPhi + seg.X);
        if (rowDist && x1 > x0)
        {
          copyRow(this->distance(entry) + local + seg.From + (x0 - seg.X), x1 - x0, rowDist + x0);
        }
      }
      else
      {
        std::fill_n(
          rowPhi + seg.X, seg.Count, entry == Remote ? unknown : (entry == Inside ? -this->Gamma : this->Gamma));
        if (rowDist && x1 > x0)
        {
          std::fill_n(rowDist + x0, x1 - x0, unknown);
        }
      }
    }
  }
  phi.fillGhosts();
  if (dist && distFrom == 0) // a d copied near the block only is read there only
  {
    dist->fillGhosts();
  }
}

template <int D>
bool TiledField<D>::flatCell(std::int32_t id, const std::array<Index, D>& first, Index size) const
{
  const std::array<Index, D>& origin = this->tileOrigin(id);
  Index count = 1;
  for (int a = 0; a < D; ++a)
  {
    if (origin[a] * TileEdge + first[a] + size > this->Grid.Dims[a])
    {
      return false; // a node beyond the grid
    }
    count *= size;
  }
  // Row by row along x (contiguous in the tile), the rows' offsets counted like an odometer.
  Index base = 0;
  for (int a = 0; a < D; ++a)
  {
    base |= first[a] << (TileBits * a);
  }
  const double* p = this->phi(id);
  const double side = p[base];
  if (std::fabs(side) != this->Gamma)
  {
    return false;
  }
  std::array<Index, D> at{}; // the row's position along y (and z) within the cell
  for (Index row = 0; row < count / size; ++row)
  {
    Index offset = base;
    for (int a = 1; a < D; ++a)
    {
      offset += at[a] << (TileBits * a);
    }
    for (Index x = 0; x < size; ++x)
    {
      if (p[offset + x] != side)
      {
        return false;
      }
    }
    for (int a = 1; a < D && ++at[a] == size; ++a)
    {
      at[a] = 0;
    }
  }
  return true;
}

namespace
{
/// Leaves below (and with) the cell of tile `id` at `first` covering `size` nodes per axis.
template <int D>
Index cellLeaves(const TiledField<D>& field, std::int32_t id, const std::array<Index, D>& first, Index size)
{
  if (!field.nodeInGrid(id, first))
  {
    return 0; // masked in the output
  }
  if (size == 1 || field.flatCell(id, first, size))
  {
    return 1;
  }
  Index leaves = 0;
  for (int child = 0; child < (1 << D); ++child)
  {
    std::array<Index, D> corner = first;
    for (int a = 0; a < D; ++a)
    {
      corner[a] += ((child >> a) & 1) ? size / 2 : 0;
    }
    leaves += cellLeaves<D>(field, id, corner, size / 2);
  }
  return leaves;
}
} // namespace

template <int D>
Index TiledField<D>::leafCount(std::int32_t id) const
{
  return cellLeaves<D>(*this, id, std::array<Index, D>{}, TileEdge);
}

template class TiledField<2>;
template class TiledField<3>;

} // namespace sltk
