// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file BandReach.h (private)
/// Which neighbouring slots of the band tiles lie within `reach` nodes of a
/// band node (|phi| < gamma, 1.48): the slots the reinitialisation's dilated
/// band (1.53) can write and the distance stencils of the step and the energy
/// read (Documentation/Octree.md, "The tiled band").

#include "sltk/core/IndexBox.h"
#include "sltk/exec/Context.h"
#include "sltk/octree/TiledField.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace sltk
{

/// Bit of the neighbour direction v (each component -1, 0 or 1) among the 3^D.
template <int D>
int directionBit(const std::array<Index, D>& v)
{
  int bit = 0;
  for (int a = D - 1; a >= 0; --a)
  {
    bit = bit * 3 + static_cast<int>(v[a] + 1);
  }
  return bit;
}

/// Per band tile, the 3^D neighbour directions (bits of directionBit, the
/// tile's own included) that hold a node within `reach` nodes (each axis) of
/// one of its band nodes.
template <int D>
std::vector<std::uint32_t> bandReach(
  const TiledField<D>& field, const std::vector<std::int32_t>& band, Index reach, const Context& ctx)
{
  std::vector<std::uint32_t> bits(band.size(), 0);
  ctx.parallelFor(0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      for (Index j = b; j < e; ++j)
      {
        const double* p = field.phi(band[static_cast<size_t>(j)]);
        std::uint32_t reached = 0;
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          if (!(std::fabs(p[k]) < field.gamma()))
          {
            continue;
          }
          std::array<Index, D> lo{}, hi{};
          for (int a = 0; a < D; ++a)
          {
            const Index c = (k >> (TileBits * a)) & (TileEdge - 1);
            lo[a] = c < reach ? -1 : 0;
            hi[a] = c >= TileEdge - reach ? 1 : 0;
          }
          forEachIndexInBox<D>(lo, hi, [&](const std::array<Index, D>& v) { reached |= 1u << directionBit<D>(v); });
        }
        bits[static_cast<size_t>(j)] = reached;
      }
    });
  return bits;
}

/// Calls f(slot) for each slot (inside the slot grid) in a direction of
/// `reached` (bandReach) from band tile `id`.
template <int D, class F>
void forEachReachedSlot(const TiledField<D>& field, std::int32_t id, std::uint32_t reached, F&& f)
{
  std::array<Index, D> lo{}, hi{};
  lo.fill(-1);
  hi.fill(1);
  const auto& origin = field.tileOrigin(id);
  forEachIndexInBox<D>(lo, hi,
    [&](const std::array<Index, D>& v)
    {
      if (!(reached >> directionBit<D>(v) & 1u))
      {
        return;
      }
      std::array<Index, D> t = origin;
      for (int a = 0; a < D; ++a)
      {
        t[a] += v[a];
        if (t[a] < 0 || t[a] >= field.slotDims()[a])
        {
          return; // beyond the grid
        }
      }
      f(field.slotIndex(t));
    });
}

} // namespace sltk
