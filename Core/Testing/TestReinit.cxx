// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/Reinitialise.h"

#include "sltk/exec/ThreadPool.h"
#include "sltk/grid/SampleField.h"
#include "sltk/levelset/ReinitInterface.h"
#include "sltk/levelset/ReinitScheme.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <vector>

namespace
{
using sltk::GridField;
using sltk::GridSpec;
using sltk::Index;
using sltk::ReinitMethod;
using sltk::ReinitOptions;
using sltk::ReinitScheme;

constexpr double Pi = 3.14159265358979323846;
constexpr double Radius = 0.5;
constexpr double BandCells = 5.0; // gamma + dx with gamma = 4 dx (4.4.6, (1.52))

/// Signed distance to the circle / sphere of radius Radius centred slightly off the grid nodes.
template <int D>
double sphereDistance(const double* x)
{
  double r2 = 0.0;
  for (int a = 0; a < D; ++a)
  {
    const double y = x[a] - 0.013 * (a + 1);
    r2 += y * y;
  }
  return std::sqrt(r2) - Radius;
}

/// Smooth positive distortion, between 0.7 and 2.5: phi0 = distortion * SDF
/// has |grad phi0| far from 1 and varying along the front.
template <int D>
double distortion(const double* x)
{
  double f = 1.6 + 0.9 * std::sin(3.0 * x[0] + 0.5) * std::cos(2.0 * x[1] - 0.3);
  if (D == 3)
  {
    f *= 1.0 + 0.15 * std::cos(2.5 * x[D - 1]);
  }
  return f;
}

template <int D>
GridField<D> distortedSphere(const GridSpec<D>& g)
{
  return sltk::sampleField(g, 1, [](const double* x) { return distortion<D>(x) * sphereDistance<D>(x); });
}

/// Test band: nodes within `cells` grid cells of the exact front.
template <int D>
std::vector<Index> sphereBand(const GridField<D>& u, double cells)
{
  const GridSpec<D>& g = u.spec();
  std::vector<Index> band;
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto x = sltktest::nodeCoordinates<D>(g, u.nodeIndex(k));
    if (std::fabs(sphereDistance<D>(x.data())) < cells * g.Spacing[0])
    {
      band.push_back(k);
    }
  }
  return band;
}

struct Deviation
{
  double Mean = 0.0;
  double Max = 0.0;
  Index Count = 0;
};

void accumulate(Deviation& d, double e)
{
  d.Mean += e;
  d.Max = std::max(d.Max, e);
  ++d.Count;
}

void finish(Deviation& d)
{
  d.Mean = d.Count > 0 ? d.Mean / double(d.Count) : 0.0;
}

/// ||grad phi| - 1| by central differences on the band nodes within `cells`
/// of the front (their stencils stay in the band) and away from the grid edge.
template <int D>
Deviation gradientDeviation(const GridField<D>& u, const std::vector<Index>& band, double cells)
{
  const GridSpec<D>& g = u.spec();
  Deviation d;
  for (Index k : band)
  {
    const auto i = u.nodeIndex(k);
    const auto x = sltktest::nodeCoordinates<D>(g, i);
    bool inner = std::fabs(sphereDistance<D>(x.data())) < cells * g.Spacing[0];
    for (int a = 0; a < D; ++a)
    {
      inner = inner && i[a] > 0 && i[a] < g.Dims[a] - 1;
    }
    if (!inner)
    {
      continue;
    }
    double sum = 0.0;
    for (int a = 0; a < D; ++a)
    {
      auto m = i;
      auto p = i;
      --m[a];
      ++p[a];
      const double gradient = (u(p) - u(m)) / (2.0 * g.Spacing[a]);
      sum += gradient * gradient;
    }
    accumulate(d, std::fabs(std::sqrt(sum) - 1.0));
  }
  finish(d);
  return d;
}

/// |phi - SDF| / dx over the band nodes within `cells` of the front.
template <int D>
Deviation distanceError(const GridField<D>& u, const std::vector<Index>& band, double cells)
{
  Deviation d;
  const double dx = u.spec().Spacing[0];
  for (Index k : band)
  {
    const auto i = u.nodeIndex(k);
    const auto x = sltktest::nodeCoordinates<D>(u.spec(), i);
    const double exact = sphereDistance<D>(x.data());
    if (std::fabs(exact) < cells * dx)
    {
      accumulate(d, std::fabs(u(i) - exact) / dx);
    }
  }
  finish(d);
  return d;
}

/// Displacement of the front, in cells: at every crossing of a grid edge by the
/// initial front (linear interpolation of `before` along the edge, as (1.40)),
/// |after| interpolated at that point, which is the distance from the point to
/// the new front since |grad after| ~ 1. Unlike comparing crossings edge by
/// edge, this does not jump by a cell when a node at 0.01 dx changes sign.
template <int D>
Deviation frontDisplacement(const GridField<D>& before, const GridField<D>& after)
{
  const GridSpec<D>& g = before.spec();
  Deviation d;
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = before.nodeIndex(k);
    for (int a = 0; a < D; ++a)
    {
      if (i[a] + 1 >= g.Dims[a])
      {
        continue;
      }
      auto j = i;
      ++j[a];
      if (!(before(i) * before(j) < 0.0))
      {
        continue;
      }
      const double t = before(i) / (before(i) - before(j));
      accumulate(d, std::fabs((1.0 - t) * after(i) + t * after(j)) / g.Spacing[0]);
    }
  }
  finish(d);
  return d;
}

/// Band nodes whose sign differs from the initial data.
template <int D>
Index signChanges(const GridField<D>& before, const GridField<D>& after, const std::vector<Index>& band)
{
  Index n = 0;
  for (Index k : band)
  {
    const auto i = before.nodeIndex(k);
    n += before(i) * after(i) < 0.0 ? 1 : 0;
  }
  return n;
}

/// Steady state to 1e-6 dx. The plain PDE does not reach it: its front keeps
/// drifting (by ~2e-3 dx per step here), so it stops after 40 steps, enough to
/// cross the band (5 cells at dtau = dx / 2) and settle it.
ReinitOptions options(ReinitMethod method, ReinitScheme scheme = ReinitScheme::Godunov)
{
  ReinitOptions o;
  o.Method = method;
  o.Scheme = scheme;
  o.MaxIterations = method == ReinitMethod::Plain ? 40 : 200;
  o.Tolerance = 1e-6;
  return o;
}

