// SPDX-License-Identifier: BSD-3-Clause
// The tiled reconstruction (runs >= 2 on tiles of 8^D nodes) distributed over
// the ranks of MPI_COMM_WORLD (ctest: 1 and 2 ranks; also right on 3 and 4):
// every rank returns the one-rank iterations, band and stored nodes and tiles,
// and its own tiles hold the one-rank phi and d; the tiles gathered on rank 0
// are the one-rank field. The tiled runs add every sum in the one-rank order
// (Documentation/Octree.md, "Distributing the tiled band"), but run 1 is the
// uniform version on slabs, whose reductions add in MPI's order: the values
// may differ in the last bits (measured: E_2, Err_P and eps_1 within 4e-15
// relative, phi and d within 1e-15 of a cell), hence 1e-10.
#include "MpiWorld.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/octree/TiledReconstruction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{

/// Equal within `tolerance` (relative to `scale`), NaN equal to NaN (a distance not computed).
bool near(double x, double y, double tolerance, double scale)
{
  return (std::isnan(x) && std::isnan(y)) || std::fabs(x - y) <= tolerance * scale;
}

constexpr double Tolerance = 1e-10;

/// What a distributed run did on this rank.
struct RankRun
{
  int GhostLayers = 0;      ///< the most ghost layers a step read
  sltk::Index OwnTiles = 0; ///< the last run's tiles this rank owns
};

/// Plans the thesis's reconstruction of the circle of 64 points (every rank the same plan).
sltk::Status planThesisCircle(sltk::ReconstructionPlan<2>& plan)
{
  return sltk::planReconstruction(sltk::circleCloud(64), sltk::ReconstructionOptions::thesis(), sltk::Context{}, plan);
}

