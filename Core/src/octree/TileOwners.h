// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TileOwners.h (private)
/// Which rank owns each slot of a TiledField when the band is distributed
/// (Documentation/Octree.md, "Distributing the tiled band"): p4est's rule for
/// a forest whose leaves are the tiles, consecutive runs of the Morton order
/// (z-order, the space-filling curve of p4est's partition) holding equal
/// numbers of tiles. The cuts fall only between blocks of BlockTiles^D slots,
/// the blocks the level-set step copies at once, so that no block is split
/// and every block computes what it computes on one rank.

#include "sltk/core/Index.h"
#include "sltk/core/MortonKey.h"
#include "sltk/octree/TiledField.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace sltk
{

/// The owner of every slot of `field`: ranks take consecutive runs of the
/// Morton order of blocks of `blockEdge`^D slots (a power of two), each run
/// holding about the same number of `weighted` slots (per slot, 0 or 1). With
/// no weighted slot, rank 0 owns everything.
template <int D>
std::vector<std::int32_t> mortonOwners(
  const TiledField<D>& field, const std::vector<std::uint8_t>& weighted, int ranks, Index blockEdge)
{
  int blockBits = 0;
  while ((Index(1) << blockBits) < blockEdge)
  {
    ++blockBits;
  }
  const auto blockKey = [&](Index s)
  {
    std::array<Index, D> t = field.slotCoordinates(s);
    for (int a = 0; a < D; ++a)
    {
      t[a] >>= blockBits;
    }
    return mortonKey<D>(t);
  };
  std::vector<std::uint64_t> keys; // the blocks of the weighted slots, one entry per slot
  for (Index s = 0; s < static_cast<Index>(weighted.size()); ++s)
  {
    if (weighted[static_cast<size_t>(s)])
    {
      keys.push_back(blockKey(s));
    }
  }
  std::sort(keys.begin(), keys.end());
  // Rank r starts at the block holding weighted slot r * W / P (rank 0 at key 0).
  const size_t total = keys.size();
  std::vector<std::uint64_t> starts(static_cast<size_t>(ranks), 0);
  for (int r = 1; r < ranks; ++r)
  {
    const size_t at = total * static_cast<size_t>(r) / static_cast<size_t>(ranks);
    starts[static_cast<size_t>(r)] = at < total ? keys[at] : UINT64_MAX;
    starts[static_cast<size_t>(r)] = std::max(starts[static_cast<size_t>(r)], starts[static_cast<size_t>(r) - 1]);
  }
  std::vector<std::int32_t> owners(weighted.size(), 0);
  for (Index s = 0; s < static_cast<Index>(owners.size()); ++s)
  {
    const std::uint64_t k = blockKey(s);
    owners[static_cast<size_t>(s)] =
      static_cast<std::int32_t>(std::upper_bound(starts.begin(), starts.end(), k) - starts.begin()) - 1;
  }
  return owners;
}

/// Per slot, its distance in slots (the largest of the axes' distances) to
/// the nearest slot `rank` owns, capped at `cap` (<= 254): 0 on its own slots.
template <int D>
std::vector<std::uint8_t> distanceToRank(
  const std::array<Index, D>& dims, const std::vector<std::int32_t>& owners, int rank, int cap)
{
  std::vector<std::uint8_t> d(owners.size());
  for (size_t s = 0; s < owners.size(); ++s)
  {
    d[s] = owners[s] == rank ? 0 : static_cast<std::uint8_t>(cap);
  }
  // The distance to a set under the largest-axis metric is separable: one
  // pass per axis of d(x) = min_k max(|k|, d(x + k e_a)).
  std::vector<std::uint8_t> line;
  Index stride = 1;
  for (int a = 0; a < D; ++a)
  {
    const Index n = dims[a];
    line.resize(static_cast<size_t>(n));
    for (Index first = 0; first < static_cast<Index>(d.size()); ++first)
    {
      if ((first / stride) % n != 0)
      {
        continue; // not a line's first slot
      }
      for (Index x = 0; x < n; ++x)
      {
        line[static_cast<size_t>(x)] = d[static_cast<size_t>(first + x * stride)];
      }
      for (Index x = 0; x < n; ++x)
      {
        std::uint8_t best = line[static_cast<size_t>(x)];
        for (Index k = 1; k < best && k <= cap; ++k)
        {
          const std::uint8_t kk = static_cast<std::uint8_t>(k);
          if (x - k >= 0)
          {
            best = std::min(best, std::max(kk, line[static_cast<size_t>(x - k)]));
          }
          if (x + k < n)
          {
            best = std::min(best, std::max(kk, line[static_cast<size_t>(x + k)]));
          }
        }
        d[static_cast<size_t>(first + x * stride)] = best;
      }
    }
    stride *= n;
  }
  return d;
}

} // namespace sltk
