// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/ThreadPool.h"
#include "sltk/levelset/CutOff.h"
#include "sltk/levelset/NarrowBand.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// Signed distance to the sphere of radius r centred at c.
template <int D>
sltk::GridField<D, double> sphereSdf(const sltk::GridSpec<D>& g, double r, double shift = 0.0)
{
  sltk::GridField<D, double> phi(g, 1);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    double s = 0.0;
    for (int a = 0; a < D; ++a)
    {
      const double x = g.coordinate(a, i[a]) - (a == 0 ? shift : 0.0);
      s += x * x;
    }
    phi(i) = std::sqrt(s) - r;
  }
  return phi;
}
} // namespace

TEST(NarrowBand, CutOffValuesOfPengEtAl)
{
  const double dx = 0.1;
  const auto w = sltk::BandWidths::forSpacing(dx); // beta = 2 dx, gamma = 4 dx (4.4.6)
  EXPECT_DOUBLE_EQ(w.Beta, 0.2);
  EXPECT_DOUBLE_EQ(w.Gamma, 0.4);
  EXPECT_EQ(sltk::cutOff(0.0, w), 1.0);
  EXPECT_EQ(sltk::cutOff(0.2, w), 1.0);
  EXPECT_EQ(sltk::cutOff(-0.2, w), 1.0);
  EXPECT_NEAR(sltk::cutOff(0.4, w), 0.0, 1e-15);
  EXPECT_EQ(sltk::cutOff(0.41, w), 0.0);
  // (1.55) at |phi| = 3 dx: (dx)^2 (6 dx + 4 dx - 6 dx) / (2 dx)^3 = 1/2.
  EXPECT_NEAR(sltk::cutOff(0.3, w), 0.5, 1e-14);
  EXPECT_NEAR(sltk::cutOff(-0.3, w), 0.5, 1e-14);
  // at |phi| = 2.5 dx: (1.5)^2 (5 + 4 - 6) / 8 = 0.84375.
  EXPECT_NEAR(sltk::cutOff(0.25, w), 0.84375, 1e-14);
}

TEST(NarrowBand, CutOffIsC1AndMonotone)
{
  const double beta = 2.0;
  const double gamma = 4.0;
  const double h = 1e-6;
  for (double x : { beta, gamma })
  {
    // One-sided slopes on both sides of the junctions vanish (C1), values match (C0).
    const double left = (sltk::cutOff(x, beta, gamma) - sltk::cutOff(x - h, beta, gamma)) / h;
    const double right = (sltk::cutOff(x + h, beta, gamma) - sltk::cutOff(x, beta, gamma)) / h;
    EXPECT_NEAR(left, 0.0, 1e-5) << x;
    EXPECT_NEAR(right, 0.0, 1e-5) << x;
    EXPECT_NEAR(sltk::cutOff(x - 1e-12, beta, gamma), sltk::cutOff(x + 1e-12, beta, gamma), 1e-10);
  }
  double previous = 1.0;
  for (double x = 0.0; x < 5.0; x += 0.01)
  {
    const double c = sltk::cutOff(x, beta, gamma);
    EXPECT_LE(c, previous + 1e-15);
    EXPECT_GE(c, 0.0);
    previous = c;
  }
  EXPECT_EQ(sltk::cutLevel(-7.0, 4.0), -4.0);
  EXPECT_EQ(sltk::cutLevel(7.0, 4.0), 4.0);
  EXPECT_EQ(sltk::cutLevel(1.5, 4.0), 1.5);
}

TEST(NarrowBand, BandOfACircleHasExactlyTheNodesWithinGamma)
{
  const auto g = sltk::uniformBox<2>(61, -1.5, 1.5);
  const auto phi = sphereSdf<2>(g, 0.8);
  const double gamma = 4.0 * g.Spacing[0];
  sltk::NodeList band;
  sltk::collectBand(phi, gamma, sltk::Context{}, band);
  sltk::NodeList expected;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    const double r = std::hypot(g.coordinate(0, i[0]), g.coordinate(1, i[1]));
    if (std::fabs(r - 0.8) < gamma)
    {
      expected.push_back(k);
    }
  }
  EXPECT_EQ(band, expected);
  // About 2 gamma * length / dx^2 nodes.
  const double estimate = 2.0 * gamma * 2.0 * M_PI * 0.8 / (g.Spacing[0] * g.Spacing[0]);
  EXPECT_NEAR(static_cast<double>(band.size()), estimate, 0.05 * estimate);
}

