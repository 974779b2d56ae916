// SPDX-License-Identifier: BSD-3-Clause
// The whole reconstruction (Algorithm 1, every run) on the slabs of
// MPI_COMM_WORLD (ctest: 1 and 2 ranks; also right on 3 and 4): each rank's
// owned nodes of the signed distance and the distance are the one-rank
// reconstruction's to rounding, with the same runs, iteration counts, band
// sizes and Err_P. The energy, eps_1 and Err_P are sums whose terms the ranks
// add in another order, and run 1's distance is swept to a tolerance
// (DistanceOptions::SweepTolerance), so values may differ in the last bits:
// phi within 1e-12 of a cell (measured: 2.3e-14), d within 1e-10 (measured:
// 1.2e-12) (Documentation/Distributed.md).
#include "MpiWorld.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/InsideComponents.h"
#include "sltk/recon/Reconstruction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace
{

/// A circle sampled unevenly (the local offset's sparsity varies along it).
sltk::PointCloud<2> unevenCircle(int n)
{
  sltk::PointCloud<2> cloud;
  for (int k = 0; k < n; ++k)
  {
    const double u = static_cast<double>(k) / n;
    const double t = 2.0 * M_PI * u + 0.7 * std::sin(2.0 * M_PI * u);
    cloud.Points.push_back({ 1.3 * std::cos(t), 0.8 * std::sin(t) + 0.2 * std::cos(3.0 * t) });
  }
  return cloud;
}

/// The agreement the header states; a thin part amplifies the last bits (see the fin's test).
struct Agreement
{
  double Phi = 1e-12;        ///< of a cell
  double CloudError = 1e-12; ///< relative
};

/// Returns the feet interpolated by another rank over all runs (FarFeetExchange.h);
/// `held`: the most points a rank's run read (RunRecord::PointsHeld), over the runs.
template <int D>
sltk::Index expectSameAsOneRank(const sltk::PointCloud<D>& cloud, const sltk::ReconstructionOptions& options,
  Agreement agreement = {}, sltk::Index* held = nullptr)
{
  auto comm = world();
  sltk::ReconstructionPlan<D> plan;
  EXPECT_TRUE(sltk::planReconstruction(cloud, options, sltk::Context{}, plan).isOk());
  sltk::ReconstructionResult<D> one, mine;
  const sltk::Status oneStatus = sltk::reconstruct(plan, sltk::Context{}, one);
  EXPECT_TRUE(oneStatus.isOk()) << oneStatus.message();
  const sltk::Status status = sltk::reconstruct(plan, sltk::Context{}, mine, *comm);
  EXPECT_TRUE(status.isOk()) << status.message();
  if (!status.isOk() || !oneStatus.isOk() || mine.Runs.size() != one.Runs.size())
  {
    ADD_FAILURE() << "runs differ";
    return 0;
  }
  for (size_t r = 0; r < one.Runs.size(); ++r)
  {
    EXPECT_EQ(mine.Runs[r].Iterations, one.Runs[r].Iterations) << "run " << r + 1;
    EXPECT_NEAR(mine.Runs[r].CloudError, one.Runs[r].CloudError, agreement.CloudError * one.Runs[r].CloudError)
      << "run " << r + 1;
  }
  // The pieces (InsideComponents.h: labelled per slab, merged over the ranks) and the
  // cloud's components are the one rank's.
  EXPECT_GE(one.Pieces, 1);
  EXPECT_EQ(mine.Pieces, one.Pieces);
  EXPECT_EQ(mine.CloudComponents, one.CloudComponents);
  EXPECT_EQ(mine.FitsCloud, one.FitsCloud);
  expectSameMissedPlaces(mine.MissedPlaces, one.MissedPlaces);
  EXPECT_EQ(mine.History.size(), one.History.size());
  for (size_t k = 0; k < std::min(one.History.size(), mine.History.size()); ++k)
  {
    EXPECT_EQ(mine.History[k].BandSize, one.History[k].BandSize)
      << "run " << one.History[k].Run << " iteration " << one.History[k].Iteration << ", E_2 " << mine.History[k].Energy
      << " against " << one.History[k].Energy;
  }
  const sltk::SlabPlan& slab = mine.Slab;
  const sltk::GridSpec<D>& whole = one.SignedDistance.spec();
  EXPECT_EQ(mine.WholeGrid.Dims, whole.Dims);
  EXPECT_EQ(mine.SignedDistance.spec().Dims[D - 1], slab.windowRows());
  const sltk::Index rowNodes = whole.nodeCount() / whole.Dims[D - 1];
  double phiGap = 0.0, distGap = 0.0;
  for (sltk::Index k = (slab.Begin - slab.First) * rowNodes; k < (slab.End - slab.First) * rowNodes; ++k)
  {
    const sltk::Index w = k + slab.First * rowNodes;
    phiGap = std::max(phiGap,
      std::fabs(
        mine.SignedDistance(mine.SignedDistance.nodeIndex(k)) - one.SignedDistance(one.SignedDistance.nodeIndex(w))));
    distGap =
      std::max(distGap, std::fabs(mine.Distance(mine.Distance.nodeIndex(k)) - one.Distance(one.Distance.nodeIndex(w))));
  }
  const double dx = whole.Spacing[0];
  EXPECT_LE(phiGap, agreement.Phi * dx) << "rank " << comm->rank() << " of " << comm->size();
  EXPECT_LE(distGap, 1e-10 * dx) << "rank " << comm->rank() << " of " << comm->size();
  std::printf("rank %d of %d: rows %lld..%lld, %zu runs, largest gap phi %.3g dx, d %.3g dx, %lld piece(s), %zu "
              "recoveries\n",
    comm->rank(), comm->size(), static_cast<long long>(slab.Begin), static_cast<long long>(slab.End), one.Runs.size(),
    phiGap / dx, distGap / dx, static_cast<long long>(mine.Pieces), mine.Recoveries.size());
  sltk::Index farFeet = 0;
  for (const auto& run : mine.Runs)
  {
    farFeet += run.FarFeet;
    if (held)
    {
      *held = std::max(*held, run.PointsHeld);
    }
  }
  for (const auto& run : one.Runs)
  {
    EXPECT_EQ(run.PointsHeld, plan.Cloud.size()) << "one rank reads the whole cloud";
  }
  return farFeet;
}

} // namespace

