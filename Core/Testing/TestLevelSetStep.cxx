// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/LevelSetStep.h"

#include "sltk/grid/SampleField.h"
#include "sltk/interp/Cweno.h"
#include "sltk/interp/Q1.h"
#include "sltk/interp/Weno3.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace
{
template <int D>
double radius(const double* x)
{
  return std::sqrt(sltktest::squaredNorm<D>(x));
}

/// Zero crossing of phi along the positive x axis (linear between nodes).
template <int D>
double crossingOnAxis(const sltk::GridField<D>& phi)
{
  const auto& g = phi.spec();
  std::array<sltk::Index, D> i{};
  for (int a = 1; a < D; ++a)
  {
    i[a] = (g.Dims[a] - 1) / 2;
  }
  for (sltk::Index k = (g.Dims[0] - 1) / 2; k + 1 < g.Dims[0]; ++k)
  {
    i[0] = k;
    const double a = phi(i);
    i[0] = k + 1;
    const double b = phi(i);
    if (a <= 0.0 && b > 0.0)
    {
      return g.coordinate(0, k) + g.Spacing[0] * a / (a - b);
    }
  }
  return NAN;
}

template <int D, class Interp>
double advanceSphere(sltk::Index n, int steps, double eta, double r0, bool distanceToSphere, double* dtOut = nullptr,
  sltk::ThreadPool* pool = nullptr, sltk::GridField<D>* result = nullptr, double dtOverDx = 1.0)
{
  const auto g = sltk::uniformBox<D>(n, -1.0, 1.0);
  const double dx = g.Spacing[0];
  auto phi = sltk::sampleField(g, 2, [&](const double* x) { return radius<D>(x) - r0; });
  // d = distance to a sphere of radius 0.3 (advection test) or 1 (curvature test: grad d = 0 away
  // from the centre is not true, so use a constant field instead).
  auto dist = sltk::sampleField(
    g, 1, [&](const double* x) { return distanceToSphere ? std::fabs(radius<D>(x) - 0.3) : 1.0; },
    sltk::GhostFill::Exact);
  sltk::LevelSetStepParameters par;
  par.P = 1.0;
  par.Eta = eta;
  par.TimeStep = dtOverDx * dx;
  par.Widths = sltk::BandWidths::forSpacing(dx, 3.0, 6.0);
  sltk::Context ctx;
  ctx.Executor = pool;
  std::vector<double> scratch;
  for (int s = 0; s < steps; ++s)
  {
    sltk::NodeList band;
    sltk::collectBand(phi, par.Widths.Gamma, ctx, band);
    EXPECT_TRUE((sltk::levelSetStep<Interp, D>(ctx, phi, dist, band, par, scratch).isOk()));
    // Keep phi a distance function (what reinitialisation does in Algorithm 1).
    const double shift = crossingOnAxis(phi);
    phi = sltk::sampleField(g, 2, [&](const double* x) { return radius<D>(x) - shift; });
  }
  if (dtOut)
  {
    *dtOut = par.TimeStep;
  }
  if (result)
  {
    *result = phi;
  }
  return crossingOnAxis(phi);
}

/// The values of one step on the band |phi| < gamma, with the feet within `feetWithin` (phi unchanged).
template <class Interp>
std::vector<double> stepValuesOnBand(const sltk::GridField<3>& phi, const sltk::GridField<3>& dist,
  sltk::LevelSetStepParameters par, double feetWithin, sltk::NodeList& band)
{
  sltk::Context ctx;
  sltk::collectBand(phi, par.Widths.Gamma, ctx, band);
  par.FeetWithin = feetWithin;
  auto copy = phi;
  std::vector<double> values;
  EXPECT_TRUE((sltk::levelSetStepValues<Interp, 3>(ctx, copy, dist, band, par, values).isOk()));
  return values;
}
} // namespace

