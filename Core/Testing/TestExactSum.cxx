// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/core/ExactSum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{
double exactSum(const std::vector<double>& terms)
{
  sltk::ExactSum s;
  for (double t : terms)
  {
    s.add(t);
  }
  return s.value();
}
} // namespace

TEST(ExactSum, CancellationAndRoundingToNearestEven)
{
  EXPECT_EQ(exactSum({}), 0.0);
  EXPECT_EQ(exactSum({ 1e100, 1.0, -1e100 }), 1.0); // a plain sum gives 0
  EXPECT_EQ(exactSum({ 1.0, -1.0 }), 0.0);
  EXPECT_EQ(exactSum({ -2.5, 0.5 }), -2.0);
  const double ulp = std::ldexp(1.0, -52);
  EXPECT_EQ(exactSum({ 1.0, ulp / 2 }), 1.0);                              // a tie: to even
  EXPECT_EQ(exactSum({ 1.0 + ulp, ulp / 2 }), 1.0 + 2 * ulp);              // a tie: to even, up
  EXPECT_EQ(exactSum({ 1.0, ulp / 2, std::ldexp(1.0, -200) }), 1.0 + ulp); // just above the tie
  EXPECT_EQ(exactSum({ 1.0, ulp / 2, -std::ldexp(1.0, -200) }), 1.0);      // just below it
  const double least = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(exactSum({ least, least, least }), 3 * least);
  EXPECT_EQ(exactSum({ std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), least }), least);
  EXPECT_EQ(exactSum({ std::numeric_limits<double>::max(), std::numeric_limits<double>::max() }),
    std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isinf(exactSum({ 1.0, std::numeric_limits<double>::infinity() })));
  EXPECT_TRUE(std::isnan(exactSum({ 1.0, std::numeric_limits<double>::quiet_NaN() })));
}

TEST(ExactSum, AnyOrderAndSplitGivesTheCorrectlyRoundedSum)
{
  // Terms within 2^40 of each other and 2^16 of them: their exact sum has at most 53 + 40 + 16 bits,
  // which a long double of 64 bits does not hold but __float128's 113 do.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-20, 20);
  std::vector<double> terms(1 << 16);
  __float128 reference = 0;
  for (double& t : terms)
  {
    t = std::ldexp(mantissa(rng), exponent(rng));
    reference += t;
  }
  const double expected = static_cast<double>(reference);
  EXPECT_EQ(exactSum(terms), expected);
  std::shuffle(terms.begin(), terms.end(), rng);
  EXPECT_EQ(exactSum(terms), expected);
  sltk::ExactSum first, second;
  for (size_t i = 0; i < terms.size(); ++i)
  {
    (i % 3 == 0 ? first : second).add(terms[i]);
  }
  first += second;
  EXPECT_EQ(first.value(), expected);
}
