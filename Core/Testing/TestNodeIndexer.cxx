// SPDX-License-Identifier: BSD-3-Clause
// InvariantDivisor and NodeIndexer give exactly what / and % give: for
// divisors from 1 to beyond 2^32, numerators on both sides of the 2^32 bound
// of the multiplication, negative ones, and every node of small grids.
#include "sltk/grid/GridField.h"
#include "sltk/grid/NodeIndexer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace
{
void expectDivision(sltk::Index d, sltk::Index k)
{
  const sltk::InvariantDivisor divisor(d);
  sltk::Index q = -1;
  sltk::Index r = -1;
  divisor.divide(k, q, r);
  EXPECT_EQ(q, k / d) << k << " / " << d;
  EXPECT_EQ(r, k % d) << k << " % " << d;
}
} // namespace

TEST(NodeIndexer, DivisionMatchesTheHardwareOne)
{
  const sltk::Index large = sltk::Index(1) << 32;
  std::vector<sltk::Index> divisors = { 1, 2, 3, 7, 64, 85, 253, 318, 320, 1000, 4096, 65535, 65536, 1 << 20,
    2147483647, large - 1, large, large + 1, sltk::Index(1) << 40 };
  std::vector<sltk::Index> numerators = { 0, 1, 2, 3, 63, 64, 65, 25745279, large - 2, large - 1, large, large + 1,
    (sltk::Index(1) << 40) + 12345, INT64_MAX, -1, -7, -large, INT64_MIN + 1 };
  std::mt19937_64 random(42);
  for (int n = 0; n < 2000; ++n)
  {
    numerators.push_back(static_cast<sltk::Index>(random() % static_cast<std::uint64_t>(large)));
    divisors.push_back(static_cast<sltk::Index>(1 + random() % 100000));
  }
  for (const sltk::Index d : divisors)
  {
    for (size_t n = 0; n < numerators.size(); n += (d > 100000 ? 1 : 7))
    {
      expectDivision(d, numerators[n]);
    }
    for (sltk::Index k = large - 3 * d; k < large + 3 * d && d < 100000; k += d / 2 + 1)
    {
      expectDivision(d, k); // quotients and remainders around the 2^32 bound
    }
  }
}

TEST(NodeIndexer, EveryNodeOfAGrid)
{
  for (const std::array<sltk::Index, 3> dims :
    { std::array<sltk::Index, 3>{ 5, 7, 3 }, std::array<sltk::Index, 3>{ 1, 9, 4 }, { 17, 1, 1 }, { 320, 318, 4 } })
  {
    const sltk::NodeIndexer<3> indexer(dims);
    const sltk::Index count = dims[0] * dims[1] * dims[2];
    for (sltk::Index k = 0; k < count; ++k)
    {
      const std::array<sltk::Index, 3> i = indexer(k);
      ASSERT_EQ(i[0], k % dims[0]);
      ASSERT_EQ(i[1], (k / dims[0]) % dims[1]);
      ASSERT_EQ(i[2], (k / (dims[0] * dims[1])) % dims[2]);
    }
  }
  sltk::GridSpec<2> g = sltk::uniformBox<2>(11, 0.0, 1.0);
  g.Dims[1] = 6;
  const sltk::GridField<2> field(g, 2);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const std::array<sltk::Index, 2> i = field.nodeIndex(k);
    ASSERT_EQ(i[0] + 11 * i[1], k);
    ASSERT_TRUE(i[0] >= 0 && i[0] < 11 && i[1] >= 0 && i[1] < 6);
  }
}