TEST(ReconstructionSlabs, UnevenCircleWithTheDefaultsIsTheOneRankReconstruction)
{
  expectSameAsOneRank<2>(unevenCircle(240), sltk::ReconstructionOptions{});
}

TEST(ReconstructionSlabs, TheRanksOfALongCloudReadOnlyThePointsNearTheirRows)
{
  // An ellipse five times longer than wide along the slabs' axis: each rank's
  // runs read the points within reach of its rows (RunPoints.h), and give the
  // one-rank result.
  sltk::PointCloud<2> cloud;
  for (int k = 0; k < 500; ++k)
  {
    const double t = 2.0 * M_PI * k / 500.0;
    cloud.Points.push_back({ 0.4 * std::cos(t) + 0.05 * std::sin(3.0 * t), 2.0 * std::sin(t) });
  }
  sltk::Index held = 0;
  expectSameAsOneRank<2>(cloud, sltk::ReconstructionOptions{}, Agreement{}, &held);
  const int ranks = world()->size();
  std::printf("the most points a rank's run read: %lld of %zu\n", static_cast<long long>(held), cloud.Points.size());
  if (ranks > 1)
  {
    EXPECT_LT(held, static_cast<sltk::Index>(0.8 * static_cast<double>(cloud.Points.size())));
  }
}

TEST(ReconstructionSlabs, SphereWithTheThesisParametersIsTheOneRankReconstruction)
{
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.CellSizeFactor = 2.0;
  options.OutsideThresholdFactor = 10.0;
  options.Runs = 2;
  expectSameAsOneRank<3>(sltk::sphereCloud(600), options);
}

TEST(ReconstructionSlabs, BallsSeededAroundALostFinAreTheOneRankBalls)
{
  // Run 1 at C_dx = 1 loses the fin; each rank finds the fin's points in its own
  // rows and every rank adds all the balls (recon/FarPointSeeds.h). The same
  // iterations, but a looser agreement than the header's: on 2 and 3 ranks phi
  // within 1e-6 of a cell and Err_P within 1e-8 of itself (measured; on 4 ranks
  // 3e-14 of a cell; without the seeds, 2 ranks, 7e-11 of a cell); with the
  // feet within beta (the default since 2026-12-02) 1.2e-5 of a cell on 2 ranks,
  // 6e-14 on 3 and 4. The fin amplifies some last-bit difference; its cause is
  // not found yet. The bounds are ten times the largest measured ones.
  const sltk::PointCloud<2> cloud = sltk::discWithFinCloud(0.016);
  sltk::ReconstructionOptions options;
  options.CellSizeFactor = 1.0;
  options.SeedFarPoints = true;
  Agreement fin;
  fin.Phi = 1e-4;
  fin.CloudError = 1e-7;
  expectSameAsOneRank<2>(cloud, options, fin);
  sltk::ReconstructionResult<2> one;
  ASSERT_TRUE(sltk::reconstruct(cloud, options, sltk::Context{}, one).isOk());
  EXPECT_GT(one.Runs.front().FarPoints, 0.01) << "run 1 was expected to lose the fin";
  EXPECT_LT(one.Runs.back().FarPoints, 0.01) << "the seeds were expected to bring it back";
}