TEST(NarrowBand, SphereBandIdenticalWithThreads)
{
  const auto g = sltk::uniformBox<3>(41, -1.2, 1.2);
  const auto phi = sphereSdf<3>(g, 0.7);
  sltk::NodeList serial;
  sltk::NodeList threaded;
  const double gamma = 4.0 * g.Spacing[0];
  sltk::collectBand(phi, gamma, sltk::Context{}, serial);
  sltk::ThreadPool pool(3);
  sltk::Context ctx;
  ctx.Executor = &pool;
  sltk::collectBand(phi, gamma, ctx, threaded);
  EXPECT_EQ(serial, threaded);
  ASSERT_FALSE(serial.empty());
  for (const sltk::Index k : serial)
  {
    EXPECT_LT(std::fabs(phi(phi.nodeIndex(k))), gamma);
  }
  EXPECT_TRUE(std::is_sorted(serial.begin(), serial.end()));
  // Complement: every node not listed is outside.
  size_t listed = 0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    listed += std::fabs(phi(phi.nodeIndex(k))) < gamma ? 1 : 0;
  }
  EXPECT_EQ(listed, serial.size());
}

TEST(NarrowBand, DilationMatchesBruteForce)
{
  const auto g = sltk::uniformBox<2>(31, -1.0, 1.0);
  const auto phi = sphereSdf<2>(g, 0.5);
  sltk::NodeList band;
  sltk::collectBand(phi, 2.0 * g.Spacing[0], sltk::Context{}, band);
  for (int k : { 1, 2, 3 })
  {
    sltk::NodeList dilated;
    sltk::dilateBand(g, band, k, sltk::Context{}, dilated);
    sltk::NodeList expected;
    for (sltk::Index n = 0; n < g.nodeCount(); ++n)
    {
      const auto i = phi.nodeIndex(n);
      bool near = false;
      for (const sltk::Index b : band)
      {
        const auto j = phi.nodeIndex(b);
        const sltk::Index dx = i[0] - j[0];
        const sltk::Index dy = i[1] - j[1];
        near = near || dx * dx + dy * dy <= k * k;
      }
      if (near)
      {
        expected.push_back(n);
      }
    }
    EXPECT_EQ(dilated, expected) << "k = " << k;
    EXPECT_GT(dilated.size(), band.size());
  }
}

TEST(NarrowBand, Dilation3DWithMoreNodesMatchesBruteForce)
{
  // A band and a second list (a slab's ghost-row band) that overlap, one
  // list out of order: the ascending union of the balls, in the grid.
  sltk::GridSpec<3> g = sltk::uniformBox<3>(9, -1.0, 1.0);
  g.Dims[1] = 7;
  g.Dims[2] = 5;
  const sltk::GridField<3> index(g, 0);
  sltk::NodeList band, more;
  for (sltk::Index n = 0; n < g.nodeCount(); ++n)
  {
    if (n % 7 == 0 || n % 11 == 3)
    {
      band.push_back(n);
    }
    if (n % 13 == 5)
    {
      more.insert(more.begin(), n); // descending
    }
  }
  more.push_back(band[3]);       // a node of both lists
  more.push_back(g.nodeCount()); // outside the grid: ignored
  sltk::ThreadPool pool(2);      // the x lines shared out among threads, small chunks
  sltk::Context ctx;
  ctx.Executor = &pool;
  for (int k : { 1, 2 })
  {
    sltk::NodeList dilated;
    sltk::dilateBand(g, band, k, ctx, dilated, &more);
    sltk::NodeList expected;
    for (sltk::Index n = 0; n < g.nodeCount(); ++n)
    {
      const auto i = index.nodeIndex(n);
      bool near = false;
      for (const sltk::NodeList* list : { &band, &more })
      {
        for (const sltk::Index b : *list)
        {
          if (b >= g.nodeCount())
          {
            continue;
          }
          const auto j = index.nodeIndex(b);
          sltk::Index r2 = 0;
          for (int a = 0; a < 3; ++a)
          {
            r2 += (i[a] - j[a]) * (i[a] - j[a]);
          }
          near = near || r2 <= k * k;
        }
      }
      if (near)
      {
        expected.push_back(n);
      }
    }
    EXPECT_EQ(dilated, expected) << "k = " << k;
  }
}

