// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/core/SortByKey.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

TEST(SortByKey, OrderedKeysFollowTheDoublesOrder)
{
  const double inf = std::numeric_limits<double>::infinity();
  const double values[] = { -inf, -1e300, -2.5, -1.0, -std::numeric_limits<double>::denorm_min(), -0.0, 0.0,
    std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(), 1e-300, 0.1, 1.0, 1.0 + 1e-15, 2.5,
    1e300, inf };
  const size_t n = sizeof(values) / sizeof(values[0]);
  for (size_t a = 0; a + 1 < n; ++a)
  {
    EXPECT_LT(sltk::orderedKey(values[a]), sltk::orderedKey(values[a + 1])) << values[a] << " < " << values[a + 1];
  }
  EXPECT_EQ(sltk::orderedKey(0.75), sltk::orderedKey(3.0 / 4.0));
  for (const double v : values)
  {
    const double back = sltk::fromOrderedKey(sltk::orderedKey(v));
    EXPECT_EQ(std::memcmp(&back, &v, sizeof v), 0) << v;
  }
}

TEST(SortByKey, SortsAsStdStableSortDoesItemsInIncreasingOrder)
{
  std::mt19937_64 random(11);
  for (const size_t n : { size_t(0), size_t(1), size_t(2), size_t(17), size_t(5000), size_t(200000) })
  {
    for (const int spread : { 0, 3, 1000, 64 })
    {
      // Keys of doubles with many ties (spread 3: three values), all equal
      // (spread 0), or over the whole range of exponents (spread 64).
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      std::vector<std::uint64_t> keys(n);
      std::vector<std::uint32_t> items(n);
      for (size_t k = 0; k < n; ++k)
      {
        const double d = spread == 0 ? 1.5
          : spread == 64             ? std::ldexp(unit(random) - 0.5, static_cast<int>(random() % 200) - 100)
                                     : std::floor(unit(random) * spread) * 0.37;
        keys[k] = sltk::orderedKey(d);
        items[k] = static_cast<std::uint32_t>(k);
      }
      std::vector<std::uint32_t> expected = items;
      std::stable_sort(
        expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
      const std::vector<std::uint64_t> unsorted = keys;
      sltk::sortByKey(keys, items);
      ASSERT_EQ(items.size(), expected.size());
      size_t differing = 0;
      for (size_t k = 0; k < n; ++k)
      {
        differing += items[k] != expected[k] || keys[k] != unsorted[expected[k]] ? 1 : 0;
      }
      EXPECT_EQ(differing, 0u) << n << " items, spread " << spread;
    }
  }
}

TEST(SortByKey, EqualKeysGoByTheirItems)
{
  // Items dealt in no order: the pairs come out in (key, item) order.
  std::mt19937_64 random(5);
  const size_t n = 50000;
  std::vector<std::uint64_t> keys(n);
  std::vector<std::int64_t> items(n);
  std::vector<std::pair<std::uint64_t, std::int64_t>> expected(n);
  for (size_t k = 0; k < n; ++k)
  {
    keys[k] = sltk::orderedKey(static_cast<double>(random() % 97) - 40.0);
    items[k] = static_cast<std::int64_t>(random() % 100000) - 50000;
    expected[k] = { keys[k], items[k] };
  }
  std::sort(expected.begin(), expected.end());
  sltk::sortByKey(keys, items);
  size_t differing = 0;
  for (size_t k = 0; k < n; ++k)
  {
    differing += keys[k] != expected[k].first || items[k] != expected[k].second ? 1 : 0;
  }
  EXPECT_EQ(differing, 0u);
}
