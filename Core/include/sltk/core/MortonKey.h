// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file MortonKey.h
/// The Morton (z-order) key of integer coordinates, the space-filling curve
/// of p4est's partition: the distributed tiled band's owners
/// (Core/src/octree/TileOwners.h) and sltkBenchTiled's partition profile.

#include "sltk/core/Index.h"

#include <array>
#include <cstdint>

namespace sltk
{

/// Bit b of t[a] at bit D * b + a (coordinates of up to 64 / D bits).
template <int D>
std::uint64_t mortonKey(const std::array<Index, D>& t)
{
  constexpr int Bits = 64 / D;
  std::uint64_t key = 0;
  for (int b = 0; b < Bits; ++b)
  {
    for (int a = 0; a < D; ++a)
    {
      key |= ((static_cast<std::uint64_t>(t[a]) >> b) & 1u) << (D * b + a);
    }
  }
  return key;
}

} // namespace sltk
