// SPDX-License-Identifier: BSD-3-Clause
// Control sets A and the minimisation of (3.7) (thesis 3.2): tabulation on
// constant controls + golden section / projected Nelder-Mead, kept inside A.
#include "sltk/hjb/ControlSet.h"
#include "sltk/hjb/Minimizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using sltk::ControlKind;
using sltk::ControlSet;
using sltk::ControlMinimizer;
using sltk::LocalSearch;
using sltk::MinimizerOptions;

/// (x - 0.7)^2 + 3 (y + 1.1)^2 + (x - 0.7)(y + 1.1) of the control (x, y):
/// a tilted bowl, its minimum 0 at (0.7, -1.1).
double tiltedBowl(const sltk::ControlSequence<2, 1>& a)
{
  const double x = a[0][0] - 0.7, y = a[0][1] + 1.1;
  return x * x + 3.0 * y * y + x * y;
}

/// Minimises f over the disc (`points` tabulation points per axis, the default
/// search with `tolerance`) and expects that no control f is given lies outside
/// the disc (by more than 1e-12): the projected search keeps its vertices in A.
template <class F>
auto minimizeInDisc(const ControlSet<2>& disc, int points, double tolerance, F f)
{
  MinimizerOptions opt;
  opt.TabulationPoints = points;
  opt.Tolerance = tolerance;
  const ControlMinimizer<2, 1> m(disc, opt);
  int outside = 0;
  const auto r = m.minimize(
    [&](const sltk::ControlSequence<2, 1>& a)
    {
      outside += disc.contains(a[0], 1e-12) ? 0 : 1;
      return f(a);
    });
  EXPECT_EQ(outside, 0) << "controls evaluated outside the disc";
  return r;
}

TEST(HjbControlSet, MembershipAndProjection)
{
  const auto box = ControlSet<2>::box({ -1.0, 0.0 }, { 1.0, 2.0 });
  EXPECT_TRUE(box.validate().isOk());
  EXPECT_TRUE(box.contains({ 0.5, 1.5 }));
  EXPECT_FALSE(box.contains({ 1.5, 1.5 }));
  const auto pb = box.project({ 3.0, -1.0 });
  EXPECT_DOUBLE_EQ(pb[0], 1.0);
  EXPECT_DOUBLE_EQ(pb[1], 0.0);

  const auto ball = ControlSet<2>::ball({ 1.0, 0.0 }, 2.0);
  EXPECT_TRUE(ball.contains({ 2.0, 1.0 }));
  EXPECT_FALSE(ball.contains({ 4.0, 0.0 }));
  const auto pball = ball.project({ 1.0, 4.0 });
  EXPECT_NEAR(pball[0], 1.0, 1e-15);
  EXPECT_NEAR(pball[1], 2.0, 1e-15);

  const auto circle = ControlSet<2>::sphere({ 0.0, 0.0 }, 1.0);
  EXPECT_FALSE(circle.contains({ 0.5, 0.0 }));
  const auto pc = circle.project({ 0.0, -3.0 });
  EXPECT_NEAR(pc[1], -1.0, 1e-15);
  EXPECT_TRUE(circle.contains(circle.project({ 0.0, 0.0 }))); // the centre goes somewhere on the circle

  const auto finite = ControlSet<1>::finite({ { -1.0 }, { 0.25 }, { 3.0 } });
  EXPECT_TRUE(finite.contains({ 0.25 }));
  EXPECT_DOUBLE_EQ(finite.project({ 0.0 })[0], 0.25);

  EXPECT_FALSE(ControlSet<1>::box({ 1.0 }, { 0.0 }).validate().isOk());
  EXPECT_FALSE(ControlSet<2>::ball({ 0.0, 0.0 }, -1.0).validate().isOk());
  EXPECT_FALSE(ControlSet<1>::finite({}).validate().isOk());
  EXPECT_TRUE(ControlSet<1>::none().empty());
}

TEST(HjbControlSet, TabulationCoversAndStaysInsideA)
{
  const auto box = ControlSet<2>::box({ -1.0, 0.0 }, { 1.0, 2.0 });
  const auto tb = box.tabulation(5);
  ASSERT_EQ(tb.size(), 25u);
  for (const auto& a : tb)
  {
    EXPECT_TRUE(box.contains(a));
  }
  const auto disc = ControlSet<2>::ball({ 0.0, 0.0 }, 2.2);
  const auto td = disc.tabulation(33);
  EXPECT_GT(td.size(), 780u); // about pi/4 of 33 x 33
  EXPECT_LT(td.size(), 900u);
  bool hasCentre = false;
  for (const auto& a : td)
  {
    EXPECT_TRUE(disc.contains(a, 1e-12));
    hasCentre = hasCentre || (a[0] == 0.0 && a[1] == 0.0);
  }
  EXPECT_TRUE(hasCentre);
  const auto circle = ControlSet<2>::sphere({ 0.0, 0.0 }, 1.0);
  const auto tc = circle.tabulation(16);
  ASSERT_EQ(tc.size(), 16u);
  for (const auto& a : tc)
  {
    EXPECT_TRUE(circle.contains(a, 1e-12));
  }
  EXPECT_TRUE(ControlSet<3>::none().tabulation(8).empty());
}