TEST(LevelSetStep, AdvectionMovesTheFrontTowardsTheCloudAtUnitSpeed)
{
  // eta = 0, p = 1: phi_t = grad d . grad phi = 1 near a front outside the sphere of radius 0.3.
  double dt = 0.0;
  const double q1 = advanceSphere<2, sltk::Q1Interpolator<2>>(81, 5, 0.0, 0.7, true, &dt);
  EXPECT_NEAR(q1, 0.7 - 5 * dt, 0.05 * dt);
  const double weno = advanceSphere<3, sltk::Weno3Interpolator<3>>(41, 4, 0.0, 0.7, true, &dt);
  EXPECT_NEAR(weno, 0.7 - 4 * dt, 0.05 * dt);
  // CWENO feet go through the cell cache (CellCache.h).
  const double cweno = advanceSphere<3, sltk::CwenoInterpolator<3>>(41, 4, 0.0, 0.7, true, &dt);
  EXPECT_NEAR(cweno, 0.7 - 4 * dt, 0.05 * dt);
}

TEST(LevelSetStep, CurvatureTermShrinksCirclesAndSpheresByMeanCurvatureMotion)
{
  // d = 1, eta = 1, p = 1: phi_t = kappa |grad phi|, so r^2 = r0^2 - 2 (D - 1) t (4.10)-(4.20).
  // Final time 0.05 with dt = dx (4.36); the SL scheme for (4.10) is first order in dt.
  for (sltk::Index n : { 81, 161, 321 })
  {
    double dt = 0.0;
    const int steps = static_cast<int>(n - 1) / 40;
    const double r2 = advanceSphere<2, sltk::Weno3Interpolator<2>>(n, steps, 1.0, 0.5, false, &dt);
    const double exact2 = std::sqrt(0.25 - 2.0 * steps * dt);
    const double error = std::fabs(r2 - exact2);
    EXPECT_LT(error, 0.1 * (0.5 - exact2)) << "n = " << n;
  }
  // 3D with dt = dx / 8: the first-order time error ~ dt / r^2 stays small.
  double dt = 0.0;
  const double r3 = advanceSphere<3, sltk::Weno3Interpolator<3>>(41, 4, 1.0, 0.6, false, &dt, nullptr, nullptr, 0.125);
  const double exact3 = std::sqrt(0.36 - 4.0 * 4 * dt);
  EXPECT_NEAR(r3, exact3, 0.1 * (0.6 - exact3));
}

TEST(LevelSetStep, SerialAndThreadedAreIdentical)
{
  sltk::ThreadPool one(1), two(2);
  sltk::GridField<3> a, b;
  advanceSphere<3, sltk::Q1Interpolator<3>>(33, 2, 0.5, 0.6, true, nullptr, &one, &a);
  advanceSphere<3, sltk::Q1Interpolator<3>>(33, 2, 0.5, 0.6, true, nullptr, &two, &b);
  EXPECT_TRUE(a.storage() == b.storage());
}

TEST(LevelSetStep, WritesOnlyBandNodesAndUsesTheSingularFallback)
{
  const auto g = sltk::uniformBox<2>(21, -1.0, 1.0);
  // phi flat (|grad phi| = 0) on the left half: the fallback (4.26) averages neighbours.
  auto phi = sltk::sampleField(g, 2, [](const double* x) { return x[0] < 0.0 ? 0.0 : x[0]; });
  auto dist = sltk::sampleField(g, 1, [](const double*) { return 0.5; });
  const auto before = phi;
  sltk::NodeList band = { 3 + 21 * 10, 15 + 21 * 10 };
  sltk::LevelSetStepParameters par;
  par.TimeStep = g.Spacing[0];
  par.Widths = sltk::BandWidths::forSpacing(g.Spacing[0]);
  std::vector<double> scratch;
  double change = -1.0;
  sltk::Context ctx;
  ASSERT_TRUE((sltk::levelSetStep<sltk::Q1Interpolator<2>, 2>(ctx, phi, dist, band, par, scratch, &change).isOk()));
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    if (k != band[0] && k != band[1])
    {
      ASSERT_EQ(phi(phi.nodeIndex(k)), before(before.nodeIndex(k))) << k;
    }
  }
  EXPECT_EQ(phi({ 3, 10 }), 0.0); // mean of four zero neighbours
  EXPECT_GE(change, 0.0);
}

