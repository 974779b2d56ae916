// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/octree/TiledMemory.h"

#include "sltk/core/IndexBox.h"
#include "sltk/octree/TiledField.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sltk
{

template <int D>
double estimatedTiledNodes(const PointCloud<D>& cloud, const GridSpec<D>& finest)
{
  std::array<Index, D> slots{};
  Index count = 1;
  for (int a = 0; a < D; ++a)
  {
    slots[a] = (finest.Dims[a] + TileEdge - 1) / TileEdge;
    count *= slots[a];
  }
  std::vector<std::uint8_t> marked(static_cast<size_t>(count), 0);
  for (const auto& q : cloud.Points)
  {
    std::array<Index, D> lo{}, hi{};
    for (int a = 0; a < D; ++a)
    {
      const Index t = static_cast<Index>(std::floor((q[a] - finest.Origin[a]) / finest.Spacing[a])) >> TileBits;
      lo[a] = std::max<Index>(t - 1, 0);
      hi[a] = std::min<Index>(t + 1, slots[a] - 1);
    }
    forEachIndexInBox<D>(lo, hi,
      [&](const std::array<Index, D>& t)
      {
        Index s = 0;
        for (int a = D - 1; a >= 0; --a)
        {
          s = s * slots[a] + t[a];
        }
        marked[static_cast<size_t>(s)] = 1;
      });
  }
  return static_cast<double>(std::count(marked.begin(), marked.end(), std::uint8_t(1))) *
    static_cast<double>(tileNodes<D>());
}

template double estimatedTiledNodes(const PointCloud<2>&, const GridSpec<2>&);
template double estimatedTiledNodes(const PointCloud<3>&, const GridSpec<3>&);

} // namespace sltk
