// SPDX-License-Identifier: BSD-3-Clause
// The memory check of a reconstruction split over ranks (SlabPolicy.h,
// planRunGrids): it sizes the windows of the ranks on this machine, so a grid
// too large for one rank is planned for 4 ranks on 4 machines, and refused
// for 4 ranks sharing one; the windows it sizes are the boundaries the slabs
// are cut at.
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/ReconstructionPlan.h"
#include "sltk/recon/SlabPolicy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace
{
sltk::ReconstructionOptions explicitGrid()
{
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.CellSizeFactor = 1.0;
  options.OutsideThresholdFactor = 10.0;
  options.Runs = 2;
  return options;
}
} // namespace

TEST(SlabPolicy, MemoryCheckSizesTheWindowsOfTheRanksOnThisMachine)
{
  sltk::ReconstructionOptions options = explicitGrid();
  sltk::ReconstructionPlan<3> whole;
  ASSERT_TRUE(sltk::planReconstruction(sltk::sphereCloud(2000), options, {}, whole).isOk());
  const double finest = static_cast<double>(whole.Grids.Runs.back().nodeCount()) * sltk::ReconstructionBytesPerNode;

  options.MemoryBudget = static_cast<std::uint64_t>(0.6 * finest); // the whole grid does not fit
  sltk::ReconstructionPlan<3> one, spread, shared;
  const sltk::Status refused = sltk::planReconstruction(sltk::sphereCloud(2000), options, {}, one);
  EXPECT_EQ(refused.code(), sltk::StatusCode::OutOfMemory) << refused.message();

  options.Ranks = 4; // on 4 machines: each holds a quarter and its ghost rows
  options.RanksHere = 1;
  const sltk::Status planned = sltk::planReconstruction(sltk::sphereCloud(2000), options, {}, spread);
  EXPECT_TRUE(planned.isOk()) << planned.message();
  EXPECT_EQ(spread.Grids.Runs.back().Dims, whole.Grids.Runs.back().Dims) << "the same grids on any rank count";

  options.RanksHere = 4; // all 4 on this machine: more than the whole grid
  const sltk::Status crowded = sltk::planReconstruction(sltk::sphereCloud(2000), options, {}, shared);
  EXPECT_EQ(crowded.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_NE(crowded.message().find("4 rank(s) on this machine"), std::string::npos) << crowded.message();
  EXPECT_NE(crowded.message().find("C_dx >="), std::string::npos) << crowded.message();
}

TEST(SlabPolicy, AutomaticCellSizePlansTheSameGridsForAnyRanksOnThisMachine)
{
  // No options: C_dx is the smallest whose finest grid fits the automatic 1 GiB
  // (AutomaticParameters.h), about 27M nodes here. Four ranks on this machine hold
  // more than that in their windows with ghost rows; the automatic budget chose
  // the grids and is not a limit, so they run the one-rank grids (issue: mpirun
  // -np 4 on the merged scans was refused).
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(20000);
  sltk::ReconstructionOptions options;
  options.Guess = sltk::InitialGuess::BoundingSphere; // K_P plays no part in the grids' size
  sltk::ReconstructionPlan<3> one, four;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, {}, one).isOk());
  ASSERT_GT(one.Options.CellSizeFactor, 1.0) << "the budget must bind for this test to say anything";
  options.Ranks = 4;
  options.RanksHere = 4;
  options.MemoryAvailable = std::uint64_t(64) << 30; // this machine holds the windows, whatever runs the test
  const sltk::Status planned = sltk::planReconstruction(cloud, options, {}, four);
  ASSERT_TRUE(planned.isOk()) << planned.message();
  EXPECT_EQ(four.Options.CellSizeFactor, one.Options.CellSizeFactor);
  ASSERT_EQ(four.Grids.Runs.size(), one.Grids.Runs.size());
  for (size_t r = 0; r < one.Grids.Runs.size(); ++r)
  {
    EXPECT_EQ(four.Grids.Runs[r].Dims, one.Grids.Runs[r].Dims) << "run " << r + 1;
  }
  // The same budget given as a limit, with the same C_dx, refuses the four windows.
  options.CellSizeFactor = one.Options.CellSizeFactor;
  options.MemoryBudget = sltk::AutomaticMemoryBudget;
  sltk::ReconstructionPlan<3> limited;
  const sltk::Status refused = sltk::planReconstruction(cloud, options, {}, limited);
  EXPECT_EQ(refused.code(), sltk::StatusCode::OutOfMemory) << "the case the automatic budget refused";
}

