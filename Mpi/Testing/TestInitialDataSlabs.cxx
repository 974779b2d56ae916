// SPDX-License-Identifier: BSD-3-Clause
// cloudInitialDataSlabs() (CloudInitialDataSlabs.h) on the ranks of
// MPI_COMM_WORLD (ctest: 1 and 2 ranks; also right on 3 and 4): from the
// distance on slabs, phi0 on every owned node is the one-rank phi0 to
// rounding, with the same sign everywhere (the external marking crosses the
// slabs by exchanges of marks); a bad threshold fails every rank.
#include "MpiWorld.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/CloudInitialDataSlabs.h"
#include "sltk/recon/DistanceFunction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace
{
template <int D>
void expectSameAsOneRank(const sltk::PointCloud<D>& cloud, sltk::Index n, double gammaInDx)
{
  auto comm = world();
  const sltk::GridSpec<D> whole = sltk::uniformBox<D>(n, -1.5, 1.5);
  const sltk::PointLocator<D> locator(cloud);
  sltk::DistanceOptions distanceOptions;
  distanceOptions.SweepTolerance = 0.0;
  distanceOptions.MaxSweepCycles = 1000;
  sltk::InitialDataOptions options;
  options.SweepTolerance = 0.0;
  options.MaxSweepCycles = 1000;
  const double gamma = gammaInDx * whole.Spacing[0];
  sltk::GridField<D, double> d1, dn, one, mine;
  ASSERT_TRUE(sltk::distanceToCloud(locator, whole, sltk::Context{}, d1, distanceOptions).isOk());
  ASSERT_TRUE(sltk::cloudInitialData(d1, gamma, sltk::Context{}, one, options).isOk());
  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlab(n, 1, comm->rank(), comm->size(), "the sweep's stencil", slab).isOk());
  ASSERT_TRUE(sltk::distanceToCloudSlabs(locator, whole, slab, *comm, sltk::Context{}, dn, distanceOptions).isOk());
  sltk::InitialDataReport report;
  const sltk::Status s =
    sltk::cloudInitialDataSlabs(dn, gamma, slab, n, *comm, sltk::Context{}, mine, options, &report);
  ASSERT_TRUE(s.isOk()) << s.message();
  const sltk::Index rowNodes = whole.nodeCount() / n;
  double worst = 0.0;
  sltk::Index signs = 0, inside = 0;
  for (sltk::Index k = (slab.Begin - slab.First) * rowNodes; k < (slab.End - slab.First) * rowNodes; ++k)
  {
    const double a = mine(mine.nodeIndex(k)), b = one(one.nodeIndex(k + slab.First * rowNodes));
    worst = std::max(worst, std::fabs(a - b));
    signs += (a < 0.0) != (b < 0.0) ? 1 : 0;
    inside += b < 0.0 ? 1 : 0;
  }
  EXPECT_EQ(signs, 0) << "rank " << comm->rank() << " of " << comm->size();
  EXPECT_LE(worst, 1e-12 * whole.Spacing[0]) << "rank " << comm->rank() << " of " << comm->size();
  EXPECT_GT(comm->allReduce(static_cast<std::int64_t>(inside), sltk::ReduceOp::Sum), 0) << "the cloud encloses nodes";
  EXPECT_GE(report.MarkingRounds, 1);
}
} // namespace

TEST(InitialDataSlabs, SphereAndCircleGiveTheOneRankPhi0)
{
  expectSameAsOneRank<3>(sltk::sphereCloud(800), 33, 2.0);
  expectSameAsOneRank<2>(sltk::circleCloud(200), 81, 2.0);
}

TEST(InitialDataSlabs, ABadThresholdFailsEveryRank)
{
  auto comm = world();
  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlab(41, 1, comm->rank(), comm->size(), "the sweep's stencil", slab).isOk());
  sltk::GridSpec<2> window = sltk::uniformBox<2>(41, -1.0, 1.0);
  window.Dims[1] = slab.windowRows();
  const sltk::GridField<2, double> d(window, 2, 1.0);
  sltk::GridField<2, double> phi0;
  const double gamma = comm->rank() == 0 ? -1.0 : 0.1; // wrong on rank 0 only
  const sltk::Status s = sltk::cloudInitialDataSlabs(d, gamma, slab, 41, *comm, sltk::Context{}, phi0);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument) << s.message();
  comm->barrier(); // no hang
}
