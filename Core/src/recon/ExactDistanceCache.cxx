// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/ExactDistanceCache.h"

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
  this->Pending.clear();
  for (Index k : band) // serial: cheap mask tests, ascending order keeps it deterministic
  {
    const Index base = dist.offset(dist.nodeIndex(k));
    for (int s = 0; s < n; ++s)
    {
      const Index slot = base + stencil[s];
      if (!this->Exact[static_cast<size_t>(slot)])
      {
        this->Exact[static_cast<size_t>(slot)] = 1;
        this->Pending.push_back(slot);
      }
    }
  }
  // Storage offset -> multi-index (ghosts included) for the coordinates.
  std::array<Index, D> padded{};
  for (int a = 0; a < D; ++a)
  {
    padded[a] = spec.Dims[a] + 2 * dist.ghost();
  }
  double* values = dist.storage().data();
  ctx.parallelFor(0, static_cast<Index>(this->Pending.size()), [&](Index b, Index e) {
    for (Index p = b; p < e; ++p)
    {
      Index rest = this->Pending[static_cast<size_t>(p)];
      std::array<double, D> x;
      for (int a = 0; a < D; ++a)
      {
        x[a] = spec.coordinate(a, rest % padded[a] - dist.ghost());
        rest /= padded[a];
      }
      values[this->Pending[static_cast<size_t>(p)]] = this->Locator->nearest(x).Distance;
    }
  });
  return static_cast<Index>(this->Pending.size());
}

template class ExactDistanceCache<2>;
template class ExactDistanceCache<3>;

} // namespace sltk