const char* name(ReinitMethod m)
{
  return m == ReinitMethod::Plain ? "plain" : (m == ReinitMethod::RussoSmereka ? "Russo-Smereka" : "constrained");
}

/// Inner band: |SDF| < gamma = 4 dx (4.4.6). The outer layer of the band has
/// larger errors: where the distortion is below 1 the values just outside the
/// band are smaller than the distance and act as upwind data (in Algorithm 1
/// the cut (1.49) that follows clamps that layer anyway).
constexpr double InnerCells = BandCells - 1.0;

struct Outcome
{
  Deviation Gradient;
  Deviation Error;      ///< whole band
  Deviation InnerError; ///< |SDF| < InnerCells dx
  Deviation Displacement;
  Index SignChanges = 0;
  sltk::ReinitReport Report;
};

/// Reinitialises the distorted circle/sphere on an n^D grid and measures it.
template <int D>
Outcome run(Index n, const ReinitOptions& o, const sltk::Context& ctx = sltk::Context())
{
  const auto g = sltk::uniformBox<D>(n, -1.0, 1.0);
  const GridField<D> initial = distortedSphere<D>(g);
  GridField<D> phi = initial;
  const auto band = sphereBand<D>(phi, BandCells);
  Outcome r;
  const sltk::Status st = sltk::reinitialise<D>(phi, band, o, ctx, &r.Report);
  EXPECT_TRUE(st.isOk()) << st.toString();
  // Central differences reach one node further: stay off the outer layer.
  r.Gradient = gradientDeviation<D>(phi, band, InnerCells - 1.0);
  r.Error = distanceError<D>(phi, band, BandCells);
  r.InnerError = distanceError<D>(phi, band, InnerCells);
  r.Displacement = frontDisplacement<D>(initial, phi);
  r.SignChanges = signChanges<D>(initial, phi, band);
  return r;
}
} // namespace

TEST(Reinit, SignApproximationAndGodunovStep)
{
  // (1.31): sign of phi0, magnitude below 1, about 1/sqrt(2) one cell from the front.
  EXPECT_EQ(sltk::reinitSign(0.0, 3.0, 0.1), 0.0);
  EXPECT_NEAR(sltk::reinitSign(0.3, 3.0, 0.1), 1.0 / std::sqrt(2.0), 1e-15);
  EXPECT_LT(sltk::reinitSign(-1e-3, 3.0, 0.1), 0.0);
  // A 1D kink phi = |x| - 1 sampled at x = 0 (u = -1, neighbours -0.9, -0.9):
  // outside the front s < 0 and the upwind differences see the slope 1 on both sides.
  const double inv[1] = { 10.0 };
  const double kink[3] = { -1.0, -0.9, -0.9 };
  EXPECT_NEAR(sltk::upwindGradientNorm<1>(ReinitScheme::Godunov, kink, inv, -1.0), 1.0, 1e-12);
  EXPECT_NEAR(sltk::upwindGradientNorm<1>(ReinitScheme::Upwind, kink, inv, -1.0), std::sqrt(2.0), 1e-12);
  // Positive side, slope 3 upwind (towards the front), slope 1 downwind: (1.35) uses 3.
  const double steep[3] = { 0.6, 0.3, 0.7 };
  EXPECT_NEAR(sltk::upwindGradientNorm<1>(ReinitScheme::Godunov, steep, inv, 1.0), 3.0, 1e-12);
  EXPECT_NEAR(sltk::reinitStep<1>(ReinitScheme::Godunov, steep, inv, 1.0, 0.05), 0.6 - 0.05 * 2.0, 1e-15);
}

namespace
{
/// (1.32)/(1.35) as written before the schemes became templates (branches,
/// an early return at s = 0): the reference the lanes are held to.
double referenceStep(ReinitScheme scheme, const double* u, const double* inv, double s, double dtau)
{
  if (s == 0.0)
  {
    return u[0];
  }
  double sum = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double minus = (u[0] - u[1 + 2 * axis]) * inv[axis];
    const double plus = (u[2 + 2 * axis] - u[0]) * inv[axis];
    const double left = (s > 0.0 ? !(minus <= 0.0) : !(minus >= 0.0)) ? minus : 0.0;
    const double right = (s > 0.0 ? !(plus >= 0.0) : !(plus <= 0.0)) ? plus : 0.0;
    const double l2 = left * left;
    const double r2 = right * right;
    sum += scheme == ReinitScheme::Godunov ? (l2 > r2 ? l2 : r2) : l2 + r2;
  }
  return u[0] - dtau * s * (std::sqrt(sum) - 1.0);
}

double referenceRelax(double u, double d, double courant)
{
  const double sign = d > 0.0 ? 1.0 : (d < 0.0 ? -1.0 : 0.0);
  return u - courant * (sign * std::fabs(u) - d);
}

bool sameBits(double a, double b)
{
  return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof(double)) == 0;
}

/// The schemes on L lanes against referenceStep / referenceRelax lane by lane.
template <int L>
int laneMismatches(ReinitScheme scheme, int trials)
{
  using Vec = sltk::lanes::Lanes<L>;
  const double special[] = { 0.0, -0.0, 1e-300, -1e-300, 0.3, -0.3, 1.0, std::nan(""), HUGE_VAL, -HUGE_VAL };
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> pick(0, 2 * static_cast<int>(std::size(special)));
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto draw = [&]
  {
    const int k = pick(rng);
    return k < static_cast<int>(std::size(special)) ? special[k] : uniform(rng);
  };
  const double inv[3] = { 10.0, 12.5, 8.0 };
  int mismatches = 0;
  for (int trial = 0; trial < trials; ++trial)
  {
    double u[7][L], s[L];
    for (int l = 0; l < L; ++l)
    {
      s[l] = draw();
      for (int c = 0; c < 7; ++c)
      {
        u[c][l] = draw();
      }
    }
    Vec uv[7], sv, next, relaxed;
    std::memcpy(uv, u, sizeof(uv));
    std::memcpy(&sv, s, sizeof(sv));
    sltk::reinitStep<3>(scheme, uv, inv, sv, 0.05, next);
    sltk::russoSmerekaStep(uv[0], sv, 0.5, relaxed);
    double got[L], gotRelaxed[L];
    std::memcpy(got, &next, sizeof(got));
    std::memcpy(gotRelaxed, &relaxed, sizeof(gotRelaxed));
    for (int l = 0; l < L; ++l)
    {
      double node[7];
      for (int c = 0; c < 7; ++c)
      {
        node[c] = u[c][l];
      }
      mismatches += sameBits(got[l], referenceStep(scheme, node, inv, s[l], 0.05)) ? 0 : 1;
      mismatches += sameBits(got[l], sltk::reinitStep<3>(scheme, node, inv, s[l], 0.05)) ? 0 : 1;
      mismatches += sameBits(gotRelaxed[l], referenceRelax(node[0], s[l], 0.5)) ? 0 : 1;
    }
  }
  return mismatches;
}
} // namespace

