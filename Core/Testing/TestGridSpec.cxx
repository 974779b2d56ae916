// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/grid/GridSpec.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// [-2, 2]^2 with n nodes per axis.
sltk::GridSpec<2> square(sltk::Index n, sltk::Boundary b = sltk::Boundary::Extrapolate)
{
  return sltk::uniformBox<2>(n, -2.0, 2.0, b);
}
} // namespace

TEST(GridSpec, CountsAndCoordinates)
{
  auto g = square(81);
  EXPECT_EQ(g.nodeCount(), 81 * 81);
  EXPECT_DOUBLE_EQ(g.Spacing[0], 0.05);
  EXPECT_DOUBLE_EQ(g.coordinate(0, 80), 2.0);
  EXPECT_DOUBLE_EQ(g.length(1), 4.0);
  g.Bounds[1] = sltk::Boundary::Periodic;
  EXPECT_DOUBLE_EQ(g.length(1), 81 * 0.05);
}

TEST(GridSpec, ValidateNamesTheProblem)
{
  EXPECT_TRUE(square(3).validate().isOk());
  auto g = square(1);
  auto s = g.validate();
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_NE(s.message().find("along x"), std::string::npos) << s.message();
  g = square(10);
  g.Spacing[1] = 0.0;
  s = g.validate();
  EXPECT_NE(s.message().find("spacing along y"), std::string::npos) << s.message();
  g = square(10);
  g.Origin[0] = std::nan("");
  EXPECT_FALSE(g.validate().isOk());
}

TEST(GridSpec, LocateIsExactAtNodes)
{
  auto g = square(81);
  for (sltk::Index i = 0; i < 81; ++i)
  {
    const double x[2] = { g.coordinate(0, i), g.coordinate(1, 80 - i) };
    auto loc = sltk::locate(g, x);
    // Node i is either the left end of cell i (t = 0) or, for the last node, the right end.
    if (i < 80)
    {
      EXPECT_EQ(loc.Cell[0], i);
      EXPECT_EQ(loc.Local[0], 0.0);
    }
    else
    {
      EXPECT_EQ(loc.Cell[0], 79);
      EXPECT_EQ(loc.Local[0], 1.0);
    }
  }
}

TEST(GridSpec, LocateInteriorPoint)
{
  auto g = square(81);
  const double x[2] = { -2.0 + 0.05 * 10.25, -2.0 + 0.05 * 3.5 };
  auto loc = sltk::locate(g, x);
  EXPECT_EQ(loc.Cell[0], 10);
  EXPECT_NEAR(loc.Local[0], 0.25, 1e-12);
  EXPECT_EQ(loc.Cell[1], 3);
  EXPECT_NEAR(loc.Local[1], 0.5, 1e-12);
}

TEST(GridSpec, LocateClipsOutsidePointsOntoTheBoundary)
{
  auto g = square(11);
  const double x[2] = { -100.0, 100.0 };
  auto loc = sltk::locate(g, x);
  EXPECT_EQ(loc.Cell[0], 0);
  EXPECT_EQ(loc.Local[0], 0.0);
  EXPECT_EQ(loc.Cell[1], 9);
  EXPECT_EQ(loc.Local[1], 1.0);
}

TEST(GridSpec, LocateWrapsPeriodicAxes)
{
  sltk::GridSpec<1> g;
  g.Dims = { 10 };
  g.Origin = { 0.0 };
  g.Spacing = { 0.1 };
  g.Bounds = { sltk::Boundary::Periodic };
  const double inside[1] = { 0.95 };
  auto loc = sltk::locate(g, inside);
  EXPECT_EQ(loc.Cell[0], 9); // the cell between node 9 and node 10 == node 0
  EXPECT_NEAR(loc.Local[0], 0.5, 1e-12);
  const double wrapped[1] = { 0.95 - 3.0 };
  auto loc2 = sltk::locate(g, wrapped);
  EXPECT_EQ(loc2.Cell[0], 9);
  EXPECT_NEAR(loc2.Local[0], 0.5, 1e-9);
  const double period[1] = { 1.0 };
  auto loc3 = sltk::locate(g, period);
  EXPECT_EQ(loc3.Cell[0], 0);
  EXPECT_EQ(loc3.Local[0], 0.0);
}

TEST(GridSpec, FloorToIndexIsFloor)
{
  const double values[] = { 0.0, -0.0, 0.5, 1.0, 1.0 - 1e-16, -1e-300, -0.5, -1.0, -1.0 - 2e-16, 2.5, -2.5, 1e15 + 0.5,
    -1e15 - 0.5, 123456.999999, std::nextafter(3.0, 0.0) };
  for (const double v : values)
  {
    EXPECT_EQ(sltk::floorToIndex(v), static_cast<sltk::Index>(std::floor(v))) << v;
  }
}

TEST(GridSpec, LocateSnapsWithinTheToleranceOfANodeOnly)
{
  // The snap reads floor(s + 0.5): the same node as nearbyint within 1e-10, no snap at a tie.
  const auto g = sltk::uniformBox<1>(11, 0.0, 1.0);
  for (const double s : { 3.0 + 5e-11, 3.0 - 5e-11, 3.5, 2.5, 3.0 + 2e-10, 0.0, 10.0 - 3e-11 })
  {
    const double x[1] = { s / 10.0 };
    const auto loc = sltk::locate(g, x);
    const double nearest = std::nearbyint(g.indexCoordinate(0, x[0]));
    const double t = g.indexCoordinate(0, x[0]);
    const double snapped = std::fabs(t - nearest) < 1e-10 ? nearest : t;
    EXPECT_EQ(static_cast<double>(loc.Cell[0]) + loc.Local[0], snapped) << s;
  }
}