TEST(NarrowBand, Dilation3DAtTheGridBoundary)
{
  sltk::GridSpec<3> g = sltk::uniformBox<3>(6, -1.0, 1.0);
  sltk::NodeList corner{ 0 };
  sltk::NodeList dilated;
  sltk::dilateBand(g, corner, 1, sltk::Context{}, dilated);
  // The corner and its three face neighbours inside the grid.
  EXPECT_EQ(dilated, (sltk::NodeList{ 0, 1, 6, 36 }));
  sltk::dilateBand(g, corner, 2, sltk::Context{}, dilated);
  // Offsets with o >= 0 and |o|^2 <= 4: 1 + 3 (faces) + 3 (edge diagonals) + 1 (cube
  // diagonal, |o|^2 = 3) + 3 (two steps) = 11.
  EXPECT_EQ(dilated.size(), 11u);
}

TEST(NarrowBand, ListsWrittenOverAnOldListOrTheirOwnInput)
{
  // The run's lists are written in place, their capacity reused (NarrowBand.cxx):
  // the result may not depend on what the output held, nor break when the output
  // is also the input.
  const auto g = sltk::uniformBox<3>(41, -1.0, 1.0);
  const double dx = g.Spacing[0];
  const auto phi = sphereSdf<3>(g, 0.6);
  sltk::ThreadPool pool(2);
  sltk::Context ctx;
  ctx.Executor = &pool;
  sltk::NodeList band, clean;
  sltk::collectBand(phi, 3.0 * dx, ctx, clean);
  band.assign(3 * clean.size(), 7); // longer, with garbage
  sltk::collectBand(phi, 3.0 * dx, ctx, band);
  EXPECT_EQ(band, clean);
  sltk::NodeList dilated, stale(5, -1);
  sltk::dilateBand(g, clean, 1, ctx, dilated);
  sltk::dilateBand(g, clean, 1, ctx, stale);
  EXPECT_EQ(stale, dilated);
  sltk::NodeList alias = clean;
  sltk::dilateBand(g, alias, 1, ctx, alias); // output = input
  EXPECT_EQ(alias, dilated);
  sltk::NodeList more = clean, both;
  sltk::dilateBand(g, clean, 1, ctx, both, &more);
  sltk::dilateBand(g, clean, 1, ctx, more, &more); // output = the second input
  EXPECT_EQ(more, both);
  sltk::NodeList filtered, filteredOver(2 * dilated.size(), 3);
  sltk::filterBand(phi, dilated, 2.0 * dx, ctx, filtered);
  sltk::filterBand(phi, dilated, 2.0 * dx, ctx, filteredOver);
  EXPECT_EQ(filteredOver, filtered);
  sltk::NodeList self = dilated;
  sltk::filterBand(phi, self, 2.0 * dx, ctx, self); // output = input
  EXPECT_EQ(self, filtered);
  EXPECT_LT(filtered.size(), dilated.size());
}

TEST(NarrowBand, NextBandFilteredFromTheReinitBandAndCut)
{
  // The front moves by less than a cell: B^{n+1} is inside B^n dilated by one cell (1.52).
  const auto g = sltk::uniformBox<2>(61, -1.5, 1.5);
  const double dx = g.Spacing[0];
  const auto w = sltk::BandWidths::forSpacing(dx);
  auto phi0 = sphereSdf<2>(g, 0.8);
  sltk::NodeList band;
  sltk::collectBand(phi0, w.Gamma, sltk::Context{}, band);
  sltk::NodeList reinit;
  sltk::dilateBand(g, band, 1, sltk::Context{}, reinit);
  auto phi1 = sphereSdf<2>(g, 0.8, 0.6 * dx);
  sltk::cutLevelSet(phi1, w.Gamma, sltk::Context{});
  sltk::NodeList next;
  sltk::filterBand(phi1, reinit, w.Gamma, sltk::Context{}, next);
  sltk::NodeList full;
  sltk::collectBand(phi1, w.Gamma, sltk::Context{}, full);
  EXPECT_EQ(next, full);
  // Cutting (1.49) on a list leaves values within gamma and clamps the rest.
  auto phi2 = sphereSdf<2>(g, 0.8);
  sltk::cutLevelSet(phi2, reinit, w.Gamma, sltk::Context{});
  for (const sltk::Index k : reinit)
  {
    const auto i = phi2.nodeIndex(k);
    const double exact = std::hypot(g.coordinate(0, i[0]), g.coordinate(1, i[1])) - 0.8;
    EXPECT_NEAR(phi2(i), sltk::cutLevel(exact, w.Gamma), 1e-15);
  }
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    EXPECT_LE(std::fabs(phi1(phi1.nodeIndex(k))), w.Gamma);
  }
}
