// SPDX-License-Identifier: BSD-3-Clause
// distanceToCloudSlabs() (DistanceFunction.h) on the ranks of MPI_COMM_WORLD
// (ctest: 1 and 2 ranks; also right on 3 and 4): every rank holds the whole
// cloud and computes the distance on its slab's window; the owned nodes match
// the one-rank distanceToCloud() to rounding when the sweeps run until nothing
// changes, and within the sweeps' tolerance with the default options; a cloud
// that lies in one rank's rows only works; a bad option fails every rank.
#include "MpiWorld.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/DistanceFunction.h"

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