TEST(SlabPolicy, AutomaticCellSizeGrowsOnlyWhenTheWindowsOnThisMachineDoNotFit)
{
  // The rule (RunGridMemory.cxx, fitWindowsOnThisMachine): the one-rank
  // C_dx while the windows of this machine's ranks fit the limit (the budget
  // given, else the memory available); else the smallest C_dx of the 2% ladder
  // whose windows fit, instead of refusing what one rank runs.
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(4000);
  sltk::ReconstructionOptions options;
  options.Guess = sltk::InitialGuess::BoundingSphere; // K_P plays no part in the grids' size
  options.MemoryBudget = std::uint64_t(16) << 20;     // the smallest the front ends allow
  sltk::ReconstructionPlan<3> one;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, {}, one).isOk());
  ASSERT_GT(one.Options.CellSizeFactor, 1.0) << "the budget must bind for this test to say anything";

  const auto planned = [&](int ranks, int here, std::uint64_t available, sltk::ReconstructionPlan<3>& plan)
  {
    sltk::ReconstructionOptions o = options;
    o.Ranks = ranks;
    o.RanksHere = here;
    o.MemoryAvailable = available;
    const sltk::Status status = sltk::planReconstruction(cloud, o, {}, plan);
    EXPECT_TRUE(status.isOk()) << status.message();
    return plan.Options.CellSizeFactor;
  };
  sltk::ReconstructionPlan<3> spread, shared, roomy, tight;
  EXPECT_EQ(planned(4, 1, 0, spread), one.Options.CellSizeFactor) << "4 machines: each window fits, one rank's grids";
  const double crowded = planned(2, 2, 0, shared); // both on this machine: their windows must share the budget
  EXPECT_GT(crowded, one.Options.CellSizeFactor);
  EXPECT_NE(shared.Choices.end(),
    std::find_if(shared.Choices.begin(), shared.Choices.end(),
      [](const std::string& c) { return c.find("differ from one rank's") != std::string::npos; }));
  // The smallest that fits: one step down the ladder, given explicitly, is refused.
  sltk::ReconstructionOptions below = options;
  below.Ranks = below.RanksHere = 2;
  below.CellSizeFactor = crowded / 1.02 * (1.0 + 1e-9);
  sltk::ReconstructionPlan<3> refused;
  EXPECT_EQ(sltk::planReconstruction(cloud, below, {}, refused).code(), sltk::StatusCode::OutOfMemory);

  // No budget given: the one-rank C_dx (1 GiB) on any rank count where the memory is
  // available (the automatic budget sized the grid; it is no limit); where it is not,
  // the windows of the ranks here size it.
  options.MemoryBudget = 0;
  sltk::ReconstructionPlan<3> alone;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, {}, alone).isOk());
  EXPECT_EQ(planned(4, 4, std::uint64_t(64) << 30, roomy), alone.Options.CellSizeFactor);
  // Room for the whole grid only: 4 windows with their ghost rows hold more.
  const double wholeGrid = static_cast<double>(alone.Grids.Runs.back().nodeCount()) * sltk::ReconstructionBytesPerNode;
  EXPECT_GT(planned(4, 4, static_cast<std::uint64_t>(wholeGrid), tight), alone.Options.CellSizeFactor);
}

