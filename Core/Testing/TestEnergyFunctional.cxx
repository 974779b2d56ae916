// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/EnergyFunctional.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A centre off the grid's symmetry axes.
const double C[3] = { 0.0131, -0.0207, 0.0173 };

template <int D>
double radius(const std::array<double, D>& x)
{
  double s = 0.0;
  for (int a = 0; a < D; ++a)
  {
    s += (x[a] - C[a]) * (x[a] - C[a]);
  }
  return std::sqrt(s);
}

/// The P = 1 energy with weight 1 of the sphere (circle in 2D) of radius r about C,
/// phi = |x - C| - r on [-1, 1]^D with n nodes per axis: its area (length) as the
/// functional measures it, in e.
template <int D>
sltk::Status sphereMeasure(sltk::Index n, double r, sltk::EnergyResult& e)
{
  const auto g = sltk::uniformBox<D>(n, -1.0, 1.0);
  const auto phi = sltktest::sampleNodes<D>(g, 1, [&](const std::array<double, D>& x) { return radius<D>(x) - r; });
  const auto one = sltktest::sampleNodes<D>(g, 1, [](const std::array<double, D>&) { return 1.0; });
  sltk::EnergyOptions options;
  options.P = 1.0;
  return sltk::energyFunctional(phi, one, sltk::Context{}, e, options);
}
} // namespace

