// SPDX-License-Identifier: BSD-3-Clause
// distanceToCloudSlabs() (DistanceFunction.h) on the ranks of MPI_COMM_WORLD
// (ctest: 1 and 2 ranks; also right on 3 and 4): every rank holds the whole
// cloud and computes the distance on its slab's window; the owned nodes match
// the one-rank distanceToCloud() to rounding when the sweeps run until nothing
// changes, and within the sweeps' tolerance with the default options; a cloud
// that lies in one rank's rows only works; a bad option fails every rank.
// ExactDistanceCache (ExactDistanceCache.h) on each rank's own points: the
// whole cloud's distances bit for bit, the far ones settled over the ranks.
#include "MpiWorld.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/levelset/NarrowBand.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/ExactDistanceCache.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace
{
/// The largest difference to the one-rank distance over this rank's owned nodes, relative to dx.
template <int D>
double largestDifference(const sltk::PointCloud<D>& cloud, sltk::Index n, const sltk::DistanceOptions& options)
{
  auto comm = world();
  const sltk::GridSpec<D> whole = sltk::uniformBox<D>(n, -1.5, 1.5);
  const sltk::PointLocator<D> locator(cloud);
  sltk::GridField<D, double> one, mine;
  EXPECT_TRUE(sltk::distanceToCloud(locator, whole, sltk::Context{}, one, options).isOk());
  sltk::SlabPlan slab;
  EXPECT_TRUE(sltk::planSlab(n, 1, comm->rank(), comm->size(), "the sweep's stencil", slab).isOk());
  const sltk::Status s = sltk::distanceToCloudSlabs(locator, whole, slab, *comm, sltk::Context{}, mine, options);
  EXPECT_TRUE(s.isOk()) << s.message();
  const sltk::Index rowNodes = whole.nodeCount() / n;
  double worst = 0.0;
  for (sltk::Index k = (slab.Begin - slab.First) * rowNodes; k < (slab.End - slab.First) * rowNodes; ++k)
  {
    worst = std::max(worst, std::fabs(mine(mine.nodeIndex(k)) - one(one.nodeIndex(k + slab.First * rowNodes))));
  }
  return worst / whole.Spacing[0];
}
} // namespace

TEST(DistanceSlabs, SphereCloudUntilNothingChangesIsTheOneRankDistance)
{
  sltk::DistanceOptions until;
  until.SweepTolerance = 0.0;
  until.MaxSweepCycles = 1000;
  EXPECT_LE(largestDifference<3>(sltk::sphereCloud(800), 33, until), 1e-12);
  EXPECT_LE(largestDifference<2>(sltk::circleCloud(200), 81, until), 1e-12);
}

TEST(DistanceSlabs, DefaultOptionsAgreeWithinTheSweepTolerance)
{
  // The default sweeps stop when no value moved by 1e-6 dx in a cycle, on one rank and on each window.
  EXPECT_LE(largestDifference<3>(sltk::sphereCloud(800), 33, sltk::DistanceOptions{}), 1e-5);
}

TEST(DistanceSlabs, ACloudInOneRanksRowsOnly)
{
  // A small circle near the bottom: the upper ranks have no point and no exact node, only swept values.
  sltk::DistanceOptions until;
  until.SweepTolerance = 0.0;
  until.MaxSweepCycles = 1000;
  EXPECT_LE(largestDifference<2>(sltk::circleCloud(60, 0.2, { 0.3, -1.2 }), 81, until), 1e-12);
}

TEST(DistanceSlabs, ABadOptionFailsEveryRank)
{
  auto comm = world();
  const sltk::PointCloud<2> cloud = sltk::circleCloud(50);
  const sltk::PointLocator<2> locator(cloud);
  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlab(41, 1, comm->rank(), comm->size(), "the sweep's stencil", slab).isOk());
  sltk::DistanceOptions bad;
  bad.SweepTolerance = -1.0;
  sltk::GridField<2, double> d;
  const sltk::Status s =
    sltk::distanceToCloudSlabs(locator, sltk::uniformBox<2>(41, -1.5, 1.5), slab, *comm, sltk::Context{}, d, bad);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument) << s.message();
  comm->barrier(); // no hang
}

TEST(DistanceSlabs, ExactDistancesFromEachRanksOwnPointsAreTheWholeCloudsBitForBit)
{
  // Each rank holds only the points within `reach` of its rows (and a row on
  // each side, where the stencils reach); its band is wide enough that many
  // nodes lie farther than reach from every point, where its own points may
  // not hold the nearest: those are settled over the ranks.
  auto comm = world();
  const sltk::Index n = 33;
  const sltk::GridSpec<3> g = sltk::uniformBox<3>(n, -1.0, 1.0);
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(2000, 0.6, { 0.05, -0.02, 0.03 });
  const sltk::PointLocator<3> whole(cloud);
  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlab(n, 1, comm->rank(), comm->size(), "the cache's stencil", slab).isOk());
  const double reach = 0.15;
  const double low = g.coordinate(2, slab.Begin - 1) - reach, high = g.coordinate(2, slab.End) + reach;
  sltk::PointCloud<3> mine;
  for (const auto& q : cloud.Points)
  {
    if (q[2] >= low && q[2] <= high)
    {
      mine.Points.push_back(q);
    }
  }
  ASSERT_GT(mine.size(), 0);
  const sltk::PointLocator<3> locator(mine);
  sltk::GridField<3> sdf(g, 1);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = sdf.nodeIndex(k);
    sdf(i) = std::hypot(g.coordinate(0, i[0]) - 0.05, g.coordinate(1, i[1]) + 0.02, g.coordinate(2, i[2]) - 0.03) - 0.6;
  }
  sltk::NodeList all, band;
  sltk::collectBand(sdf, 0.45, sltk::Context{}, all);
  for (const sltk::Index k : all)
  {
    const sltk::Index row = sdf.nodeIndex(k)[2];
    if (row >= slab.Begin && row < slab.End)
    {
      band.push_back(k);
    }
  }
  const double marker = -7.0;
  sltk::GridField<3> dist(g, 1, marker);
  sltk::ExactDistanceCache<3> cache(locator);
  cache.bind(locator, reach, *comm);
  cache.reset(dist);
  cache.ensure(band, sltk::Context{}, dist);
  sltk::Index beyond = 0, checked = 0, wrong = 0;
  for (const sltk::Index k : band)
  {
    const auto i = dist.nodeIndex(k);
    for (int c = 0; c < 11; ++c)
    {
      std::array<sltk::Index, 3> j = i;
      if (c < 8)
      {
        j = { i[0] + (c & 1), i[1] + ((c >> 1) & 1), i[2] + ((c >> 2) & 1) };
      }
      else
      {
        --j[c - 8];
      }
      std::array<double, 3> x{};
      bool inGrid = true;
      for (int a = 0; a < 3; ++a)
      {
        inGrid = inGrid && j[a] >= 0 && j[a] < n;
        x[a] = g.coordinate(a, j[a]);
      }
      if (!inGrid)
      {
        continue;
      }
      const double expected = whole.nearest(x).Distance;
      wrong += dist(j) == expected ? 0 : 1;
      beyond += expected > reach ? 1 : 0;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0) << "rank " << comm->rank();
  EXPECT_EQ(wrong, 0) << "rank " << comm->rank() << ": " << wrong << " of " << checked << " stencil nodes";
  EXPECT_TRUE(comm->anyRank(beyond > 0)) << "the test needs nodes beyond reach";
  EXPECT_TRUE(comm->size() == 1 || comm->anyRank(mine.size() < cloud.size())) << "the ranks should hold part of it";
}