TEST(Reinit, SchemesInLanesAreTheBranchingSchemesBitForBit)
{
  // The pseudo-time steps run four (or two) band nodes at a time (Reinitialise.cxx): with NaN,
  // signed zeros, infinities and s = 0 among the values, every lane is the branching scheme's value.
  for (const ReinitScheme scheme : { ReinitScheme::Godunov, ReinitScheme::Upwind })
  {
    EXPECT_EQ(laneMismatches<4>(scheme, 20000), 0);
    EXPECT_EQ(laneMismatches<2>(scheme, 20000), 0);
  }
}

TEST(Reinit, InterfaceDistanceAtAThinFeature)
{
  // phi0 = 3 (|x| - 0.3 dx): a slab 0.6 dx thick around the node x = 0, whose
  // central difference is 0. (1.37) alone is unbounded there; the cap by the
  // edge crossings (ReinitInterface.h) gives the exact 0.3 dx. Off the slab the
  // data are linear and (1.37) is exact.
  const double dx = 0.1;
  const double inv[2] = { 1.0 / dx, 1.0 / dx };
  const double spacing[2] = { dx, dx };
  auto phi0 = [&](double x) { return 3.0 * (std::fabs(x) - 0.3 * dx); };
  double block[9];
  for (int c = 0; c < 9; ++c)
  {
    block[c] = phi0(dx * (c % 3 - 1)); // constant along y
  }
  EXPECT_TRUE(sltk::adjacentToInterface<2>(block));
  EXPECT_EQ(sltk::centralGradientNorm<2>(block, inv), 0.0);
  EXPECT_NEAR(sltk::interfaceDistance<2>(block, inv, spacing), -0.3 * dx, 1e-15);
  // The node x = dx next to it, with the linear branch on both sides: 0.7 dx.
  for (int c = 0; c < 9; ++c)
  {
    block[c] = phi0(dx * (c % 3));
  }
  EXPECT_NEAR(sltk::interfaceDistance<2>(block, inv, spacing), 0.7 * dx, 1e-15);
}

TEST(Reinit, ExplicitStepExactOnLinearData)
{
  // phi0 = 3 (n.x - c): (1.37) and (1.44) give the distance exactly, and the
  // PDE then reaches the linear SDF, the exact steady state of (1.35), on every
  // node whose upwind data lie in the grid: the front crosses the grid lines
  // through the node inside the grid. Elsewhere (the front leaves the grid
  // upwind) the values only have to stay finite (ReinitStencil::axes).
  const auto g = sltk::uniformBox<2>(41, -1.0, 1.0);
  const double n[2] = { 0.6, -0.8 };
  auto sdf = [&](const double* x) { return n[0] * x[0] + n[1] * x[1] - 0.1234; };
  const GridField<2> initial = sltk::sampleField(g, 1, [&](const double* x) { return 3.0 * sdf(x); });
  std::vector<Index> all(static_cast<size_t>(g.nodeCount()));
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    all[static_cast<size_t>(k)] = k;
  }
  for (int iterations : { 0, 400 })
  {
    GridField<2> phi = initial;
    ReinitOptions o = options(ReinitMethod::Constrained);
    o.MaxIterations = iterations;
    o.Tolerance = 1e-14;
    sltk::ReinitReport report;
    ASSERT_TRUE(sltk::reinitialise<2>(phi, all, o, sltk::Context(), &report).isOk());
    double frontError = 0.0;
    double dependentError = 0.0;
    double otherError = 0.0;
    Index dependent = 0;
    for (Index k = 0; k < g.nodeCount(); ++k)
    {
      const auto i = phi.nodeIndex(k);
      const auto x = sltktest::nodeCoordinates<2>(g, i);
      const double e = std::fabs(phi(i) - sdf(x.data()));
      bool inside = true;
      for (int a = 0; a < 2; ++a)
      {
        const double crossing = x[a] - sdf(x.data()) / n[a];
        inside = inside && crossing >= -1.0 && crossing <= 1.0;
      }
      ASSERT_TRUE(std::isfinite(phi(i)));
      if (std::fabs(sdf(x.data())) < 0.5 * g.Spacing[0])
      {
        frontError = std::max(frontError, e);
      }
      else if (inside)
      {
        dependentError = std::max(dependentError, e);
        ++dependent;
      }
      else
      {
        otherError = std::max(otherError, e);
      }
    }
    EXPECT_GT(report.InterfaceNodes, 0);
    EXPECT_LT(frontError, 1e-13) << "nodes next to the front, " << iterations << " steps";
    if (iterations > 0)
    {
      std::printf("linear front, whole grid as band, %d steps: max error %.1e on %lld nodes with upwind data in "
                  "the grid, %.2f dx elsewhere\n",
        report.Iterations, dependentError, static_cast<long long>(dependent), otherError / g.Spacing[0]);
      EXPECT_GT(dependent, g.nodeCount() / 3);
      EXPECT_LT(dependentError, 1e-10);
    }
  }
}