TEST(ReconstructionSlabs, LostPartIsNamedAsOnOneRank)
{
  // A needle of points (no thickness) 0.3 radii long off the unit circle, 4.5% of the cloud:
  // the cells of C_dx = 1 and WENO3 lose it (Core's AutomaticParameters.LostPartUnderTheMisfitShareSaysSo).
  // Each rank finds the missed points in its rows; gathered, every rank names the one rank's place
  // with its counts and says the result does not fit.
  const sltk::PointCloud<2> cloud = sltk::circleWithNeedleCloud(19, 0.3);
  sltk::ReconstructionOptions options;
  options.CellSizeFactor = 1.0;
  options.Interpolator = sltk::InterpolatorKind::Weno3;
  options.SeedFarPoints = false;
  expectSameAsOneRank<2>(cloud, options);
  sltk::ReconstructionResult<2> one;
  ASSERT_TRUE(sltk::reconstruct(cloud, options, sltk::Context{}, one).isOk());
  EXPECT_FALSE(one.FitsCloud) << "the needle was expected to be lost, and said";
  ASSERT_FALSE(one.Warnings.empty());
  EXPECT_NE(one.Warnings[0].find("it lost a part of the model"), std::string::npos) << one.Warnings[0];
}

TEST(ReconstructionSlabs, SingleNodeSpecksAreMergedAsOnOneRank)
{
  // With the thesis's least-squares Q1 (5.5), run 2 of this noisy circle leaves
  // one node whose sign differs from its four neighbours' (levelset/IsolatedNodes.h);
  // each rank merges those of its owned rows, reading its ghost rows.
  const sltk::PointCloud<2> cloud = sltk::withGaussianNoise(sltk::circleCloud(300), 0.01, 3);
  sltk::ReconstructionOptions options;
  options.Interpolator = sltk::InterpolatorKind::LeastSquaresQ1;
  expectSameAsOneRank<2>(cloud, options);
  sltk::ReconstructionResult<2> one, mine;
  ASSERT_TRUE(sltk::reconstruct(cloud, options, sltk::Context{}, one).isOk());
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, sltk::Context{}, plan).isOk());
  ASSERT_TRUE(sltk::reconstruct(plan, sltk::Context{}, mine, *world()).isOk());
  sltk::Index merged = 0;
  for (size_t r = 0; r < one.Runs.size() && r < mine.Runs.size(); ++r)
  {
    merged += one.Runs[r].MergedNodes;
    EXPECT_EQ(mine.Runs[r].MergedNodes, one.Runs[r].MergedNodes) << "run " << r + 1;
  }
  EXPECT_GT(merged, 0) << "the test expects a speck to merge";
}

TEST(ReconstructionSlabs, FeetBeyondTheGhostRowsAreInterpolatedByTheirOwners)
{
  // eta = 3 in run 1 spreads the feet (4.9) over 8 rows, more than the 6 ghost rows hold
  // (p = 1: a stable run; with eta = 40 in a p = 2 run the energy grows and a difference of 1e-15
  // becomes 1e-3 in two iterations, on one rank as under any other rounding).
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.Runs = 3;
  options.Schedule = { { 1.0, 3.0 }, { 2.0, 0.0 }, { 2.0, 1.0 } };
  const sltk::Index farFeet = expectSameAsOneRank<2>(unevenCircle(480), options);
  if (world()->size() > 1)
  {
    EXPECT_GT(farFeet, 0) << "the test should make feet reach beyond the ghost rows";
  }
}

TEST(ReconstructionSlabs, AnInterruptionOnOneRankStopsEveryRankWithoutAHang)
{
  auto comm = world();
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(unevenCircle(240), sltk::ReconstructionOptions{}, sltk::Context{}, plan).isOk());
  // Early (distance, marking, sweeps), in run 1's iterations and reinitialisations, and in a later run.
  for (const int stopAt : { 1, 3, 12, 60, 400 })
  {
    StopOnOneRank stop;
    stop.StopAt = comm->rank() == comm->size() - 1 ? stopAt : 0;
    sltk::Context ctx;
    ctx.Progress = &stop;
    sltk::ReconstructionResult<2> result;
    const sltk::Status status = sltk::reconstruct(plan, ctx, result, *comm);
    EXPECT_EQ(status.code(), sltk::StatusCode::Aborted) << "stop at check " << stopAt << ": " << status.message();
  }
}

