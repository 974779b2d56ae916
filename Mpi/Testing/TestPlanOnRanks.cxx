// SPDX-License-Identifier: BSD-3-Clause
// The plan of a reconstruction from the ranks' shares of the cloud
// (ReconstructionPlan.h planReconstructionOnRanks: the validation, the cleaning,
// the unit box, h_P, the noise, the automatic C_dx and thinning on the points'
// owners, CloudPoints.h) against the plan one rank makes from the whole cloud:
// the same plan bit for bit, the same refusals with the same messages, on any
// number of ranks and whatever share each rank read.
#include "MpiWorld.h"

#include "sltk/cloud/CloudFileShares.h"
#include "sltk/cloud/CloudPoints.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>

namespace
{
/// A context of two threads.
struct TwoThreads
{
  sltk::ThreadPool Pool{ 2 };
  sltk::Context Ctx;
  TwoThreads() { this->Ctx.Executor = &this->Pool; }
};

/// This rank's share of `cloud` as a parallel read cuts it (CloudFileShares.h);
/// `allOnRankZero`: rank 0 read every point. `first`: the share's first global index.
template <int D>
sltk::PointCloud<D> shareOf(
  const sltk::PointCloud<D>& cloud, const sltk::Communicator& comm, std::int64_t& first, bool allOnRankZero = false)
{
  const std::int64_t n = cloud.size();
  sltk::FileShare s = sltk::shareOf(0, n, comm.rank(), comm.size());
  if (allOnRankZero)
  {
    s = comm.rank() == 0 ? sltk::FileShare{ 0, n } : sltk::FileShare{ n, n };
  }
  first = s.Begin;
  return sltk::PointCloud<D>{ { cloud.Points.begin() + s.Begin, cloud.Points.begin() + s.End } };
}

/// The points of an x y z file of the shared data; none when /work/shared is absent.
sltk::PointCloud<3> sharedCloud(const std::string& path)
{
  sltk::PointCloud<3> cloud;
  std::ifstream in("/work/shared/data/clouds/" + path);
  double x, y, z;
  while (in >> x >> y >> z)
  {
    cloud.Points.push_back({ x, y, z });
  }
  return cloud;
}

template <int D>
void expectSameGrid(const sltk::GridSpec<D>& g, const sltk::GridSpec<D>& one)
{
  EXPECT_EQ(g.Dims, one.Dims);
  EXPECT_EQ(g.Origin, one.Origin);
  EXPECT_EQ(g.Spacing, one.Spacing);
}

/// Plans `cloud` whole on every rank and from the ranks' shares, and expects the
/// same plan (or the same refusal). Returns the one-rank plan's status.
template <int D>
sltk::Status expectOneRankPlan(const sltk::PointCloud<D>& cloud, const sltk::ReconstructionOptions& options,
  bool allOnRankZero = false, sltk::ReconstructionPlan<D>* reference = nullptr)
{
  auto comm = world();
  TwoThreads threads;
  sltk::ReconstructionPlan<D> local;
  sltk::ReconstructionPlan<D>& one = reference ? *reference : local;
  const sltk::Status oneStatus = sltk::planReconstruction(cloud, options, threads.Ctx, one);
  std::int64_t first = 0;
  const sltk::PointCloud<D> mine = shareOf(cloud, *comm, first, allOnRankZero);
  sltk::ReconstructionPlan<D> plan;
  const sltk::Status status = sltk::planReconstructionOnRanks(mine, first, options, threads.Ctx, *comm, plan);
  EXPECT_EQ(status.code(), oneStatus.code()) << status.message() << " | " << oneStatus.message();
  EXPECT_EQ(status.message(), oneStatus.message());
  if (!status.isOk() || !oneStatus.isOk())
  {
    return oneStatus;
  }
  EXPECT_EQ(plan.Choices, one.Choices);
  EXPECT_EQ(plan.Cloud.Points, one.Cloud.Points); // bit for bit, in the cloud's order
  EXPECT_EQ(plan.CloudSpacing, one.CloudSpacing);
  EXPECT_EQ(plan.CloudNoise, one.CloudNoise);
  EXPECT_EQ(plan.Box.Centre, one.Box.Centre);
  EXPECT_EQ(plan.Box.Scale, one.Box.Scale);
  EXPECT_EQ(plan.Options.CellSizeFactor, one.Options.CellSizeFactor);
  EXPECT_EQ(plan.Options.OutsideThresholdFactor, one.Options.OutsideThresholdFactor);
  EXPECT_EQ(plan.Options.Interpolator, one.Options.Interpolator);
  EXPECT_EQ(plan.Cleaning.InputPoints, one.Cleaning.InputPoints);
  EXPECT_EQ(plan.Cleaning.OutliersRemoved, one.Cleaning.OutliersRemoved);
  EXPECT_EQ(plan.Cleaning.ThinningCell, one.Cleaning.ThinningCell);
  EXPECT_EQ(plan.Cleaning.OutputPoints, one.Cleaning.OutputPoints);
  EXPECT_EQ(plan.Cleaning.AutomaticOutliers, one.Cleaning.AutomaticOutliers);
  EXPECT_EQ(plan.Cleaning.AutomaticThinning, one.Cleaning.AutomaticThinning);
  EXPECT_EQ(plan.Sparsity, one.Sparsity);
  EXPECT_EQ(plan.FirstRunReach, one.FirstRunReach);
  EXPECT_EQ(plan.InitialEllipsoid.has_value(), one.InitialEllipsoid.has_value());
  EXPECT_EQ(plan.Grids.Runs.size(), one.Grids.Runs.size());
  for (size_t r = 0; r < std::min(plan.Grids.Runs.size(), one.Grids.Runs.size()); ++r)
  {
    expectSameGrid(plan.Grids.Runs[r], one.Grids.Runs[r]);
  }
  EXPECT_TRUE(plan.Locator && &plan.Locator->cloud() == &plan.Cloud);
  EXPECT_EQ(one.PointsHeldMax, cloud.size());
  EXPECT_GE(plan.PointsHeldMax, plan.Cloud.size());                                // the cleaned cloud, gathered
  EXPECT_GE(plan.PointsHeldMax, (cloud.size() + comm->size() - 1) / comm->size()); // some rank owns N / P
  EXPECT_LE(plan.PointsHeldMax, cloud.size()); // no halo: no point held twice by a rank
  return oneStatus;
}

/// A sphere with a few points far from it (gross outliers: the automatic cleaning removes them).
sltk::PointCloud<3> sphereWithStrays()
{
  sltk::PointCloud<3> cloud = sltk::sphereCloud(3000);
  cloud.Points.insert(cloud.Points.begin() + 700, { 9.0, 0.5, -0.25 });
  cloud.Points.insert(cloud.Points.begin() + 2100, { -0.5, 8.0, 7.5 });
  return cloud;
}
} // namespace