TEST(LevelSetStep, RejectsBadParameters)
{
  const auto g = sltk::uniformBox<2>(11, -1.0, 1.0);
  auto phi = sltk::sampleField(g, 1, [](const double* x) { return x[0]; });
  auto dist = sltk::sampleField(g, 1, [](const double*) { return 0.5; });
  sltk::LevelSetStepParameters par; // dt = 0
  std::vector<double> scratch;
  sltk::Context ctx;
  EXPECT_FALSE((sltk::levelSetStep<sltk::Q1Interpolator<2>, 2>(ctx, phi, dist, { 5 }, par, scratch).isOk()));
  par.TimeStep = 0.1;
  EXPECT_FALSE((sltk::levelSetStep<sltk::Weno3Interpolator<2>, 2>(ctx, phi, dist, { 5 }, par, scratch).isOk()))
    << "WENO3 needs two ghost layers";
}

TEST(LevelSetStep, FeetWithinBetaLeaveTheNodesNearTheFrontBitForBitAndLineariseTheRest)
{
  // A sphere of radius 0.6 advected towards one of radius 0.3 with the curvature term on.
  const auto g = sltk::uniformBox<3>(41, -1.0, 1.0);
  const double dx = g.Spacing[0];
  const auto phi = sltk::sampleField(g, 2, [](const double* x) { return radius<3>(x) - 0.6; });
  const auto dist = sltk::sampleField(
    g, 1, [](const double* x) { return std::fabs(radius<3>(x) - 0.3); }, sltk::GhostFill::Exact);
  sltk::LevelSetStepParameters par;
  par.P = 2.0;
  par.Eta = 0.05;
  par.Energy = 0.2;
  par.TimeStep = dx;
  par.Widths = sltk::BandWidths::forSpacing(dx);
  sltk::NodeList band;
  using LsqQ1 = sltk::LsqQ1Interpolator<3>;
  const auto all = stepValuesOnBand<LsqQ1>(phi, dist, par, std::numeric_limits<double>::infinity(), band);
  const auto near = stepValuesOnBand<LsqQ1>(phi, dist, par, par.Widths.Beta, band);
  ASSERT_EQ(all.size(), band.size());
  ASSERT_EQ(near.size(), band.size());
  size_t within = 0, beyond = 0, linearised = 0;
  for (size_t k = 0; k < band.size(); ++k)
  {
    const double value = phi(phi.nodeIndex(band[k]));
    if (std::fabs(value) <= par.Widths.Beta)
    {
      ++within;
      EXPECT_EQ(all[k], near[k]) << "node " << band[k];
      continue;
    }
    ++beyond;
    // What the first order leaves out: the spread's s^2 / r (s^2 = 2 c (d / E) eta d dt / p,
    // at most 0.08 dx here) and the interpolation's error.
    EXPECT_NEAR(near[k], all[k], 0.15 * dx) << "node " << band[k];
    linearised += near[k] != all[k] ? 1 : 0;
  }
  EXPECT_GT(within, 1000u);
  EXPECT_GT(beyond, 1000u);
  EXPECT_GT(linearised, beyond / 2); // not the feet's values
}

TEST(LevelSetStep, TheLinearisedStepIsExactForAPlaneMovedAlongItsNormal)
{
  // phi = x - 0.1 and d = 0.5 + x / 2: the feet's mean is phi(x0) exactly for a plane.
  const auto g = sltk::uniformBox<3>(21, -1.0, 1.0);
  const double dx = g.Spacing[0];
  const auto phi = sltk::sampleField(g, 2, [](const double* x) { return x[0] - 0.1; });
  const auto dist = sltk::sampleField(
    g, 1, [](const double* x) { return 0.5 + 0.5 * x[0]; }, sltk::GhostFill::Exact);
  sltk::LevelSetStepParameters par;
  par.TimeStep = dx;
  par.Eta = 0.3;
  par.Widths = sltk::BandWidths::forSpacing(dx);
  sltk::NodeList band;
  using Q1 = sltk::Q1Interpolator<3>;
  const auto feet = stepValuesOnBand<Q1>(phi, dist, par, std::numeric_limits<double>::infinity(), band);
  const auto linear = stepValuesOnBand<Q1>(phi, dist, par, 0.0, band);
  ASSERT_EQ(feet.size(), band.size());
  ASSERT_EQ(linear.size(), band.size());
  for (size_t k = 0; k < band.size(); ++k)
  {
    EXPECT_NEAR(linear[k], feet[k], 1e-12) << "node " << band[k];
  }
}
