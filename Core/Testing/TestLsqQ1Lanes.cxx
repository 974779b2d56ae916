// SPDX-License-Identifier: BSD-3-Clause
// LsqQ1Lanes (the feet of an SL step fitted together) gives the values of
// LsqQ1Interpolator::evalAt bit for bit: inside, on the boundary cells, at
// nodes and half-way between them (where the nearest node changes), on a
// smooth field, one with kinks and one with large jumps.
#include "sltk/interp/LsqQ1.h"
#include "sltk/interp/LsqQ1Lanes.h"

#include "sltk/grid/SampleField.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// Compares the lanes with evalAt (sltktest::lanesMismatches).
template <int D, class F>
void expectBitwiseEqual(F f, int trials)
{
  sltk::GridSpec<D> g = sltk::uniformBox<D>(13, -1.0, 1.0);
  for (int a = 0; a < D; ++a)
  {
    g.Spacing[a] *= 1.0 + 0.1 * a;
  }
  sltk::GridField<D> field = sltk::sampleField(g, sltk::LsqQ1Interpolator<D>::GhostWidth, f);
  const auto around = sltk::stencilOffsets<D, 3>(field.strides(), -1);
  const sltk::LsqQ1Lanes<D> lanes(field);
  EXPECT_EQ(
    sltktest::lanesMismatches<D>(
      g, lanes, [&](const sltk::CellLocation<D>& at) { return sltk::LsqQ1Interpolator<D>::evalAt(field, around, at); },
      trials),
    0);
}
} // namespace

TEST(LsqQ1Lanes, SmoothFieldBitwise)
{
  expectBitwiseEqual<2>([](const auto& x) { return std::sin(3.0 * x[0]) * std::cos(2.0 * x[1]); }, 4000);
  expectBitwiseEqual<3>([](const auto& x) { return std::sin(3.0 * x[0]) * std::cos(2.0 * x[1]) + x[2] * x[2]; }, 4000);
}

TEST(LsqQ1Lanes, KinkedAndJumpingFieldsBitwise)
{
  expectBitwiseEqual<3>(
    [](const auto& x) { return std::fabs(std::sqrt(x[0] * x[0] + x[1] * x[1]) - 0.5) - x[2]; }, 4000);
  expectBitwiseEqual<3>([](const auto& x) { return x[0] + x[1] > 0.2 ? 1e6 : -3.0 * x[2]; }, 4000);
  expectBitwiseEqual<2>([](const auto& x) { return x[0] * x[1] > 0.0 ? 1e-8 : 5.0; }, 4000);
}