template <int D>
RankRun expectSameAsOneRank(const sltk::PointCloud<D>& cloud, const sltk::ReconstructionOptions& options)
{
  auto comm = world();
  sltk::ReconstructionPlan<D> plan;
  EXPECT_TRUE(sltk::planReconstruction(cloud, options, sltk::Context{}, plan).isOk());
  sltk::TiledReconstructionResult<D> one, mine;
  const sltk::Status oneStatus = sltk::reconstructTiled(plan, sltk::Context{}, one);
  EXPECT_TRUE(oneStatus.isOk()) << oneStatus.message();
  const sltk::Status status = sltk::reconstructTiled(plan, sltk::Context{}, mine, *comm);
  EXPECT_TRUE(status.isOk()) << status.message();
  if (!status.isOk() || !oneStatus.isOk() || mine.Records.History.size() != one.Records.History.size() ||
    mine.Storage.size() != one.Storage.size() || mine.Field.slotCount() != one.Field.slotCount())
  {
    ADD_FAILURE() << "the runs differ";
    return {};
  }
  // The pieces: the tiles' runs labelled by their owners, merged over the ranks (InsideComponents.h).
  EXPECT_GE(one.Records.Pieces, 1);
  EXPECT_EQ(mine.Records.Pieces, one.Records.Pieces);
  EXPECT_EQ(mine.Records.CloudComponents, one.Records.CloudComponents);
  EXPECT_EQ(mine.Records.FitsCloud, one.Records.FitsCloud);
  expectSameMissedPlaces(mine.Records.MissedPlaces, one.Records.MissedPlaces);
  for (size_t k = 0; k < one.Records.History.size(); ++k)
  {
    const auto &a = mine.Records.History[k], &b = one.Records.History[k];
    EXPECT_TRUE(a.Run == b.Run && a.Iteration == b.Iteration && near(a.Energy, b.Energy, Tolerance, b.Energy) &&
      near(a.CloudError, b.CloudError, Tolerance, b.CloudError) && near(a.Change, b.Change, Tolerance, b.Change) &&
      a.BandSize == b.BandSize && a.StoredNodes == b.StoredNodes && a.Leaves == b.Leaves &&
      b.LargestRankLeaves == b.Leaves && a.LargestRankLeaves <= a.Leaves &&
      a.LargestRankLeaves * comm->size() >= a.Leaves)
      << "run " << b.Run << " iteration " << b.Iteration << ": E_2 " << a.Energy << " / " << b.Energy << ", Err_P "
      << a.CloudError << " / " << b.CloudError << ", eps_1 " << a.Change << " / " << b.Change << ", band " << a.BandSize
      << " / " << b.BandSize << ", stored " << a.StoredNodes << " / " << b.StoredNodes << ", leaves " << a.Leaves
      << " / " << b.Leaves << ", the most on a rank " << a.LargestRankLeaves;
  }
  int layers = 0;
  for (size_t r = 0; r < one.Storage.size(); ++r)
  {
    EXPECT_EQ(mine.Storage[r].Tiles, one.Storage[r].Tiles) << "run " << one.Storage[r].Run;
    EXPECT_EQ(mine.Storage[r].Leaves, one.Storage[r].Leaves) << "run " << one.Storage[r].Run;
    layers = std::max(layers, mine.Storage[r].GhostLayers);
  }
  // This rank's own tiles against the one-rank field, slot by slot.
  const sltk::TiledField<D>& f = mine.Field;
  const sltk::TiledField<D>& g = one.Field;
  const double dx = g.grid().Spacing[0];
  sltk::Index own = 0, differ = 0;
  double gap = 0.0;
  for (std::int32_t id = 0; id < f.tileCount(); ++id)
  {
    const sltk::Index s = f.tileSlot(id);
    if (comm->size() > 1 && mine.Owners[static_cast<size_t>(s)] != comm->rank())
    {
      continue;
    }
    ++own;
    const std::int32_t other = g.slot(s);
    if (other < 0)
    {
      ++differ;
      continue;
    }
    for (sltk::Index k = 0; k < sltk::TiledField<D>::Nodes; ++k)
    {
      const double x = f.phi(id)[k], y = g.phi(other)[k], u = f.distance(id)[k], v = g.distance(other)[k];
      differ += near(x, y, Tolerance, dx) && near(u, v, Tolerance, dx) ? 0 : 1;
      gap = std::max({ gap, std::fabs(x - y), std::isnan(u) || std::isnan(v) ? 0.0 : std::fabs(u - v) });
    }
  }
  EXPECT_EQ(differ, 0) << "rank " << comm->rank() << ": nodes or tiles unlike the one-rank field";
  std::printf("rank %d of %d: %lld of %lld tiles own, %lld held, largest gap %.3g cells\n", comm->rank(), comm->size(),
    static_cast<long long>(own), static_cast<long long>(g.tileCount()), static_cast<long long>(f.tileCount()),
    gap / dx);
  // Gathered on rank 0: the one-rank field.
  sltk::gatherTiles(mine, *comm, 0);
  if (comm->rank() == 0)
  {
    EXPECT_EQ(mine.Field.tileCount(), g.tileCount());
    sltk::Index gathered = 0;
    for (sltk::Index s = 0; s < g.slotCount(); ++s)
    {
      const std::int32_t a = mine.Field.slot(s), b = g.slot(s);
      if (a < 0 || b < 0)
      {
        gathered += a == b ? 0 : 1;
        continue;
      }
      for (sltk::Index k = 0; k < sltk::TiledField<D>::Nodes; ++k)
      {
        gathered += near(mine.Field.phi(a)[k], g.phi(b)[k], Tolerance, dx) ? 0 : 1;
      }
    }
    EXPECT_EQ(gathered, 0) << "slots or nodes of the gathered field unlike the one-rank field";
  }
  return { layers, own };
}

} // namespace

TEST(TiledReconstructionRanks, CircleWithTheThesisParametersIsTheOneRankReconstruction)
{
  expectSameAsOneRank<2>(sltk::circleCloud(64), sltk::ReconstructionOptions::thesis());
}

