// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PruneTiles.h (private)
/// Frees the tiles the band has left (Documentation/Octree.md, "The tiled
/// band"): a tile that holds no band node (|phi| < gamma, 1.48), lies beyond
/// the reach of every band node (BandReach.h: the reinitialisation's dilation
/// (1.53) and the distance stencils) and holds +gamma or -gamma at every node
/// says no more than its slot does, so its slot takes that side again. Where
/// the band comes back, extendBand allocates it again at the same +-gamma and
/// TiledDistances computes its d again where it is read: the iterations are
/// unchanged.

#include "BandReach.h"

#include "sltk/exec/Context.h"
#include "sltk/octree/TiledField.h"

#include <cstdint>
#include <vector>

namespace sltk
{

/// -1 or +1 when the `count` values `p` are all -gamma or all +gamma (a slot
/// side holds them exactly), else 0.
inline int oneSideOf(const double* p, Index count, double gamma)
{
  const double side = p[0] < 0.0 ? -gamma : gamma;
  for (Index k = 0; k < count; ++k)
  {
    if (p[k] != side)
    {
      return 0;
    }
  }
  return side < 0.0 ? -1 : 1;
}

/// The tiles of `field` to free: not in `band`, not in a slot `reached` from
/// a band tile, at one +-gamma throughout, and `mayFree(id)` (distributed: a
/// rank frees only its own tiles, TileDistribution.h).
template <int D, class MayFree>
std::vector<std::uint8_t> tilesLeftBehind(const TiledField<D>& field, const std::vector<std::int32_t>& band,
  const std::vector<std::uint32_t>& reached, const Context& ctx, MayFree&& mayFree)
{
  std::vector<std::uint8_t> needed(static_cast<size_t>(field.tileCount()), 0);
  for (size_t j = 0; j < band.size(); ++j)
  {
    needed[static_cast<size_t>(band[j])] = 1;
    forEachReachedSlot(field, band[j], reached[j],
      [&](Index s)
      {
        const std::int32_t id = field.slot(s);
        if (id >= 0)
        {
          needed[static_cast<size_t>(id)] = 1;
        }
      });
  }
  std::vector<std::uint8_t> left(needed.size(), 0);
  ctx.parallelFor(0, field.tileCount(),
    [&](Index b, Index e)
    {
      for (Index id = b; id < e; ++id)
      {
        if (needed[static_cast<size_t>(id)] || !mayFree(static_cast<std::int32_t>(id)))
        {
          continue;
        }
        const double* p = field.phi(static_cast<std::int32_t>(id));
        left[static_cast<size_t>(id)] = oneSideOf(p, TiledField<D>::Nodes, field.gamma()) != 0 ? 1 : 0;
      }
    });
  return left;
}

/// Frees tilesLeftBehind(); `band` (kept tiles) is renumbered and `forget(left)`
/// is called so that per-tile state elsewhere follows. The freed tiles' slots
/// are appended to `freedSlots`. Returns the tiles freed.
template <int D, class MayFree, class Forget>
Index pruneTiles(TiledField<D>& field, std::vector<std::int32_t>& band, const std::vector<std::uint32_t>& reached,
  const Context& ctx, MayFree&& mayFree, Forget&& forget, std::vector<Index>& freedSlots)
{
  const std::vector<std::uint8_t> left = tilesLeftBehind(field, band, reached, ctx, mayFree);
  std::vector<std::int32_t> newId(left.size(), -1);
  std::int32_t kept = 0;
  for (size_t id = 0; id < left.size(); ++id)
  {
    if (!left[id])
    {
      newId[id] = kept++;
    }
  }
  const Index freed = static_cast<Index>(left.size()) - kept;
  if (freed == 0)
  {
    return 0;
  }
  field.forEachTileInSlotOrder(
    [&](std::int32_t id)
    {
      if (left[static_cast<size_t>(id)])
      {
        freedSlots.push_back(field.tileSlot(id));
      }
    });
  field.removeTiles(left);
  for (std::int32_t& id : band)
  {
    id = newId[static_cast<size_t>(id)];
  }
  forget(left);
  return freed;
}

} // namespace sltk