TEST(ReconstructionSlabs, RanksWithDifferentCloudsAreRefusedTogether)
{
  auto comm = world();
  if (comm->size() < 2)
  {
    GTEST_SKIP() << "needs two ranks";
  }
  // The last rank holds one point fewer, as a piece of a split reader would.
  sltk::PointCloud<2> cloud = unevenCircle(240);
  if (comm->rank() == comm->size() - 1)
  {
    cloud.Points.pop_back();
  }
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, sltk::ReconstructionOptions{}, sltk::Context{}, plan).isOk());
  sltk::ReconstructionResult<2> result;
  const sltk::Status status = sltk::reconstruct(plan, sltk::Context{}, result, *comm);
  EXPECT_EQ(status.code(), sltk::StatusCode::InvalidArgument) << status.message();
  EXPECT_NE(status.message().find("different clouds"), std::string::npos) << status.message();
}

TEST(ReconstructionSlabs, UnevenlySampledCircleIsOneComponentOnEveryRank)
{
  // Its lower half 10 times sparser than its upper half: 4 h_P alone splits it; the link
  // that follows the local spacing (PointClusters.h) counts one component, on every rank.
  const sltk::PointCloud<2> cloud = sltk::unevenHalvesCircleCloud(0.5, { 0.0, 0.0 }, 0.005, 0.05);
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, sltk::ReconstructionOptions{}, sltk::Context{}, plan).isOk());
  sltk::ReconstructionResult<2> one, mine;
  ASSERT_TRUE(sltk::reconstruct(plan, sltk::Context{}, one).isOk());
  ASSERT_TRUE(sltk::reconstruct(plan, sltk::Context{}, mine, *world()).isOk());
  EXPECT_EQ(one.CloudComponents, 1);
  EXPECT_EQ(mine.CloudComponents, 1);
  EXPECT_EQ(mine.Pieces, one.Pieces);
}

TEST(ReconstructionSlabs, TwoCirclesAreTwoPiecesOnEveryRank)
{
  // Side by side along the slabs' axis, so that both pieces cross slab boundaries.
  sltk::PointCloud<2> cloud = sltk::circleCloud(96, 0.6, { 0.0, -0.9 });
  for (const auto& p : sltk::circleCloud(96, 0.6, { 0.0, 0.9 }).Points)
  {
    cloud.Points.push_back(p);
  }
  expectSameAsOneRank<2>(cloud, sltk::ReconstructionOptions{});
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, sltk::ReconstructionOptions{}, sltk::Context{}, plan).isOk());
  sltk::ReconstructionResult<2> mine;
  ASSERT_TRUE(sltk::reconstruct(plan, sltk::Context{}, mine, *world()).isOk());
  EXPECT_EQ(mine.Pieces, 2);
  EXPECT_EQ(mine.CloudComponents, 2);
  EXPECT_TRUE(mine.FitsCloud);
}

TEST(ReconstructionSlabs, InsideComponentsAreTheOneRankCount)
{
  // Random inside nodes (many components crossing the slab boundaries, some several
  // times): each rank labels its rows and the ranks merge what joins across them
  // (InsideComponents.h); the count is the whole field's on one rank.
  auto comm = world();
  for (unsigned seed = 1; seed <= 3; ++seed)
  {
    sltk::GridSpec<3> grid;
    grid.Dims = { 15, 12, 16 };
    grid.Spacing = { 1.0, 1.0, 1.0 };
    sltk::GridField<3> whole;
    whole.resize(grid, 2, 1.0);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (sltk::Index k = 0; k < grid.nodeCount(); ++k)
    {
      whole(whole.nodeIndex(k)) = u(random) < 0.3 ? -1.0 : 1.0;
    }
    sltk::SlabPlan all;
    all.End = all.Stop = grid.Dims[2];
    const std::int64_t one =
      sltk::insideComponents<3>(sltk::SlabNodes<3>(whole, grid, all, 0), sltk::serialCommunicator());
    sltk::SlabPlan slab;
    slab.Begin = sltk::evenSlabBegin(grid.Dims[2], comm->rank(), comm->size());
    slab.End = sltk::evenSlabBegin(grid.Dims[2], comm->rank() + 1, comm->size());
    slab.First = std::max<sltk::Index>(slab.Begin - 1, 0);
    slab.Stop = std::min(slab.End + 1, grid.Dims[2]);
    sltk::GridSpec<3> window = grid;
    window.Dims[2] = slab.windowRows();
    sltk::GridField<3> mine;
    mine.resize(window, 2, 1.0);
    for (sltk::Index k = 0; k < window.nodeCount(); ++k)
    {
      std::array<sltk::Index, 3> i = mine.nodeIndex(k);
      mine(i) = whole({ i[0], i[1], i[2] + slab.First });
    }
    EXPECT_EQ(sltk::insideComponents<3>(sltk::SlabNodes<3>(mine, grid, slab, comm->rank()), *comm), one)
      << "seed " << seed << ", rank " << comm->rank() << " of " << comm->size();
  }
}