TEST(TiledReconstructionRanks, TwoCirclesAreTwoPiecesOnEveryRank)
{
  // Two discs' pieces span tiles of several ranks: each rank labels its slots' nodes and the
  // ranks merge the pairs across their tiles (InsideComponents.h); the one-rank count. (The
  // runs' energies agree with one rank's to 1e-7 only here, so the pieces are compared alone.)
  sltk::PointCloud<2> cloud = sltk::circleCloud(96, 0.6, { -0.9, 0.0 });
  for (const auto& p : sltk::circleCloud(96, 0.6, { 0.9, 0.0 }).Points)
  {
    cloud.Points.push_back(p);
  }
  sltk::ReconstructionOptions options;
  options.OctreeStorage = true;
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, sltk::Context{}, plan).isOk());
  sltk::TiledReconstructionResult<2> one, mine;
  ASSERT_TRUE(sltk::reconstructTiled(plan, sltk::Context{}, one).isOk());
  ASSERT_TRUE(sltk::reconstructTiled(plan, sltk::Context{}, mine, *world()).isOk());
  EXPECT_EQ(one.Records.Pieces, 2);
  EXPECT_EQ(mine.Records.Pieces, 2);
  EXPECT_EQ(mine.Records.CloudComponents, 2);
  EXPECT_TRUE(mine.Records.FitsCloud);
}

TEST(TiledReconstructionRanks, SphereWithTheDefaultsIsTheOneRankReconstruction)
{
  // 200 points: 156 tiles, which the Morton partition shares out 63 / 93 on two ranks (checked
  // below). Every rank also runs the one-rank reconstruction, so under the sanitizers on a busy
  // machine the 2000 points this test had took over 5 minutes; 200 take 37-87 s on two ranks.
  sltk::ReconstructionOptions options;
  options.OctreeStorage = true;
  const RankRun run = expectSameAsOneRank<3>(sltk::sphereCloud(200), options);
  if (world()->size() == 2)
  {
    EXPECT_GT(run.OwnTiles, 0) << "the test should share the tiles out to both ranks";
  }
}

TEST(TiledReconstructionRanks, BallsSeededAroundALostFinAreTheOneRankBalls)
{
  // Run 1 at C_dx = 1 loses the fin; run 3's balls come from the tiles of run 2,
  // each rank's own points (recon/FarPointSeeds.h).
  sltk::ReconstructionOptions options;
  options.CellSizeFactor = 1.0;
  options.OctreeStorage = true;
  options.SeedFarPoints = true;
  expectSameAsOneRank<2>(sltk::discWithFinCloud(0.016), options);
}

TEST(TiledReconstructionRanks, LostPartIsNamedAsOnOneRank)
{
  // The needle of ReconstructionSlabs.LostPartIsNamedAsOnOneRank on the tiled band: each rank
  // finds the missed points in its own tiles, and every rank names the one rank's place.
  sltk::ReconstructionOptions options;
  options.CellSizeFactor = 1.0;
  options.OctreeStorage = true;
  options.Interpolator = sltk::InterpolatorKind::Weno3;
  options.SeedFarPoints = false;
  const sltk::PointCloud<2> cloud = sltk::circleWithNeedleCloud(19, 0.3);
  expectSameAsOneRank<2>(cloud, options);
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, sltk::Context{}, plan).isOk());
  sltk::TiledReconstructionResult<2> one;
  ASSERT_TRUE(sltk::reconstructTiled(plan, sltk::Context{}, one).isOk());
  EXPECT_FALSE(one.Records.FitsCloud) << "the needle was expected to be lost, and said";
}

TEST(TiledReconstructionRanks, SingleNodeSpecksAreMergedAsOnOneRank)
{
  // Run 2 of this noisy circle with the least-squares Q1 (5.5) leaves one single-node speck
  // (levelset/IsolatedNodes.h); a rank reads the neighbours in its ghost tiles.
  const sltk::PointCloud<2> cloud = sltk::withGaussianNoise(sltk::circleCloud(300), 0.01, 3);
  sltk::ReconstructionOptions options;
  options.OctreeStorage = true;
  options.Interpolator = sltk::InterpolatorKind::LeastSquaresQ1;
  expectSameAsOneRank<2>(cloud, options);
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, sltk::Context{}, plan).isOk());
  sltk::TiledReconstructionResult<2> mine;
  ASSERT_TRUE(sltk::reconstructTiled(plan, sltk::Context{}, mine, *world()).isOk());
  sltk::Index merged = 0;
  for (const auto& run : mine.Records.Runs)
  {
    merged += run.MergedNodes;
  }
  EXPECT_EQ(merged, 1) << "the one-rank run merges one speck";
}