TEST(PlanOnRanks, IsTheOneRankPlanOfASphereWithGrossOutliers)
{
  sltk::ReconstructionPlan<3> one;
  ASSERT_TRUE(expectOneRankPlan(sphereWithStrays(), {}, false, &one).isOk());
  EXPECT_TRUE(one.Cleaning.AutomaticOutliers); // the case is the one it names
  EXPECT_EQ(one.Cleaning.OutliersRemoved, 2);
  expectOneRankPlan(sphereWithStrays(), {}, true); // every point read by rank 0
}

TEST(PlanOnRanks, IsTheOneRankPlanOfACloudThinnedAutomatically)
{
  // 60,000 points on a sphere under a 16 MB budget: C_dx grows until the finest cell is
  // wider than the density spacing, and the cloud is averaged over cells.
  sltk::ReconstructionOptions options;
  options.MemoryBudget = std::uint64_t(16) << 20;
  sltk::ReconstructionPlan<3> one;
  ASSERT_TRUE(expectOneRankPlan(sltk::sphereCloud(60000), options, false, &one).isOk());
  EXPECT_TRUE(one.Cleaning.AutomaticThinning);
  EXPECT_LT(one.Cloud.size(), 60000);
}

TEST(PlanOnRanks, IsTheOneRankPlanWithTheCleaningAskedForAndOtherOptions)
{
  sltk::ReconstructionOptions asked;
  asked.Cleaning.RemoveOutliers = true;
  asked.Cleaning.ThinningFactor = 2.0;
  sltk::ReconstructionPlan<3> one;
  ASSERT_TRUE(expectOneRankPlan(sphereWithStrays(), asked, false, &one).isOk());
  EXPECT_GT(one.Cleaning.ThinningCell, 0.0);
  EXPECT_GT(one.Cleaning.OutliersRemoved, 0);
  sltk::ReconstructionOptions level; // C_dx from the finest level (the box over the ranks)
  level.MaximumLevel = 7;
  expectOneRankPlan(sltk::sphereCloud(2000), level);
  sltk::ReconstructionOptions sphere; // run 1 from a bounding sphere, fixed C_dx, no local offset
  sphere.Guess = sltk::InitialGuess::BoundingSphere;
  sphere.CellSizeFactor = 2.0;
  sphere.LocalOffset = false;
  expectOneRankPlan(sltk::sphereCloud(1500, 2.0, { 10.0, -3.0, 1.0 }), sphere);
  sltk::ReconstructionOptions asGiven;
  asGiven.Cleaning.Automatic = false;
  expectOneRankPlan(sphereWithStrays(), asGiven);
}