TEST(HjbMinimizer, GoldenSectionFindsInteriorMinimum)
{
  const auto set = ControlSet<1>::box({ -1.5707963267948966 }, { 1.5707963267948966 });
  MinimizerOptions opt;
  opt.TabulationPoints = 64;
  opt.Search = LocalSearch::Golden;
  opt.Tolerance = 1e-12;
  const ControlMinimizer<1, 1> m(set, opt);
  const double target = 0.3141;
  const auto r = m.minimize([&](const sltk::ControlSequence<1, 1>& a) {
    EXPECT_TRUE(set.contains(a[0]));
    return std::cosh(a[0][0] - target);
  });
  EXPECT_NEAR(r.Controls[0][0], target, 1e-6);
  EXPECT_NEAR(r.Value, 1.0, 1e-13);
  EXPECT_GT(r.Evaluations, 64);
  EXPECT_LT(r.Evaluations, 64 + 80);
}

TEST(HjbMinimizer, GoldenSectionStopsAtTheBoundary)
{
  const auto set = ControlSet<1>::box({ -2.0 }, { 2.0 });
  MinimizerOptions opt;
  opt.TabulationPoints = 9;
  const ControlMinimizer<1, 1> m(set, opt);
  const auto r = m.minimize([&](const sltk::ControlSequence<1, 1>& a) {
    EXPECT_TRUE(set.contains(a[0]));
    return (a[0][0] - 5.0) * (a[0][0] - 5.0);
  });
  EXPECT_NEAR(r.Controls[0][0], 2.0, 1e-12);
}

TEST(HjbMinimizer, NelderMeadInteriorMinimumInADisc)
{
  const auto disc = ControlSet<2>::ball({ 0.0, 0.0 }, 2.2);
  const auto r = minimizeInDisc(disc, 11, 1e-10, tiltedBowl);
  EXPECT_NEAR(r.Controls[0][0], 0.7, 1e-6);
  EXPECT_NEAR(r.Controls[0][1], -1.1, 1e-6);
  EXPECT_NEAR(r.Value, 0.0, 1e-12);
}

TEST(HjbMinimizer, WarmStartFindsTheMinimumWithFewerEvaluations)
{
  const auto disc = ControlSet<2>::ball({ 0.0, 0.0 }, 2.2);
  MinimizerOptions opt;
  opt.TabulationPoints = 33;
  opt.Search = LocalSearch::NelderMead;
  opt.Tolerance = 1e-10;
  opt.WarmTabulationPoints = 5;
  const ControlMinimizer<2, 1> m(disc, opt);
  ASSERT_TRUE(m.warmStarts());
  int outside = 0;
  auto f = [&](const sltk::ControlSequence<2, 1>& a)
  {
    outside += disc.contains(a[0], 1e-12) ? 0 : 1;
    return tiltedBowl(a);
  };
  const auto cold = m.minimize(f);
  const auto warm = m.minimizeFrom(f, { 0.6, -1.2 }); // the previous step's argmin, nearby
  EXPECT_EQ(outside, 0);
  EXPECT_NEAR(warm.Controls[0][0], 0.7, 1e-6);
  EXPECT_NEAR(warm.Controls[0][1], -1.1, 1e-6);
  EXPECT_NEAR(warm.Value, cold.Value, 1e-12);
  EXPECT_EQ(warm.Arguments[0], warm.Controls[0][0]); // parameters of a ball are its coordinates
  EXPECT_EQ(warm.Arguments[1], warm.Controls[0][1]);
  EXPECT_LT(4 * warm.Evaluations, cold.Evaluations);

  // A start on the boundary: the shifted grid is projected onto A, the minimum on the rim is found.
  auto rim = [&](const sltk::ControlSequence<2, 1>& a) { return -a[0][0]; };
  const auto edge = m.minimizeFrom(rim, { 2.2, 0.0 });
  EXPECT_EQ(outside, 0);
  EXPECT_NEAR(edge.Value, -2.2, 1e-8);
}

TEST(HjbMinimizer, WarmStartOnACircleOfHeadings)
{
  const auto circle = ControlSet<2>::sphere({ 0.0, 0.0 }, 1.0);
  MinimizerOptions opt;
  opt.TabulationPoints = 32;
  opt.Tolerance = 1e-10;
  opt.WarmTabulationPoints = 3;
  const ControlMinimizer<2, 1> m(circle, opt);
  auto f = [](const sltk::ControlSequence<2, 1>& a) { return -(0.6 * a[0][0] + 0.8 * a[0][1]); };
  const auto r = m.minimizeFrom(f, { std::atan2(0.8, 0.6) + 0.3 });
  EXPECT_NEAR(r.Value, -1.0, 1e-12);
  EXPECT_NEAR(r.Arguments[0], std::atan2(0.8, 0.6), 1e-5);
  EXPECT_LT(r.Evaluations, 60);
}

