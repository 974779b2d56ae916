// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/ExactDistanceCache.h"

#include <algorithm>

namespace sltk
{

template <int D>
Index ExactDistanceCache<D>::ensure(const NodeList& band, const Context& ctx, GridField<D>& dist)
{
  // Stencil of a band node: the corners {0,1}^D of its cell and its face neighbours -e_a.
  std::array<Index, (1 << D) + D> stencil{};
  std::array<std::array<Index, D>, (1 << D) + D> shift{};
  int n = 0;
  for (int c = 0; c < (1 << D); ++c)
  {
    for (int a = 0; a < D; ++a)
    {
      shift[n][a] = (c >> a) & 1;
    }
    ++n;
  }
  for (int a = 0; a < D; ++a)
  {
    shift[n][a] = -1;
    ++n;
  }
  for (int s = 0; s < n; ++s)
  {
    stencil[s] = dist.offset(shift[s]) - dist.offset({});
  }
  const auto& spec = dist.spec();
  // Both threads mark: a slot's flag is claimed by one atomic exchange, so each
  // slot is computed once, by the chunk that claimed it first (which one does
  // not change its value, nor the count).
  const Index size = static_cast<Index>(band.size());
  const Index grain = std::max<Index>(1024, (size + 63) / 64);
  const Index chunks = (size + grain - 1) / grain;
  std::vector<std::vector<Index>> pending(static_cast<size_t>(chunks));
  ctx.parallelFor(
    0, size,
    [&](Index b, Index e)
    {
      std::vector<Index>& mine = pending[static_cast<size_t>(b / grain)];
      for (Index p = b; p < e; ++p)
      {
        const Index base = dist.offset(dist.nodeIndex(band[static_cast<size_t>(p)]));
        for (int s = 0; s < n; ++s)
        {
          const Index slot = base + stencil[s];
          std::atomic<std::uint8_t>& exact = this->Exact[slot];
          if (exact.load(std::memory_order_relaxed) == 0 && exact.exchange(1, std::memory_order_relaxed) == 0)
          {
            mine.push_back(slot);
          }
        }
      }
    },
    grain);
  // Storage offset -> multi-index (ghosts included) for the coordinates.
  std::array<Index, D> padded{};
  for (int a = 0; a < D; ++a)
  {
    padded[a] = spec.Dims[a] + 2 * dist.ghost();
  }
  double* values = dist.storage().data();
  ctx.parallelFor(
    0, chunks,
    [&](Index b, Index e)
    {
      for (Index c = b; c < e; ++c)
      {
        for (const Index slot : pending[static_cast<size_t>(c)])
        {
          Index rest = slot;
          std::array<double, D> x;
          for (int a = 0; a < D; ++a)
          {
            x[a] = spec.coordinate(a, rest % padded[a] - dist.ghost());
            rest /= padded[a];
          }
          values[slot] = this->Locator->nearest(x).Distance;
        }
      }
    },
    1);
  Index computed = 0;
  for (const std::vector<Index>& mine : pending)
  {
    computed += static_cast<Index>(mine.size());
  }
  return computed;
}

template class ExactDistanceCache<2>;
template class ExactDistanceCache<3>;

} // namespace sltk