TEST(SlabPolicy, WindowsAreTheOwnedRowsAndTheirGhostRows)
{
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(2000);
  sltk::GridSpec<3> grid = sltk::uniformBox<3>(61, -1.2, 1.2);
  const std::vector<sltk::Index> one = sltk::slabBoundaries(grid, 1, cloud);
  EXPECT_EQ(one, (std::vector<sltk::Index>{ 0, 61 }));
  EXPECT_DOUBLE_EQ(sltk::largestSlabWindowNodes(grid, one), 61.0 * 61.0 * 61.0);
  const std::vector<sltk::Index> four = sltk::slabBoundaries(grid, 4, cloud);
  ASSERT_EQ(four.size(), 5u);
  sltk::Index widest = 0;
  for (size_t r = 0; r < 4; ++r)
  {
    EXPECT_GE(four[r + 1] - four[r], sltk::SlabGhostRows) << "rank " << r;
    const sltk::Index first = std::max<sltk::Index>(0, four[r] - sltk::SlabGhostRows);
    widest = std::max(widest, std::min<sltk::Index>(61, four[r + 1] + sltk::SlabGhostRows) - first);
  }
  EXPECT_DOUBLE_EQ(sltk::largestSlabWindowNodes(grid, four), 61.0 * 61.0 * static_cast<double>(widest));
  EXPECT_LT(widest, 61) << "a quarter of the rows and 12 ghost rows";
  // A finer later run is cut where these slabs meet.
  const sltk::GridSpec<3> finer = sltk::uniformBox<3>(121, -1.2, 1.2);
  const std::vector<sltk::Index> later = sltk::slabBoundaries(finer, 4, cloud, &grid, &four);
  for (size_t r = 1; r < 4; ++r)
  {
    EXPECT_EQ(later[r], 2 * four[r]) << "boundary " << r;
  }
}

TEST(SlabPolicy, LaterCutsFollowThePreviousBandWithinThePreviousWindows)
{
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(2000);
  const sltk::GridSpec<3> grid = sltk::uniformBox<3>(61, -1.2, 1.2);
  const sltk::GridSpec<3> finer = sltk::uniformBox<3>(121, -1.2, 1.2);
  const std::vector<sltk::Index> previous{ 0, 30, 61 };
  // All of the previous band in the top rows: the cut moves up as far as the transfer allows.
  std::vector<double> band(61, 0.0);
  for (size_t row = 50; row < 61; ++row)
  {
    band[row] = 100.0;
  }
  const auto [low, high] = sltk::laterCutRange(finer, grid, 30);
  EXPECT_EQ(low, 2 * (30 - sltk::SlabGhostRows + 2));
  EXPECT_EQ(high, 2 * (30 + sltk::SlabGhostRows - 3) + 1);
  const std::vector<sltk::Index> up = sltk::slabBoundaries(finer, 2, cloud, &grid, &previous, &band);
  const auto slack = static_cast<sltk::Index>(sltk::SlabRowShareSlack * 121 / 2);
  EXPECT_EQ(up[1], std::min(high, 60 + slack)) << "a tenth of a rank's rows from the even cut at most";
  // The lower rank's last owned row lies inside its previous window (rows up to 30 + ghost - 1) with a row to spare.
  EXPECT_LE(finer.coordinate(2, up[1] - 1), grid.coordinate(2, 30 + sltk::SlabGhostRows - 2));
  // With a wider slack the previous window would limit it: the range ends where the upper rank's window does.
  const std::vector<sltk::Index> wide{ 0, 24, 61 }; // previous cut far below the even one
  const std::vector<sltk::Index> limited = sltk::slabBoundaries(finer, 2, cloud, &grid, &wide, &band);
  EXPECT_EQ(limited[1], sltk::laterCutRange(finer, grid, 24).second);
  // A band even over the rows: the cut where the band halves, inside the range.
  std::fill(band.begin(), band.end(), 0.0);
  for (size_t row = 20; row < 44; ++row)
  {
    band[row] = 10.0;
  }
  const std::vector<sltk::Index> even = sltk::slabBoundaries(finer, 2, cloud, &grid, &previous, &band);
  EXPECT_NEAR(static_cast<double>(even[1]), 2.0 * 31.5, 1.0) << "the band's half at previous row 31.5";
  // Without a band: where the previous slabs meet. The memory check sizes the widest windows the cuts allow.
  const std::vector<sltk::Index> met = sltk::slabBoundaries(finer, 2, cloud, &grid, &previous);
  EXPECT_EQ(met[1], 60);
  const double widest = sltk::largestLaterSlabWindowNodes(finer, grid, previous);
  for (const auto& cut : { up, even, met })
  {
    EXPECT_LE(sltk::largestSlabWindowNodes(finer, cut), widest);
  }
  const sltk::Index lowestCut = std::max(low, 60 - slack); // the upper rank's window starts G rows below
  EXPECT_DOUBLE_EQ(widest, 121.0 * 121.0 * static_cast<double>(121 - (lowestCut - sltk::SlabGhostRows)));
}