TEST(HjbMinimizer, NelderMeadKeepsVerticesInsideWhenTheMinimumIsOutside)
{
  // Unconstrained minimum at (3, 4), |(3, 4)| = 5: the constrained one is 2 (3, 4) / 5.
  const auto disc = ControlSet<2>::ball({ 0.0, 0.0 }, 2.0);
  const auto r = minimizeInDisc(disc, 9, MinimizerOptions{}.Tolerance,
    [](const sltk::ControlSequence<2, 1>& a)
    { return (a[0][0] - 3.0) * (a[0][0] - 3.0) + (a[0][1] - 4.0) * (a[0][1] - 4.0); });
  EXPECT_NEAR(r.Controls[0][0], 1.2, 1e-5);
  EXPECT_NEAR(r.Controls[0][1], 1.6, 1e-5);
}

TEST(HjbMinimizer, CircleOfHeadings)
{
  // min c . a over |a| = 1 is at a = -c / |c| (Zermelo: swim against c).
  const auto circle = ControlSet<2>::sphere({ 0.0, 0.0 }, 1.0);
  MinimizerOptions opt;
  opt.TabulationPoints = 16;
  opt.Tolerance = 1e-12;
  const ControlMinimizer<2, 1> m(circle, opt);
  const double c0 = 0.3, c1 = -0.8, norm = std::hypot(c0, c1);
  const auto r = m.minimize([&](const sltk::ControlSequence<2, 1>& a) {
    EXPECT_TRUE(circle.contains(a[0], 1e-12));
    return c0 * a[0][0] + c1 * a[0][1];
  });
  EXPECT_NEAR(r.Controls[0][0], -c0 / norm, 1e-6);
  EXPECT_NEAR(r.Controls[0][1], -c1 / norm, 1e-6);
  EXPECT_NEAR(r.Value, -norm, 1e-11);
}

TEST(HjbMinimizer, PerStageControlsOverAnu)
{
  // Separate targets per stage: a constant control cannot reach them, A^3 can.
  const auto set = ControlSet<1>::box({ -2.0 }, { 2.0 });
  MinimizerOptions opt;
  opt.TabulationPoints = 17;
  opt.Tolerance = 1e-10;
  const double target[3] = { -0.5, 0.25, 1.3 };
  auto objective = [&](const sltk::ControlSequence<1, 3>& a) {
    double s = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_TRUE(set.contains(a[k]));
      s += (k + 1.0) * (a[k][0] - target[k]) * (a[k][0] - target[k]);
    }
    return s;
  };
  const ControlMinimizer<1, 3> perStage(set, opt);
  EXPECT_EQ(perStage.parameterCount(), 3);
  const auto r = perStage.minimize(objective);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(r.Controls[k][0], target[k], 1e-5);
  }
  opt.PerStageControls = false;
  const ControlMinimizer<1, 3> single(set, opt);
  const auto r1 = single.minimize(objective);
  EXPECT_DOUBLE_EQ(r1.Controls[0][0], r1.Controls[2][0]);
  EXPECT_GT(r1.Value, 0.5); // the best constant control is far from optimal
  EXPECT_LT(r.Value, 1e-9);
}

TEST(HjbMinimizer, FiniteSetAndEmptySet)
{
  const auto finite = ControlSet<1>::finite({ { -1.0 }, { 0.25 }, { 3.0 } });
  const ControlMinimizer<1, 2> m(finite, MinimizerOptions{});
  EXPECT_EQ(m.tabulationSize(), 9); // all of A^2
  const auto r = m.minimize([](const sltk::ControlSequence<1, 2>& a) {
    return (a[0][0] - 3.0) * (a[0][0] - 3.0) + (a[1][0] + 1.0) * (a[1][0] + 1.0);
  });
  EXPECT_DOUBLE_EQ(r.Controls[0][0], 3.0);
  EXPECT_DOUBLE_EQ(r.Controls[1][0], -1.0);
  EXPECT_EQ(r.Evaluations, 9);

  const ControlMinimizer<2, 3> none(ControlSet<2>::none(), MinimizerOptions{});
  int calls = 0;
  const auto rn = none.minimize([&](const sltk::ControlSequence<2, 3>&) {
    ++calls;
    return 42.0;
  });
  EXPECT_EQ(calls, 1); // pure transport: one evaluation, no search
  EXPECT_EQ(rn.Value, 42.0);
}

TEST(HjbMinimizer, NaNIsNeverTheMinimum)
{
  const auto set = ControlSet<1>::box({ -1.0 }, { 1.0 });
  const ControlMinimizer<1, 1> m(set, MinimizerOptions{});
  const auto r = m.minimize([](const sltk::ControlSequence<1, 1>& a) {
    return a[0][0] < 0.0 ? std::nan("") : (a[0][0] - 0.5) * (a[0][0] - 0.5);
  });
  EXPECT_NEAR(r.Controls[0][0], 0.5, 1e-6);
}

} // namespace