TEST(Reinit, CurvatureSplitsTheFrontNodes)
{
  // (1.45) with phi < 0 inside: convex front, kappa > 0, so R1 is the inside.
  const auto g = sltk::uniformBox<2>(41, -1.0, 1.0);
  const GridField<2> phi = distortedSphere<2>(g);
  const sltk::ReinitStencil<2> stencil(phi);
  const double inv[2] = { 1.0 / g.Spacing[0], 1.0 / g.Spacing[1] };
  int inside = 0;
  int outside = 0;
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    double block[9];
    const auto i = phi.nodeIndex(k);
    stencil.block(i, block);
    if (!sltk::adjacentToInterface<2>(block))
    {
      continue;
    }
    EXPECT_GT(sltk::curvatureNumerator<2>(block, inv), 0.0);
    EXPECT_EQ(sltk::inFirstSet<2>(block, inv), phi(i) < 0.0);
    (phi(i) < 0.0 ? inside : outside)++;
  }
  EXPECT_GT(inside, 20);
  EXPECT_GT(outside, 20);
}

TEST(Reinit, DistanceGradientAndFront2D)
{
  const Index n = 81;
  const auto g = sltk::uniformBox<2>(n, -1.0, 1.0);
  const GridField<2> initial = distortedSphere<2>(g);
  const auto band = sphereBand<2>(initial, BandCells);
  const Deviation start = gradientDeviation<2>(initial, band, InnerCells - 1.0);
  std::printf("2D circle, N = %lld, band %zu nodes; initial ||grad phi| - 1|: mean %.3f max %.3f\n",
    static_cast<long long>(n), band.size(), start.Mean, start.Max);
  Outcome out[3];
  const ReinitMethod methods[3] = { ReinitMethod::Plain, ReinitMethod::RussoSmereka, ReinitMethod::Constrained };
  for (int m = 0; m < 3; ++m)
  {
    out[m] = run<2>(n, options(methods[m]));
    std::printf("  %-13s %3d steps | ||grad|-1| mean %.2e max %.2e | |phi-SDF|/dx inner mean %.2e max %.2e, "
                "band max %.2e | front shift/dx mean %.2e max %.2e | %lld sign changes\n",
      name(methods[m]), out[m].Report.Iterations, out[m].Gradient.Mean, out[m].Gradient.Max, out[m].InnerError.Mean,
      out[m].InnerError.Max, out[m].Error.Max, out[m].Displacement.Mean, out[m].Displacement.Max,
      static_cast<long long>(out[m].SignChanges));
    EXPECT_TRUE(out[m].Report.Converged || methods[m] == ReinitMethod::Plain);
    EXPECT_LT(out[m].Gradient.Mean, 0.1 * start.Mean);
    EXPECT_LT(out[m].Gradient.Max, 0.1);
    EXPECT_LT(out[m].InnerError.Max, 0.2);
    EXPECT_LT(out[m].Error.Max, 0.5);
  }
  EXPECT_LT(out[2].InnerError.Max, 0.1);
  const Deviation& plain = out[0].Displacement;
  const Deviation& constrained = out[2].Displacement;
  // The front stays put to a small fraction of a cell, far better than with the plain PDE.
  EXPECT_LT(constrained.Max, 0.05);
  EXPECT_LT(constrained.Mean, 0.5 * plain.Mean);
  EXPECT_LT(constrained.Max, 0.5 * plain.Max);
  EXPECT_LT(out[2].InnerError.Mean, out[0].InnerError.Mean);
  EXPECT_EQ(out[2].SignChanges, 0);
}

TEST(Reinit, ConvergenceUnderRefinement2D)
{
  // Error of the steady state against the exact SDF in a band of a fixed number
  // of cells: first order per cell crossed, hence about dx^2 over the band.
  constexpr int Levels = 4;
  const Index sizes[Levels] = { 41, 81, 161, 321 };
  for (ReinitMethod method : { ReinitMethod::Plain, ReinitMethod::Constrained })
  {
    double mean[Levels];
    double max[Levels];
    double shift[Levels];
    double gradient[Levels];
    for (int r = 0; r < Levels; ++r)
    {
      const Outcome o = run<2>(sizes[r], options(method));
      const double dx = 2.0 / double(sizes[r] - 1);
      mean[r] = o.InnerError.Mean * dx;
      max[r] = o.InnerError.Max * dx;
      shift[r] = o.Displacement.Max * dx;
      gradient[r] = o.Gradient.Mean;
      auto order = [&](const double* e) { return r > 0 ? std::log2(e[r - 1] / e[r]) : 0.0; };
      std::printf("2D %-11s N = %3lld: inner |phi - SDF| mean %.3e (order %5.2f) max %.3e (order %5.2f), band max "
                  "%.3e | front shift max %.2e (order %5.2f) | ||grad|-1| mean %.2e max %.2e\n",
        name(method), static_cast<long long>(sizes[r]), mean[r], order(mean), max[r], order(max), o.Error.Max * dx,
        shift[r], order(shift), o.Gradient.Mean, o.Gradient.Max);
      if (r > 0)
      {
        EXPECT_GT(order(mean), 1.5);
        EXPECT_GT(order(max), 1.5);
        EXPECT_GT(order(gradient), 0.8); // |grad phi| - 1: first order
        if (method == ReinitMethod::Constrained)
        {
          EXPECT_GT(order(shift), 1.5);
        }
      }
    }
  }
}

TEST(Reinit, UpwindAndGodunovSchemes2D)
{
  // (1.32) and (1.35) differ only where both one-sided differences along an axis
  // are upwind (phi has an extremum along the grid line: here inside the circle,
  // on the lines through its centre); there (1.32) adds both and overestimates |grad phi|.
  const auto g = sltk::uniformBox<2>(81, -1.0, 1.0);
  const GridField<2> initial = distortedSphere<2>(g);
  const auto band = sphereBand<2>(initial, BandCells);
  GridField<2> phi[2] = { initial, initial };
  const ReinitScheme schemes[2] = { ReinitScheme::Godunov, ReinitScheme::Upwind };
  for (int m = 0; m < 2; ++m)
  {
    sltk::ReinitReport report;
    ASSERT_TRUE(
      sltk::reinitialise<2>(phi[m], band, options(ReinitMethod::Constrained, schemes[m]), sltk::Context(), &report)
        .isOk());
    EXPECT_TRUE(report.Converged);
  }
  Deviation error[2];
  for (Index k : band)
  {
    const auto i = initial.nodeIndex(k);
    if (phi[0](i) == phi[1](i))
    {
      continue;
    }
    const auto x = sltktest::nodeCoordinates<2>(g, i);
    for (int m = 0; m < 2; ++m)
    {
      accumulate(error[m], std::fabs(phi[m](i) - sphereDistance<2>(x.data())) / g.Spacing[0]);
    }
  }
  finish(error[0]);
  finish(error[1]);
  std::printf("2D N = 81 constrained, on the %lld nodes where the schemes differ: |phi-SDF|/dx Godunov (1.35) mean "
              "%.2e max %.2e, upwind (1.32) mean %.2e max %.2e\n",
    static_cast<long long>(error[0].Count), error[0].Mean, error[0].Max, error[1].Mean, error[1].Max);
  EXPECT_GT(error[0].Count, 10);
  EXPECT_LT(error[0].Mean, 0.8 * error[1].Mean);
  EXPECT_LT(error[1].Max, 0.5);
}