TEST(TiledReconstructionRanks, FeetBeyondOneTileReadDeeperGhostLayers)
{
  // eta = 6 spreads the feet of runs 2 and 3 (4.9) beyond one tile of 8 nodes (p = 1: a stable run).
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.Schedule = { { 1.0, 0.0 }, { 1.0, 6.0 }, { 1.0, 6.0 } };
  const RankRun run = expectSameAsOneRank<2>(sltk::circleCloud(200), options);
  if (world()->size() > 1)
  {
    EXPECT_GT(run.GhostLayers, 1) << "the test should make feet reach beyond one ghost layer";
  }
}

TEST(TiledReconstructionRanks, ARankWithoutTilesTakesPartInEveryCollective)
{
  // Run 2's grid (29 x 29 nodes) has 4 x 4 slots, one block of the partition: one rank owns every tile.
  sltk::ReconstructionOptions options;
  options.Runs = 2;
  options.CellSizeFactor = 2.0;
  const RankRun run = expectSameAsOneRank<2>(sltk::circleCloud(24), options);
  const auto comm = world();
  const std::int64_t without = comm->allReduce(std::int64_t(run.OwnTiles == 0 ? 1 : 0), sltk::ReduceOp::Sum);
  if (comm->size() > 1)
  {
    EXPECT_EQ(without, comm->size() - 1) << "the test should leave a rank without tiles";
  }
}

TEST(TiledReconstructionRanks, AnInterruptionOnOneRankStopsEveryRankWithoutAHang)
{
  auto comm = world();
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(planThesisCircle(plan).isOk());
  // Every check of a whole reconstruction counted; then a stop in run 1 (uniform, on slabs), and in the
  // last tiled run's iterations.
  StopOnOneRank count;
  sltk::Context counting;
  counting.Progress = &count;
  sltk::TiledReconstructionResult<2> whole;
  ASSERT_TRUE(sltk::reconstructTiled(plan, counting, whole, *comm).isOk());
  ASSERT_GT(count.Calls, 10);
  for (const int stopAt : { 1, count.Calls / 2, count.Calls - 3, count.Calls })
  {
    StopOnOneRank stop;
    stop.StopAt = comm->rank() == comm->size() - 1 ? stopAt : 0;
    sltk::Context ctx;
    ctx.Progress = &stop;
    sltk::TiledReconstructionResult<2> result;
    const sltk::Status status = sltk::reconstructTiled(plan, ctx, result, *comm);
    EXPECT_EQ(status.code(), sltk::StatusCode::Aborted) << "stop at check " << stopAt << ": " << status.message();
  }
}

TEST(TiledReconstructionRanks, RanksWithDifferentCloudsAreRefusedTogether)
{
  auto comm = world();
  if (comm->size() < 2)
  {
    GTEST_SKIP() << "needs two ranks";
  }
  sltk::PointCloud<2> cloud = sltk::circleCloud(64);
  if (comm->rank() == comm->size() - 1)
  {
    cloud.Points.pop_back();
  }
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, sltk::ReconstructionOptions::thesis(), sltk::Context{}, plan).isOk());
  sltk::TiledReconstructionResult<2> result;
  const sltk::Status status = sltk::reconstructTiled(plan, sltk::Context{}, result, *comm);
  EXPECT_EQ(status.code(), sltk::StatusCode::InvalidArgument) << status.message();
  EXPECT_NE(status.message().find("different clouds"), std::string::npos) << status.message();
}

TEST(TiledReconstructionRanks, AFailureOnOneRankEndsEveryRankWithItsError)
{
  // The last rank alone has a memory budget too small for run 2's tiles (its check fails where
  // the others' pass): every rank returns its error, none waits in a collective.
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(planThesisCircle(plan).isOk());
  auto comm = world();
  if (comm->rank() == comm->size() - 1)
  {
    plan.Options.MemoryBudget = 4096;
  }
  sltk::TiledReconstructionResult<2> result;
  const sltk::Status status = sltk::reconstructTiled(plan, sltk::Context{}, result, *comm);
  EXPECT_EQ(status.code(), sltk::StatusCode::OutOfMemory) << status.message();
  EXPECT_NE(status.message().find("run 2 of the octree reconstruction needs"), std::string::npos) << status.message();
  if (comm->size() > 1)
  {
    EXPECT_NE(status.message().find("rank " + std::to_string(comm->size() - 1)), std::string::npos) << status.message();
  }
}
