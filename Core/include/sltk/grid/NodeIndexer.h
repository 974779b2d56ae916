// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file NodeIndexer.h
/// The multi-index of a grid node from its linear index (x fastest), without
/// a hardware division per axis. The band bookkeeping converts every band node
/// of every iteration this way (the narrow band's lists hold linear indices,
/// the storage has ghost layers), and a 64-bit division costs tens of cycles:
/// before this class the divisions were the largest cost of collecting,
/// filtering, cutting and dilating the band (Documentation/Profile.md).
///
/// The quotient by a divisor fixed in advance is one 128-bit multiplication
/// (Lemire, Kaser and Kurz, "Faster remainder by direct computation", 2019):
/// with c = ceil(2^64 / d), floor(c k / 2^64) = floor(k / d) for every
/// 0 <= k < 2^32 and 0 < d < 2^32. Other k (grids of 2^32 nodes and more)
/// take the division, so the results are those of / and % for every k.

#include "sltk/core/Index.h"

#include <array>
#include <cstdint>

namespace sltk
{

/// k / d and k % d for one d > 0 chosen at construction.
class InvariantDivisor
{
public:
  InvariantDivisor() = default;
  explicit InvariantDivisor(Index divisor)
    : Divisor(divisor > 0 ? divisor : 1)
    , Magic(this->Divisor > 1 && static_cast<std::uint64_t>(this->Divisor) <= Largest
          ? UINT64_MAX / static_cast<std::uint64_t>(this->Divisor) + 1
          : 0)
  {
  }

  /// quotient = k / d, remainder = k % d (C++ semantics for every k).
  void divide(Index k, Index& quotient, Index& remainder) const
  {
    if (this->Magic != 0 && static_cast<std::uint64_t>(k) <= Largest)
    {
      __extension__ using Wide = unsigned __int128;
      quotient = static_cast<Index>((static_cast<Wide>(this->Magic) * static_cast<std::uint64_t>(k)) >> 64);
    }
    else
    {
      quotient = k / this->Divisor; // d = 1, k outside [0, 2^32), or d >= 2^32
    }
    remainder = k - quotient * this->Divisor;
  }

private:
  static constexpr std::uint64_t Largest = 0xFFFFFFFFu; // 2^32 - 1: the bound of the theorem above
  Index Divisor = 1;
  std::uint64_t Magic = 0; // ceil(2^64 / d); 0: divide
};

/// Linear node index <-> multi-index of a grid of Dims nodes per axis.
template <int D>
class NodeIndexer
{
public:
  NodeIndexer() = default;
  explicit NodeIndexer(const std::array<Index, D>& dims)
  {
    for (int a = 0; a < D; ++a)
    {
      this->Axis[a] = InvariantDivisor(dims[a]);
    }
  }

  /// i[a] = (k / (N_0 ... N_{a-1})) % N_a, as the loop of % and / gives it.
  std::array<Index, D> operator()(Index k) const
  {
    std::array<Index, D> i{};
    for (int a = 0; a < D; ++a)
    {
      Index quotient = 0;
      this->Axis[a].divide(k, quotient, i[a]);
      k = quotient;
    }
    return i;
  }

private:
  std::array<InvariantDivisor, D> Axis{};
};

} // namespace sltk