TEST(Reinit, DistanceGradientAndFront3D)
{
  const Index sizes[2] = { 33, 65 };
  Outcome out[2][2];
  const ReinitMethod methods[2] = { ReinitMethod::Plain, ReinitMethod::Constrained };
  for (int m = 0; m < 2; ++m)
  {
    for (int r = 0; r < 2; ++r)
    {
      const Outcome& o = out[m][r] = run<3>(sizes[r], options(methods[m]));
      const double dx = 2.0 / double(sizes[r] - 1);
      // Errors in cells: the order in absolute terms is 1 + log2 of the ratio in cells.
      const double orderMean = r > 0 ? 1.0 + std::log2(out[m][0].InnerError.Mean / o.InnerError.Mean) : 0.0;
      const double orderMax = r > 0 ? 1.0 + std::log2(out[m][0].InnerError.Max / o.InnerError.Max) : 0.0;
      std::printf("3D sphere %-11s N = %2lld, %3d steps: ||grad|-1| mean %.2e max %.2e | inner |phi-SDF| mean %.3e "
                  "(order %.2f) max %.3e (order %.2f), band max %.3e | front shift/dx mean %.2e max %.2e | %lld sign "
                  "changes\n",
        name(methods[m]), static_cast<long long>(sizes[r]), o.Report.Iterations, o.Gradient.Mean, o.Gradient.Max,
        o.InnerError.Mean * dx, orderMean, o.InnerError.Max * dx, orderMax, o.Error.Max * dx, o.Displacement.Mean,
        o.Displacement.Max, static_cast<long long>(o.SignChanges));
      EXPECT_TRUE(o.Report.Converged || methods[m] == ReinitMethod::Plain);
      EXPECT_LT(o.Gradient.Mean, 0.05);
      EXPECT_LT(o.InnerError.Max, 0.6);
      EXPECT_LT(o.Error.Max, 0.75);
      if (r > 0)
      {
        EXPECT_GT(orderMean, 1.5);
        EXPECT_GT(orderMax, 1.5);
      }
    }
  }
  for (int r = 0; r < 2; ++r)
  {
    const Outcome& plain = out[0][r];
    const Outcome& constrained = out[1][r];
    EXPECT_LT(constrained.InnerError.Max, 0.35);
    EXPECT_LT(constrained.InnerError.Max, 0.7 * plain.InnerError.Max);
    EXPECT_LT(constrained.Displacement.Max, 0.05);
    EXPECT_LT(constrained.Displacement.Mean, 0.5 * plain.Displacement.Mean);
    EXPECT_LT(constrained.Displacement.Max, 0.5 * plain.Displacement.Max);
    EXPECT_EQ(constrained.SignChanges, 0);
  }
}

TEST(Reinit, OnlyBandNodesAreWritten)
{
  const auto g = sltk::uniformBox<3>(33, -1.0, 1.0);
  GridField<3> phi = distortedSphere<3>(g);
  const GridField<3> initial = phi;
  const auto band = sphereBand<3>(phi, BandCells);
  std::vector<char> inBand(phi.storage().size(), 0);
  for (Index k : band)
  {
    inBand[static_cast<size_t>(phi.offset(phi.nodeIndex(k)))] = 1;
  }
  ASSERT_TRUE(sltk::reinitialise<3>(phi, band, options(ReinitMethod::Constrained), sltk::Context()).isOk());
  size_t changedInside = 0;
  for (size_t s = 0; s < phi.storage().size(); ++s)
  {
    if (inBand[s])
    {
      changedInside += phi.storage()[s] != initial.storage()[s] ? 1 : 0;
    }
    else
    {
      // Nodes outside the band and ghost layers: bit for bit.
      ASSERT_EQ(std::memcmp(&phi.storage()[s], &initial.storage()[s], sizeof(double)), 0) << "storage " << s;
    }
  }
  EXPECT_GT(changedInside, band.size() / 2);
}

TEST(Reinit, SerialAndThreadedAreBitIdentical)
{
  const auto g = sltk::uniformBox<3>(65, -1.0, 1.0);
  const GridField<3> initial = distortedSphere<3>(g);
  const auto band = sphereBand<3>(initial, BandCells);
  ASSERT_GT(band.size(), 8u * 2048u); // several chunks
  for (ReinitMethod method : { ReinitMethod::Plain, ReinitMethod::RussoSmereka, ReinitMethod::Constrained })
  {
    GridField<3> serial = initial;
    GridField<3> threaded = initial;
    ReinitOptions o = options(method);
    o.MaxIterations = 30;
    sltk::ReinitReport a;
    sltk::ReinitReport b;
    ASSERT_TRUE(sltk::reinitialise<3>(serial, band, o, sltk::Context(), &a).isOk());
    sltk::ThreadPool pool(4);
    sltk::Context ctx;
    ctx.Executor = &pool;
    ASSERT_TRUE(sltk::reinitialise<3>(threaded, band, o, ctx, &b).isOk());
    EXPECT_EQ(a.Iterations, b.Iterations);
    EXPECT_EQ(a.InterfaceNodes, b.InterfaceNodes);
    EXPECT_EQ(
      std::memcmp(serial.storage().data(), threaded.storage().data(), serial.storage().size() * sizeof(double)), 0)
      << name(method);
  }
}