TEST(EnergyFunctional, CircleLengthConvergesAtSecondOrder)
{
  const double r = 0.7;
  double previous = 0.0;
  for (sltk::Index n : { 21, 41, 81, 161 })
  {
    sltk::EnergyResult e;
    ASSERT_TRUE(sphereMeasure<2>(n, r, e).isOk());
    const double error = std::fabs(e.Energy - 2.0 * Pi * r);
    std::printf("circle n=%lld: length %.8f, error %.3e", static_cast<long long>(n), e.Energy, error);
    if (previous > 0.0)
    {
      std::printf(", order %.2f", std::log2(previous / error));
      EXPECT_GT(std::log2(previous / error), 1.8);
    }
    std::printf("\n");
    previous = error;
    // The inscribed polygon is shorter than the circle.
    EXPECT_LT(e.Energy, 2.0 * Pi * r);
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(EnergyFunctional, CircleWithDistanceWeightAndPEqualTwo)
{
  // d = |x - C| equals r on the circle: E_p = (2 pi r r^p)^(1/p).
  const double r = 0.6;
  const auto g = sltk::uniformBox<2>(161, -1.0, 1.0);
  const auto phi = sltktest::sampleNodes<2>(g, 1, [&](const std::array<double, 2>& x) { return radius<2>(x) - r; });
  const auto d = sltktest::sampleNodes<2>(g, 1, [&](const std::array<double, 2>& x) { return radius<2>(x); });
  const auto one = sltktest::sampleNodes<2>(g, 1, [](const std::array<double, 2>&) { return 1.0; });
  sltk::EnergyResult e;
  ASSERT_TRUE(sltk::energyFunctional(phi, one, sltk::Context{}, e).isOk()); // p = 2 by default
  EXPECT_NEAR(e.Energy, std::sqrt(2.0 * Pi * r), 1e-4);
  EXPECT_NEAR(e.Integral, 2.0 * Pi * r, 2e-4);
  ASSERT_TRUE(sltk::energyFunctional(phi, d, sltk::Context{}, e).isOk());
  EXPECT_NEAR(e.Energy, std::sqrt(2.0 * Pi * r * r * r), 1e-3);
  sltk::EnergyOptions three;
  three.P = 3.0;
  ASSERT_TRUE(sltk::energyFunctional(phi, d, sltk::Context{}, e, three).isOk());
  EXPECT_NEAR(e.Energy, std::cbrt(2.0 * Pi * std::pow(r, 4.0)), 1e-3);
  EXPECT_GT(e.FrontCells, 0);
}

TEST(EnergyFunctional, SaddleCellsGiveTwoSegments)
{
  // phi = x y on one cell [-1, 1]^2 with centre value 0 shifted to +0.1: the
  // zero set is the hyperbola x y = -0.1; the cuts are at (+-0.1, -+1) and (-+1, +-0.1).
  sltk::GridSpec<2> g;
  g.Dims = { 2, 2 };
  g.Origin = { -1.0, -1.0 };
  g.Spacing = { 2.0, 2.0 };
  const auto phi = sltktest::sampleNodes<2>(g, 1, [](const std::array<double, 2>& x) { return x[0] * x[1] + 0.1; });
  const auto one = sltktest::sampleNodes<2>(g, 1, [](const std::array<double, 2>&) { return 1.0; });
  sltk::EnergyResult e;
  sltk::EnergyOptions options;
  options.P = 1.0;
  ASSERT_TRUE(sltk::energyFunctional(phi, one, sltk::Context{}, e, options).isOk());
  // Corners (-1,-1), (1,1) are positive (1.1), the centre 0.1 is positive: the two
  // segments cut off the negative corners (1,-1) and (-1,1): each from (0.1/1.1... ) on the edges.
  const double t = 1.1 / 2.0; // fraction along an edge from the positive corner: 1.1 / (1.1 + 0.9)
  const double cutA = -1.0 + 2.0 * t;
  const double seg = std::hypot(1.0 - cutA, 1.0 - cutA);
  EXPECT_NEAR(e.Integral, 2.0 * seg, 1e-14);
  EXPECT_EQ(e.FrontCells, 1);
}

TEST(EnergyFunctional, SphereAreaWithinAFewPercent)
{
  const double r = 0.6;
  const auto g = sltk::uniformBox<3>(41, -1.0, 1.0);
  const auto phi = sltktest::sampleNodes<3>(g, 1, [&](const std::array<double, 3>& x) { return radius<3>(x) - r; });
  const auto one = sltktest::sampleNodes<3>(g, 1, [](const std::array<double, 3>&) { return 1.0; });
  const auto d = sltktest::sampleNodes<3>(g, 1, [&](const std::array<double, 3>& x) { return radius<3>(x); });
  const double area = 4.0 * Pi * r * r;
  sltk::EnergyResult e;
  sltk::EnergyOptions options;
  options.P = 1.0;
  ASSERT_TRUE(sltk::energyFunctional(phi, one, sltk::Context{}, e, options).isOk());
  std::printf("sphere 41^3: area %.5f vs %.5f (%.2f%%)\n", e.Energy, area, 100.0 * (e.Energy / area - 1.0));
  EXPECT_NEAR(e.Energy, area, 0.03 * area);
  // p = 2 with d = |x - C| = r on the sphere: E_2 = sqrt(4 pi r^2 r^2).
  options.P = 2.0;
  ASSERT_TRUE(sltk::energyFunctional(phi, d, sltk::Context{}, e, options).isOk());
  EXPECT_NEAR(e.Energy, std::sqrt(area * r * r), 0.02 * std::sqrt(area * r * r));
  // The literal (dx')^(n-1) weight of (4.30) gives sqrt(3) times the area.
  options.P = 1.0;
  options.Measure = sltk::SubcellMeasure::Thesis;
  sltk::EnergyResult literal;
  ASSERT_TRUE(sltk::energyFunctional(phi, one, sltk::Context{}, literal, options).isOk());
  EXPECT_NEAR(literal.Energy / area, std::sqrt(3.0), 0.03 * std::sqrt(3.0));
}

TEST(EnergyFunctional, SphereAreaConvergesWithTheGrid)
{
  const double r = 0.5;
  double errors[2];
  int k = 0;
  for (sltk::Index n : { 21, 41 })
  {
    sltk::EnergyResult e;
    ASSERT_TRUE(sphereMeasure<3>(n, r, e).isOk());
    errors[k++] = std::fabs(e.Energy / (4.0 * Pi * r * r) - 1.0);
    std::printf("sphere r=0.5 n=%lld: relative area error %.3f%%\n", static_cast<long long>(n), 100.0 * errors[k - 1]);
  }
  EXPECT_LT(errors[1], 0.02);
}

TEST(EnergyFunctional, BandRestrictionAndThreadsAgree)
{
  const double r = 0.55;
  const auto g = sltk::uniformBox<3>(33, -1.0, 1.0);
  const double dx = g.Spacing[0];
  const auto phi = sltktest::sampleNodes<3>(g, 1, [&](const std::array<double, 3>& x) { return radius<3>(x) - r; });
  const auto d = sltktest::sampleNodes<3>(g, 1, [&](const std::array<double, 3>& x) { return 0.2 + x[0] * x[0]; });
  sltk::EnergyResult full;
  ASSERT_TRUE(sltk::energyFunctional(phi, d, sltk::Context{}, full).isOk());
  sltk::NodeList band;
  sltk::collectBand(phi, 4.0 * dx, sltk::Context{}, band); // (1.48) with gamma = 4 dx
  sltk::EnergyResult banded;
  ASSERT_TRUE(sltk::energyFunctional(phi, d, band, sltk::Context{}, banded).isOk());
  EXPECT_EQ(banded.FrontCells, full.FrontCells);
  EXPECT_NEAR(banded.Integral, full.Integral, 1e-12 * full.Integral);
  sltk::ThreadPool pool(3);
  sltk::Context ctx;
  ctx.Executor = &pool;
  sltk::EnergyResult threaded;
  ASSERT_TRUE(sltk::energyFunctional(phi, d, band, ctx, threaded).isOk());
  EXPECT_EQ(threaded.Integral, banded.Integral);
  // Bad input.
  sltk::EnergyOptions bad;
  bad.P = 0.5;
  EXPECT_EQ(sltk::energyFunctional(phi, d, ctx, threaded, bad).code(), sltk::StatusCode::InvalidArgument);
  const auto other =
    sltktest::sampleNodes<3>(sltk::uniformBox<3>(21, -1.0, 1.0), 1, [](const std::array<double, 3>&) { return 1.0; });
  EXPECT_EQ(sltk::energyFunctional(phi, other, ctx, threaded).code(), sltk::StatusCode::InvalidArgument);
}

TEST(EnergyFunctional, SecondExponentInTheSamePassEqualsASeparatePass)
{
  // Algorithm 1 needs E_p for the scale factor (4.32) and E_2 for the stopping rule (4.33):
  // one traversal gives both, bit for bit the values of two separate passes (2D and 3D).
  auto check = [](const auto& phi, const auto& d)
  {
    sltk::EnergyOptions both;
    both.P = 1.0;
    both.SecondP = 2.0;
    sltk::EnergyOptions two;
    two.P = 2.0;
    sltk::EnergyResult merged, first, second;
    ASSERT_TRUE(sltk::energyFunctional(phi, d, sltk::Context{}, merged, both).isOk());
    ASSERT_TRUE(sltk::energyFunctional(phi, d, sltk::Context{}, first, sltk::EnergyOptions{ 1.0 }).isOk());
    ASSERT_TRUE(sltk::energyFunctional(phi, d, sltk::Context{}, second, two).isOk());
    EXPECT_EQ(merged.Energy, first.Energy);
    EXPECT_EQ(merged.SecondIntegral, second.Integral);
    EXPECT_EQ(merged.SecondEnergy, second.Energy);
    EXPECT_GT(merged.SecondEnergy, 0.0);
  };
  const auto g2 = sltk::uniformBox<2>(81, -1.0, 1.0);
  check(sltktest::sampleNodes<2>(g2, 1, [](const std::array<double, 2>& x) { return radius<2>(x) - 0.6; }),
    sltktest::sampleNodes<2>(g2, 1, [](const std::array<double, 2>& x) { return 0.1 + x[0] * x[0]; }));
  const auto g3 = sltk::uniformBox<3>(31, -1.0, 1.0);
  check(sltktest::sampleNodes<3>(g3, 1, [](const std::array<double, 3>& x) { return radius<3>(x) - 0.6; }),
    sltktest::sampleNodes<3>(g3, 1, [](const std::array<double, 3>& x) { return 0.1 + x[1] * x[1]; }));
  sltk::EnergyOptions bad;
  bad.SecondP = 0.5;
  sltk::EnergyResult r;
  EXPECT_FALSE(
    sltk::energyFunctional(sltktest::sampleNodes<2>(g2, 1, [](const std::array<double, 2>& x) { return x[0]; }),
      sltktest::sampleNodes<2>(g2, 1, [](const std::array<double, 2>&) { return 1.0; }), sltk::Context{}, r, bad)
      .isOk());
}
