// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/grid/SampleField.h"

#include <gtest/gtest.h>

TEST(SampleField, BoundaryFillExtrapolatesExactFillEvaluates)
{
  sltk::GridSpec<2> g;
  g.Dims = { 5, 4 };
  g.Origin = { 0.0, 1.0 };
  g.Spacing = { 0.5, 0.25 };
  g.Bounds = { sltk::Boundary::Extrapolate, sltk::Boundary::Extrapolate };
  auto f = [](const double* x) { return x[0] * x[0] + 3.0 * x[1]; };
  auto byPolicy = sltk::sampleField(g, 2, f);
  auto exact = sltk::sampleField(g, 2, f, sltk::GhostFill::Exact);
  EXPECT_EQ(byPolicy({ 2, 3 }), 1.0 + 3.0 * 1.75);
  EXPECT_EQ(exact({ 2, 3 }), byPolicy({ 2, 3 }));
  // Ghost at x = -0.5: exact value 0.25 + 3; linear extrapolation of x^2 gives 0 - (0.25 - 0) = -0.25.
  EXPECT_DOUBLE_EQ(exact({ -1, 0 }), 0.25 + 3.0);
  EXPECT_DOUBLE_EQ(byPolicy({ -1, 0 }), -0.25 + 3.0);
}
