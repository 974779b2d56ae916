// SPDX-License-Identifier: BSD-3-Clause
// Weno3Lanes (the feet of an SL step interpolated together) gives the values
// of Weno3Interpolator bit for bit: inside, on the boundary cells (clipped
// feet), at nodes, on a field with kinks and one with large jumps.
#include "sltk/interp/Weno3.h"
#include "sltk/interp/Weno3Lanes.h"

#include "sltk/grid/SampleField.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// Compares the lanes with one interpolator per foot (sltktest::lanesMismatches).
template <int D, class F>
void expectBitwiseEqual(F f, int trials)
{
  sltk::GridSpec<D> g = sltk::uniformBox<D>(13, -1.0, 1.0);
  for (int a = 0; a < D; ++a)
  {
    g.Spacing[a] *= 1.0 + 0.1 * a; // a spacing, hence an epsilon (2.67), per axis
  }
  sltk::GridField<D> field = sltk::sampleField(g, sltk::Weno3Interpolator<D>::GhostWidth, f);
  sltk::Weno3Interpolator<D> one(field);
  const sltk::Weno3Lanes<D> lanes(field);
  EXPECT_EQ(sltktest::lanesMismatches<D>(
              g, lanes,
              [&](const sltk::CellLocation<D>& at)
              {
                one.prepare(at.Cell);
                return one.eval(at.Local);
              },
              trials),
    0);
}
} // namespace

TEST(Weno3Lanes, SmoothFieldBitwise)
{
  expectBitwiseEqual<2>([](const auto& x) { return std::sin(3.0 * x[0]) * std::cos(2.0 * x[1]); }, 4000);
  expectBitwiseEqual<3>([](const auto& x) { return std::sin(3.0 * x[0]) * std::cos(2.0 * x[1]) + x[2] * x[2]; }, 4000);
}

TEST(Weno3Lanes, KinkedAndJumpingFieldsBitwise)
{
  // A distance-like kink (the nonlinear weights away from their linear values) and large jumps.
  expectBitwiseEqual<3>(
    [](const auto& x) { return std::fabs(std::sqrt(x[0] * x[0] + x[1] * x[1]) - 0.5) - x[2]; }, 4000);
  expectBitwiseEqual<3>([](const auto& x) { return x[0] + x[1] > 0.2 ? 1e6 : -3.0 * x[2]; }, 4000);
  expectBitwiseEqual<2>([](const auto& x) { return x[0] * x[1] > 0.0 ? 1e-8 : 5.0; }, 4000);
}