TEST(Reinit, AReusedWorkspaceGivesTheValuesOfAFreshOneBitForBit)
{
  // A run keeps one workspace for all its iterations (SlabBand.h); what a call
  // left in it (a larger or a smaller band, another grid, an interrupted call)
  // must not show in the next one: the values, the report's last change and
  // its convergence as a call with its own arrays gives them. The tight box
  // puts band nodes on the grid's faces (the node-by-node path). Keeping a
  // stale role where the classification should write one makes it fail.
  const auto wide = sltk::uniformBox<3>(49, -1.0, 1.0);
  const auto tight = sltk::uniformBox<3>(33, -0.55, 0.55);
  struct Case
  {
    GridField<3> Initial;
    std::vector<Index> Band;
  };
  const auto makeCase = [](const GridSpec<3>& g, double cells)
  {
    Case c{ distortedSphere<3>(g), {} };
    c.Band = sphereBand<3>(c.Initial, cells);
    return c;
  };
  const Case large = makeCase(wide, BandCells);
  const Case small = makeCase(tight, 3.0);
  ASSERT_NE(large.Band.size(), small.Band.size());
  sltk::ThreadPool pool(2);
  sltk::Context ctx;
  ctx.Executor = &pool;
  const auto run = [&](const Case& c, const ReinitOptions& o, const sltk::Context& context,
                     sltk::ReinitWorkspace* workspace, GridField<3>& phi, sltk::ReinitReport& report)
  {
    phi = c.Initial;
    return sltk::reinitialise<3>(
      phi, c.Band.data(), static_cast<Index>(c.Band.size()), o, context, &report, {}, workspace);
  };
  for (ReinitMethod method : { ReinitMethod::Plain, ReinitMethod::RussoSmereka, ReinitMethod::Constrained })
  {
    const ReinitOptions o = options(method);
    for (const Case* order : { &large, &small })
    {
      sltk::ReinitWorkspace workspace;
      GridField<3> phi;
      sltk::ReinitReport first;
      ASSERT_TRUE(run(order == &small ? large : small, o, ctx, &workspace, phi, first).isOk());
      GridField<3> fresh, reused;
      sltk::ReinitReport a, b;
      ASSERT_TRUE(run(*order, o, ctx, nullptr, fresh, a).isOk());
      ASSERT_TRUE(run(*order, o, ctx, &workspace, reused, b).isOk());
      EXPECT_EQ(a.Iterations, b.Iterations);
      EXPECT_EQ(a.InterfaceNodes, b.InterfaceNodes);
      EXPECT_EQ(std::memcmp(&a.MaxChange, &b.MaxChange, sizeof(double)), 0);
      EXPECT_EQ(a.Converged, b.Converged);
      EXPECT_EQ(
        std::memcmp(fresh.storage().data(), reused.storage().data(), fresh.storage().size() * sizeof(double)), 0)
        << name(method) << (order == &small ? ", after the larger band" : ", after the smaller band");
    }
  }
  // A call interrupted after two steps leaves the workspace usable.
  struct StopAtSecond : sltk::Interrupter
  {
    int Calls = 0;
    bool wasInterrupted(double) override { return ++this->Calls >= 2; }
  } stop;
  sltk::Context stopping = ctx;
  stopping.Progress = &stop;
  sltk::ReinitWorkspace workspace;
  GridField<3> phi, fresh;
  sltk::ReinitReport a, b;
  const ReinitOptions o = options(ReinitMethod::Constrained);
  ASSERT_EQ(run(large, o, stopping, &workspace, phi, a).code(), sltk::StatusCode::Aborted);
  ASSERT_TRUE(run(small, o, ctx, &workspace, phi, a).isOk());
  ASSERT_TRUE(run(small, o, ctx, nullptr, fresh, b).isOk());
  EXPECT_EQ(std::memcmp(fresh.storage().data(), phi.storage().data(), fresh.storage().size() * sizeof(double)), 0);
}

TEST(Reinit, BandNodesInLanesAreTheNodeByNodeValuesBitForBit)
{
  // The band's nodes are stepped four (or two) at a time, and a group with a node next to the
  // grid's end node by node (Reinitialise.cxx). Interleaving a node of the grid's faces after every
  // three nodes of the band (far from it, so no band node reads it) sends every group node by
  // node: the band's values must be the lanes' bit for bit, for the three methods, after the
  // classification alone (which the interleaving must not disturb) and after five steps.
  const auto g = sltk::uniformBox<3>(41, -1.0, 1.0);
  const GridField<3> initial = distortedSphere<3>(g);
  const auto band = sphereBand<3>(initial, 3.0);
  std::vector<Index> faces;
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = initial.nodeIndex(k);
    if (std::any_of(i.begin(), i.end(), [&](Index c) { return c == 0 || c == g.Dims[0] - 1; }))
    {
      faces.push_back(k);
    }
  }
  ASSERT_GT(3 * faces.size(), band.size()) << "a face node for every three band nodes";
  // The band with the middle two of every four nodes swapped: groups of nodes that lie in a row of
  // storage but out of order must be gathered, not loaded (the lanes' plain loads).
  std::vector<Index> swapped = band;
  for (size_t j = 0; j + 3 < swapped.size(); j += 4)
  {
    std::swap(swapped[j + 1], swapped[j + 2]);
  }
  std::vector<Index> interleaved;
  for (size_t j = 0; j < band.size(); ++j)
  {
    interleaved.push_back(band[j]);
    if (j % 3 == 2)
    {
      interleaved.push_back(faces[j / 3]);
    }
  }
  for (ReinitMethod method : { ReinitMethod::Plain, ReinitMethod::RussoSmereka, ReinitMethod::Constrained })
  {
    for (int steps : { 0, 5 })
    {
      GridField<3> inLanes = initial;
      GridField<3> nodeByNode = initial;
      GridField<3> outOfOrder = initial;
      ReinitOptions o = options(method);
      o.MaxIterations = steps;
      o.Tolerance = 0.0;
      sltk::ReinitReport a, b, c;
      ASSERT_TRUE(sltk::reinitialise<3>(inLanes, band, o, sltk::Context(), &a).isOk());
      ASSERT_TRUE(sltk::reinitialise<3>(nodeByNode, interleaved, o, sltk::Context(), &b).isOk());
      ASSERT_TRUE(sltk::reinitialise<3>(outOfOrder, swapped, o, sltk::Context(), &c).isOk());
      EXPECT_EQ(a.InterfaceNodes, b.InterfaceNodes) << name(method);
      size_t differ = 0, differOutOfOrder = 0, moved = 0;
      for (Index k : band)
      {
        const double x = inLanes(inLanes.nodeIndex(k)), y = nodeByNode(nodeByNode.nodeIndex(k));
        const double z = outOfOrder(outOfOrder.nodeIndex(k));
        differ += std::memcmp(&x, &y, sizeof(double)) != 0 ? 1 : 0;
        differOutOfOrder += std::memcmp(&z, &y, sizeof(double)) != 0 ? 1 : 0;
        moved += x != initial(initial.nodeIndex(k)) ? 1 : 0;
      }
      EXPECT_EQ(differ, 0u) << name(method) << ", " << steps << " steps";
      EXPECT_EQ(differOutOfOrder, 0u) << name(method) << ", " << steps << " steps, the band out of order";
      if (steps > 0 || method == ReinitMethod::Constrained) // else nothing is written
      {
        EXPECT_GT(moved, band.size() / 20) << name(method) << ", " << steps << " steps";
      }
    }
  }
}