TEST(PlanOnRanks, IsTheOneRankPlanIn2D)
{
  sltk::PointCloud<2> circle = sltk::circleCloud(800, 1.5, { 3.0, -1.0 });
  circle.Points.push_back({ 40.0, 40.0 }); // a gross outlier
  expectOneRankPlan(circle, {});
  sltk::ReconstructionOptions options;
  options.MemoryBudget = std::uint64_t(1) << 20;
  expectOneRankPlan(sltk::circleCloud(20000), options);
}

TEST(PlanOnRanks, RefusesWhatOneRankRefusesWithItsMessage)
{
  sltk::PointCloud<3> bad = sltk::sphereCloud(500);
  bad.Points[321][1] = std::numeric_limits<double>::quiet_NaN(); // on the last rank's share or another
  EXPECT_FALSE(expectOneRankPlan(bad, {}).isOk());
  sltk::PointCloud<3> plane;
  for (int k = 0; k < 300; ++k)
  {
    plane.Points.push_back({ std::sin(0.3 * k), std::cos(0.7 * k), 0.25 });
  }
  EXPECT_FALSE(expectOneRankPlan(plane, {}).isOk());
  EXPECT_FALSE(expectOneRankPlan(sltk::PointCloud<3>{}, {}).isOk());
  sltk::ReconstructionOptions wrong;
  wrong.Runs = 0;
  EXPECT_FALSE(expectOneRankPlan(sltk::sphereCloud(300), wrong).isOk());
  // Outliers removed until too few points stay: refused after the cleaning, as on one rank.
  sltk::PointCloud<3> few = sltk::sphereCloud(12);
  sltk::ReconstructionOptions strict;
  strict.Cleaning.RemoveOutliers = true;
  strict.Cleaning.Outliers.Deviations = 0.01;
  expectOneRankPlan(few, strict);
}

TEST(PlanOnRanks, TheMergedStanfordScansPlanAsOnOneRank)
{
  const sltk::PointCloud<3> scans = sharedCloud("bunny/scans/bunny_scans_registered.xyz");
  if (scans.Points.empty())
  {
    GTEST_SKIP() << "the merged Stanford scans (/work/shared) are not available";
  }
  sltk::ReconstructionPlan<3> one;
  ASSERT_TRUE(expectOneRankPlan(scans, {}, false, &one).isOk());
  EXPECT_TRUE(one.Cleaning.AutomaticOutliers); // the stray point of the scans
  EXPECT_TRUE(one.Cleaning.AutomaticThinning);
}

TEST(ValidateOwnedPoints, GivesTheOneRankVerdictAndMessage)
{
  auto comm = world();
  std::vector<sltk::PointCloud<3>> clouds(6);
  for (int k = 0; k < 200; ++k)
  {
    clouds[0].Points.push_back({ 0.5 * k, 1.0 + 0.25 * k, -0.1 * k });          // a line
    clouds[1].Points.push_back({ std::sin(0.3 * k), std::cos(0.7 * k), 0.25 }); // a plane
    clouds[2].Points.push_back({ static_cast<double>(k % 2), static_cast<double>((k / 2) % 2),
      static_cast<double>(k % 3 == 0) });                                          // ties for the farthest
    clouds[3].Points.push_back({ 1.0, 2.0, 3.0 });                                 // coinciding
    clouds[4].Points.push_back({ 1e9 + 1e-3 * std::sin(k), 1e9 + 1e-3 * k, 1e9 }); // survey coordinates
  }
  clouds[5] = sltk::sphereCloud(400);
  clouds[5].Points[17] = { 1e200, 0.0, 0.0 };
  clouds.push_back(sltk::sphereCloud(3));
  clouds.push_back(sltk::sphereCloud(250));
  for (const sltk::PointCloud<3>& cloud : clouds)
  {
    std::int64_t first = 0;
    const sltk::PointCloud<3> mine = shareOf(cloud, *comm, first);
    sltk::OwnedCloud<3> owned(*comm);
    ASSERT_TRUE(owned.own(mine, first).isOk());
    const sltk::Status status = owned.validate(), one = sltk::validateCloud(cloud);
    EXPECT_EQ(status.code(), one.code());
    EXPECT_EQ(status.message(), one.message());
    // With halos (points held by several ranks, owned by one): each counted once.
    sltk::OwnedPoints<3> halo;
    ASSERT_TRUE(
      sltk::sendToOwners(mine, first, sltk::balancedCuts(mine, *comm), 1e300, *comm, halo).isOk()); // every point
    const sltk::Status held = sltk::validateOwnedPoints(halo.Cloud, halo.Ids, halo.Mine, *comm);
    EXPECT_EQ(held.code(), one.code());
    EXPECT_EQ(held.message(), one.message());
  }
}
