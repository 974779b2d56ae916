// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file LeafTable.h
/// The leaves of a tree by level and integer position (open addressing):
/// what the cell-centred scheme's neighbour lists and point location look
/// up. A leaf of level l at integer index (i_1, ..., i_D), i_a < 2^l, is the
/// key l + 32 (i_1 + 2^B i_2 + ...), B = 27 bits per axis in 2D and 16 in 3D
/// (the deepest levels the trees allow).

#include <array>
#include <cstdint>
#include <vector>

namespace sltk
{
namespace p4est
{

template <int D>
class LeafTable
{
public:
  static constexpr int IndexBits = D == 2 ? 27 : 16;
  static constexpr int DeepestLevel = IndexBits;
  using Index = std::array<std::uint32_t, D>;

  static std::uint64_t key(int level, const Index& at)
  {
    std::uint64_t k = static_cast<std::uint64_t>(level);
    for (int a = 0; a < D; ++a)
    {
      k |= static_cast<std::uint64_t>(at[a]) << (5 + a * IndexBits);
    }
    return k;
  }

  /// Room for `leaves` leaves, empty.
  void reset(std::size_t leaves)
  {
    std::size_t size = 16;
    while (size < 2 * leaves)
    {
      size *= 2;
    }
    this->Keys.assign(size, Empty);
    this->Values.assign(size, -1);
    this->Mask = size - 1;
    this->Deepest = 0;
  }

  void insert(int level, const Index& at, int leaf)
  {
    const std::uint64_t k = key(level, at);
    std::size_t slot = hash(k) & this->Mask;
    while (this->Keys[slot] != Empty)
    {
      slot = (slot + 1) & this->Mask;
    }
    this->Keys[slot] = k;
    this->Values[slot] = leaf;
    this->Deepest = level > this->Deepest ? level : this->Deepest;
  }

  /// The leaf at that level and index, or -1.
  int find(int level, const Index& at) const
  {
    const std::uint64_t k = key(level, at);
    for (std::size_t slot = hash(k) & this->Mask;; slot = (slot + 1) & this->Mask)
    {
      if (this->Keys[slot] == k)
      {
        return this->Values[slot];
      }
      if (this->Keys[slot] == Empty)
      {
        return -1;
      }
    }
  }

  /// The leaf holding the point t of the reference cube [0, 1]^D (clamped
  /// there; half-open cells, the cube's far side closed), or -1 for an empty table.
  int locate(const std::array<double, D>& t) const
  {
    for (int level = this->Deepest; level >= 0; --level)
    {
      const double cells = static_cast<double>(std::uint64_t(1) << level);
      Index at;
      for (int a = 0; a < D; ++a)
      {
        const double c = t[a] <= 0.0 ? 0.0 : t[a] * cells;
        at[a] = c >= cells ? static_cast<std::uint32_t>(cells - 1.0) : static_cast<std::uint32_t>(c);
      }
      const int leaf = this->find(level, at);
      if (leaf >= 0)
      {
        return leaf;
      }
    }
    return -1;
  }

private:
  static constexpr std::uint64_t Empty = ~std::uint64_t(0);

  static std::size_t hash(std::uint64_t k)
  {
    k ^= k >> 33; // MurmurHash3's finaliser
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    k *= 0xc4ceb9fe1a85ec53ULL;
    k ^= k >> 33;
    return static_cast<std::size_t>(k);
  }

  std::vector<std::uint64_t> Keys;
  std::vector<int> Values;
  std::size_t Mask = 0;
  int Deepest = 0;
};

} // namespace p4est
} // namespace sltk