TEST(Reinit, PeriodicAndExtrapolatedBoundaries)
{
  // A front x = x0 crossing a periodic y axis; the band reaches the x ends of the
  // grid (linear extrapolation). phi0 = (x - x0)(1.5 + 0.5 sin(2 pi y / L)).
  GridSpec<2> g;
  g.Dims = { 25, 32 };
  g.Origin = { 0.0, 0.0 };
  g.Spacing = { 1.0 / 24.0, 1.0 / 32.0 };
  g.Bounds = { sltk::Boundary::Extrapolate, sltk::Boundary::Periodic };
  const double x0 = 0.4321;
  GridField<2> phi =
    sltk::sampleField(g, 0, [&](const double* x) { return (x[0] - x0) * (1.5 + 0.5 * std::sin(2.0 * Pi * x[1])); });
  std::vector<Index> all(static_cast<size_t>(g.nodeCount()));
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    all[static_cast<size_t>(k)] = k;
  }
  ReinitOptions o = options(ReinitMethod::Constrained);
  o.Tolerance = 1e-12;
  o.MaxIterations = 400;
  sltk::ReinitReport report;
  ASSERT_TRUE(sltk::reinitialise<2>(phi, all, o, sltk::Context(), &report).isOk());
  EXPECT_TRUE(report.Converged);
  double error = 0.0;
  for (Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    error = std::max(error, std::fabs(phi(i) - (g.coordinate(0, i[0]) - x0)));
  }
  // Front nodes: (1.37) sees the y-variation of the distortion through the central
  // gradient only at O(dx^2); elsewhere the Godunov solution of a planar front is exact.
  std::printf("planar front, periodic y, whole grid as band: max |phi - SDF| = %.2e (dx = %.3f), %d steps\n", error,
    g.Spacing[0], report.Iterations);
  EXPECT_LT(error, 0.02 * g.Spacing[0]);
}

TEST(Reinit, RejectsInvalidInput)
{
  const auto g = sltk::uniformBox<2>(11, -1.0, 1.0);
  GridField<2> phi = distortedSphere<2>(g);
  const GridField<2> initial = phi;
  std::vector<Index> band = { 3, 4, g.nodeCount() };
  EXPECT_EQ(
    sltk::reinitialise<2>(phi, band, ReinitOptions(), sltk::Context()).code(), sltk::StatusCode::InvalidArgument);
  band = { 3, 4 };
  ReinitOptions o;
  o.Courant = 0.8; // above 1/sqrt(2)
  EXPECT_EQ(sltk::reinitialise<2>(phi, band, o, sltk::Context()).code(), sltk::StatusCode::InvalidArgument);
  o = ReinitOptions();
  o.Scheme = ReinitScheme::Upwind; // monotone up to 1/sqrt(2D): 0.5 in 2D, not in 3D
  EXPECT_TRUE(sltk::reinitialise<2>(phi, band, o, sltk::Context()).isOk());
  EXPECT_EQ(o.validate<3>().code(), sltk::StatusCode::InvalidArgument);
  o.Courant = 0.4;
  EXPECT_TRUE(o.validate<3>().isOk());
  phi = initial;
  o = ReinitOptions();
  o.MaxIterations = -1;
  EXPECT_EQ(sltk::reinitialise<2>(phi, band, o, sltk::Context()).code(), sltk::StatusCode::InvalidArgument);
  EXPECT_EQ(phi.storage(), initial.storage());
  EXPECT_TRUE(sltk::reinitialise<2>(phi, nullptr, 0, ReinitOptions(), sltk::Context()).isOk());
}

TEST(Reinit, ReportsAbortAndNonFiniteValues)
{
  const auto g = sltk::uniformBox<2>(41, -1.0, 1.0);
  const GridField<2> initial = distortedSphere<2>(g);
  const auto band = sphereBand<2>(initial, BandCells);

  // The interrupter is asked once per step and stops the third.
  struct StopAtThird : sltk::Interrupter
  {
    int Calls = 0;
    bool wasInterrupted(double) override { return ++this->Calls >= 3; }
  } stop;
  sltk::Context ctx;
  ctx.Progress = &stop;
  GridField<2> phi = initial;
  sltk::ReinitReport report;
  EXPECT_EQ(sltk::reinitialise<2>(phi, band, options(ReinitMethod::Constrained), ctx, &report).code(),
    sltk::StatusCode::Aborted);
  EXPECT_EQ(report.Iterations, 3);
  EXPECT_FALSE(report.Converged);

  // A NaN next to the band spreads into it: reported, not hidden.
  phi = initial;
  std::array<Index, 2> hole{};
  for (Index k : band)
  {
    hole = phi.nodeIndex(k);
  }
  ++hole[0];
  phi(hole) = std::nan("");
  EXPECT_EQ(sltk::reinitialise<2>(phi, band, options(ReinitMethod::Plain), sltk::Context(), &report).code(),
    sltk::StatusCode::NumericalFailure);
  EXPECT_EQ(report.Iterations, 1);
}

