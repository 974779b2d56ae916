// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/ExactDistanceCache.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/exec/Context.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace
{
/// Every node of the band's stencils (corners {0,1}^3 of its cell, face
/// neighbours -e_a) equals the per-node query bit for bit; every other node
/// keeps its marker value.
void expectExactOnStencils(const sltk::GridField<3>& dist, const std::vector<sltk::NodeList>& bands,
  const sltk::PointLocator<3>& locator, double marker)
{
  const sltk::GridSpec<3>& g = dist.spec();
  sltk::GridField<3> expected(g, 1, marker);
  for (const sltk::NodeList& band : bands)
  {
    for (const sltk::Index k : band)
    {
      const auto i = dist.nodeIndex(k);
      std::vector<std::array<sltk::Index, 3>> stencil;
      for (int c = 0; c < 8; ++c)
      {
        stencil.push_back({ i[0] + (c & 1), i[1] + ((c >> 1) & 1), i[2] + ((c >> 2) & 1) });
      }
      for (int a = 0; a < 3; ++a)
      {
        auto j = i;
        --j[a];
        stencil.push_back(j);
      }
      for (const auto& j : stencil)
      {
        bool inGrid = true;
        std::array<double, 3> x{};
        for (int a = 0; a < 3; ++a)
        {
          inGrid = inGrid && j[a] >= 0 && j[a] < g.Dims[a];
          x[a] = g.coordinate(a, j[a]);
        }
        if (inGrid)
        {
          expected(j) = locator.nearest(x).Distance;
        }
      }
    }
  }
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = dist.nodeIndex(k);
    ASSERT_EQ(dist(i), expected(i)) << "node " << i[0] << " " << i[1] << " " << i[2];
  }
}
} // namespace

TEST(ExactDistanceCache, BandStencilsGetTheNearestPointQueriesBitForBit)
{
  // A sphere cloud shifted to survey-like coordinates, a band that grows
  // between two calls (nodes already exact are not recomputed), one and two
  // threads: the nodes grouped in boxes give each node its own query's value.
  for (const int threads : { 1, 2 })
  {
    const std::array<double, 3> centre{ 4.0e5, -2.0e5, 10.0 };
    const sltk::PointCloud<3> cloud = sltk::sphereCloud(3000, 0.6, centre);
    const sltk::PointLocator<3> locator(cloud);
    sltk::GridSpec<3> g = sltk::uniformBox<3>(41, -1.0, 1.0);
    for (int a = 0; a < 3; ++a)
    {
      g.Origin[a] += centre[a];
    }
    sltk::GridSpec<3> centred = sltk::uniformBox<3>(41, -1.0, 1.0);
    const double marker = -7.0;
    sltk::GridField<3> dist(g, 1, marker);
    sltk::ExactDistanceCache<3> cache(locator);
    cache.reset(dist);
    sltk::ThreadPool pool(threads);
    sltk::Context ctx;
    ctx.Executor = &pool;
    std::vector<sltk::NodeList> bands;
    sltk::Index computed = 0;
    for (const double gamma : { 0.05, 0.12 })
    {
      sltk::NodeList band;
      sltk::collectBand(
        sltktest::sampleNodes<3>(centred, 1, [](const std::array<double, 3>& x) { return sltk::sphereSdf(x, 0.6); }),
        gamma, ctx, band);
      ASSERT_FALSE(band.empty());
      computed += cache.ensure(band, ctx, dist);
      bands.push_back(band);
      expectExactOnStencils(dist, bands, locator, marker);
    }
    sltk::Index exact = 0;
    for (sltk::Index k = 0; k < g.nodeCount(); ++k)
    {
      exact += dist(dist.nodeIndex(k)) != marker ? 1 : 0;
    }
    EXPECT_EQ(computed, exact) << "each node computed once";
  }
}
