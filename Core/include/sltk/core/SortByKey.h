// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Items sorted by a 64-bit key (and by themselves among equal keys), and the
// key whose unsigned order is a double's order. The automatic K_P's probe sorts
// the nodes of a grid of up to 4M nodes by their distance twice (LocalOffset.cxx,
// CloudInitialData.cxx): std::sort's comparisons took 0.4-0.6 s there
// (Documentation/Profile.md, "The automatic K_P's probe: sorts by buckets").

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sltk
{

/// The key of v whose unsigned order is the order of the doubles: negative
/// values (their bits complemented) below positive ones (their sign bit set),
/// -0 just below +0. Equal doubles other than the two zeros have equal keys.
/// NaN has no place in that order: callers leave it out.
inline std::uint64_t orderedKey(double v)
{
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  constexpr std::uint64_t sign = std::uint64_t(1) << 63;
  return (bits & sign) != 0 ? ~bits : bits | sign;
}

/// The double whose orderedKey() is `key`, bit for bit.
inline double fromOrderedKey(std::uint64_t key)
{
  constexpr std::uint64_t sign = std::uint64_t(1) << 63;
  const std::uint64_t bits = (key & sign) != 0 ? key & ~sign : ~key;
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

/// Sorts `keys` increasing and `items` (one a key) with them; equal keys by
/// increasing item, so the result is the one order of the (key, item) pairs
/// whatever their first order. A bucket sort: one pass deals the pairs into
/// about n / 32 buckets of equal key ranges between the smallest key and the
/// largest, then each bucket (cache-sized when the keys spread evenly; a few
/// outlying keys put most in a few buckets, and the sort slows towards
/// std::sort's) is sorted. Uses about 16 bytes an item more while it runs.
/// `items` must hold one item a key.
template <class Item>
void sortByKey(std::vector<std::uint64_t>& keys, std::vector<Item>& items)
{
  const std::size_t n = keys.size();
  assert(items.size() == n);
  if (n < 2)
  {
    return;
  }
  const auto range = std::minmax_element(keys.begin(), keys.end());
  const std::uint64_t lowest = *range.first, span = *range.second - *range.first;
  const std::uint64_t wanted = std::max<std::uint64_t>(1, n / 32);
  int shift = 0;
  while (shift < 63 && (span >> shift) >= wanted)
  {
    ++shift;
  }
  const std::size_t buckets = static_cast<std::size_t>(span >> shift) + 1;
  std::vector<std::size_t> start(buckets + 1, 0);
  for (const std::uint64_t key : keys)
  {
    ++start[((key - lowest) >> shift) + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b)
  {
    start[b + 1] += start[b];
  }
  struct Pair
  {
    std::uint64_t Key;
    Item Value;
    bool operator<(const Pair& o) const { return this->Key < o.Key || (this->Key == o.Key && this->Value < o.Value); }
  };
  std::vector<Pair> dealt(n);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < n; ++k)
    {
      dealt[next[(keys[k] - lowest) >> shift]++] = { keys[k], items[k] };
    }
  }
  for (std::size_t b = 0; b < buckets; ++b)
  {
    std::sort(
      dealt.begin() + static_cast<std::ptrdiff_t>(start[b]), dealt.begin() + static_cast<std::ptrdiff_t>(start[b + 1]));
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    keys[k] = dealt[k].Key;
    items[k] = dealt[k].Value;
  }
}

} // namespace sltk