TEST(Reinit, SkewedStepsAreThePlainStepsBitForBit)
{
  // One process steps a large band in skewed rounds (SkewedSteps.h): step t of a plane runs
  // after step t - 1 of its neighbouring planes, not after the whole band's. The values, the
  // steps done, the last largest change and the convergence must be the plain steps' bit for
  // bit: with rounds of 10 steps, with a tolerance stop inside a round (its steps again from
  // the kept band), on one thread and on three, in 2D and 3D, and when a band out of order
  // or a periodic slowest axis sends the call to the plain steps.
  sltk::ThreadPool pool(3);
  sltk::Context threaded;
  threaded.Executor = &pool;
  const auto compare = [&](auto initial, const std::vector<Index>& band, ReinitOptions o, const char* what)
  {
    for (const bool onThreads : { true, false })
    {
      const sltk::Context context = onThreads ? threaded : sltk::Context();
      auto plain = initial;
      auto skewed = initial;
      sltk::ReinitWorkspace plainArrays, skewedArrays;
      plainArrays.SkewedBandNodes = std::numeric_limits<Index>::max();
      skewedArrays.SkewedBandNodes = 0;
      sltk::ReinitReport a, b;
      const Index n = static_cast<Index>(band.size());
      const sltk::Status plainStatus = sltk::reinitialise(plain, band.data(), n, o, context, &a, {}, &plainArrays);
      const sltk::Status skewedStatus = sltk::reinitialise(skewed, band.data(), n, o, context, &b, {}, &skewedArrays);
      EXPECT_EQ(plainStatus.code(), skewedStatus.code()) << what;
      EXPECT_EQ(plainStatus.message(), skewedStatus.message()) << what;
      EXPECT_EQ(a.Iterations, b.Iterations) << what;
      EXPECT_EQ(a.Converged, b.Converged) << what;
      EXPECT_EQ(a.InterfaceNodes, b.InterfaceNodes) << what;
      EXPECT_EQ(std::memcmp(&a.MaxChange, &b.MaxChange, sizeof(double)), 0) << what;
      EXPECT_EQ(
        std::memcmp(plain.storage().data(), skewed.storage().data(), plain.storage().size() * sizeof(double)), 0)
        << what << (onThreads ? ", three threads" : ", one thread");
    }
  };
  const auto g3 = sltk::uniformBox<3>(49, -1.0, 1.0);
  const GridField<3> sphere = distortedSphere<3>(g3);
  const auto band3 = sphereBand<3>(sphere, BandCells);
  ReinitOptions o = options(ReinitMethod::Constrained);
  o.MaxIterations = 10;
  compare(sphere, band3, o, "10 steps, one round");
  o.MaxIterations = 23;
  compare(sphere, band3, o, "23 steps, rounds of 10, 10 and 3");
  // The plain steps stop on the tolerance after some 25-60 steps: inside a round.
  o = options(ReinitMethod::Constrained);
  o.Tolerance = 1e-3;
  GridField<3> probe = sphere;
  sltk::ReinitReport stop;
  ASSERT_TRUE(sltk::reinitialise<3>(probe, band3, o, sltk::Context(), &stop).isOk());
  ASSERT_TRUE(stop.Converged);
  ASSERT_GT(stop.Iterations, 11);
  compare(sphere, band3, o, "a tolerance stop");
  o.Method = ReinitMethod::Plain;
  o.MaxIterations = 17;
  compare(sphere, band3, o, "plain method, 17 steps");
  // Planes of more than 1,024 band nodes make groups of one plane, where a lag of 2 races (a
  // SkewLag of 2 makes this case fail).
  const auto g81 = sltk::uniformBox<3>(81, -1.0, 1.0);
  const GridField<3> fine = distortedSphere<3>(g81);
  o = options(ReinitMethod::Constrained);
  o.MaxIterations = 10;
  compare(fine, sphereBand<3>(fine, BandCells), o, "planes of over 1,024 nodes");
  // A NaN next to the band (a node of its last plane) spreads into it: the same failure at the
  // same step, phi at that step's values.
  GridField<3> holed = sphere;
  std::array<Index, 3> hole = holed.nodeIndex(band3.back());
  ++hole[0];
  holed(hole) = std::nan("");
  o.Method = ReinitMethod::Plain;
  GridField<3> failed = holed;
  sltk::ReinitReport failure;
  ASSERT_EQ(sltk::reinitialise<3>(failed, band3, o, sltk::Context(), &failure).code(),
    sltk::StatusCode::NumericalFailure);
  ASSERT_LT(failure.Iterations, o.MaxIterations); // within the first round
  compare(holed, band3, o, "a non-finite value");

  const auto g2 = sltk::uniformBox<2>(801, -1.0, 1.0);
  const GridField<2> circle = distortedSphere<2>(g2);
  const auto band2 = sphereBand<2>(circle, BandCells);
  o = options(ReinitMethod::Constrained);
  o.MaxIterations = 30;
  compare(circle, band2, o, "2D, 30 steps");
  o.Tolerance = 1e-3;
  compare(circle, band2, o, "2D, a tolerance stop");

  // Out of order, or periodic along the slowest axis: the plain steps (the same values anyway).
  std::vector<Index> reversed(band3.rbegin(), band3.rend());
  o = options(ReinitMethod::Constrained);
  o.MaxIterations = 12;
  compare(sphere, reversed, o, "a band in reverse order");
  GridSpec<3> periodic = g3;
  periodic.Bounds[2] = sltk::Boundary::Periodic;
  // Two fronts at |z| = 0.85 whose band reaches both ends of z: its steps read across them.
  const auto slab = [](const double* x) { return distortion<3>(x) * (0.85 - std::fabs(x[2])); };
  GridField<3> wrapped = sltk::sampleField(periodic, 1, slab);
  std::vector<Index> across;
  for (Index k = 0; k < periodic.nodeCount(); ++k)
  {
    const auto x = sltktest::nodeCoordinates<3>(periodic, wrapped.nodeIndex(k));
    if (std::fabs(0.85 - std::fabs(x[2])) < BandCells * periodic.Spacing[2])
    {
      across.push_back(k);
    }
  }
  ASSERT_EQ(across.front(), 0);
  compare(wrapped, across, o, "periodic along z");
}
