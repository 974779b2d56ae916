// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/AutomaticParameters.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/CloudInitialData.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/Reconstruction.h"
#include "sltk/recon/StoppingRule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
/// A Fibonacci sphere of radius 0.8 with the cap z > cut removed: a hole whose
/// rim has radius 0.8 sqrt(1 - (cut / 0.8)^2).
sltk::PointCloud<3> sphereWithHole(int n, double cut)
{
  sltk::PointCloud<3> cloud;
  for (const auto& p : sltk::sphereCloud(n, 0.8).Points)
  {
    if (p[2] < cut)
    {
      cloud.Points.push_back(p);
    }
  }
  return cloud;
}

sltk::GridSpec<3> cubeGrid(int nodes, double half)
{
  sltk::GridSpec<3> g;
  for (int a = 0; a < 3; ++a)
  {
    g.Dims[a] = nodes;
    g.Origin[a] = -half;
    g.Spacing[a] = 2.0 * half / (nodes - 1);
  }
  return g;
}
} // namespace

TEST(AutomaticParameters, BottleneckAnswersEveryMarking)
{
  // markExternal(t) marks exactly the nodes whose bottleneck is >= t.
  const sltk::PointCloud<3> cloud = sphereWithHole(1500, 0.5);
  sltk::Context ctx;
  sltk::GridField<3, double> d;
  ASSERT_TRUE(sltk::distanceToCloud(cloud, cubeGrid(41, 1.2), ctx, d).isOk());
  std::vector<double> bottleneck;
  ASSERT_TRUE(sltk::outsideBottleneck(d, ctx, bottleneck).isOk());
  for (double t : { 0.05, 0.1, 0.2, 0.3, 0.45 })
  {
    std::vector<std::uint8_t> external;
    ASSERT_TRUE(sltk::markExternal(d, t, ctx, external).isOk());
    for (size_t k = 0; k < external.size(); ++k)
    {
      ASSERT_EQ(external[k] != 0, bottleneck[k] >= t) << "node " << k << " at threshold " << t;
    }
  }
}

TEST(AutomaticParameters, BottleneckIsTheWidestPathsFixedPoint)
{
  // Every value, bit for bit, against the relaxation b(n) = max(b(n), min(d(n), b(m)))
  // over axis neighbours m until nothing changes; d with many ties and a few +infinity.
  sltk::GridSpec<3> g = cubeGrid(9, 1.0);
  g.Dims = { 13, 11, 9 };
  sltk::GridField<3, double> d(g, 0, 0.0);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const unsigned h = static_cast<unsigned>(k) * 2654435761u;
    d(d.nodeIndex(k)) = h % 53 == 0 ? HUGE_VAL : 0.125 * static_cast<double>((h >> 7) % 9);
  }
  std::vector<double> bottleneck;
  ASSERT_TRUE(sltk::outsideBottleneck(d, sltk::Context{}, bottleneck).isOk());
  std::vector<double> reference(static_cast<size_t>(g.nodeCount()), -HUGE_VAL);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = d.nodeIndex(k);
    for (int a = 0; a < 3; ++a)
    {
      reference[static_cast<size_t>(k)] =
        i[a] == 0 || i[a] == g.Dims[a] - 1 ? HUGE_VAL : reference[static_cast<size_t>(k)];
    }
  }
  const sltk::Index stride[3] = { 1, g.Dims[0], g.Dims[0] * g.Dims[1] };
  for (bool changed = true; changed;)
  {
    changed = false;
    for (sltk::Index k = 0; k < g.nodeCount(); ++k)
    {
      const auto i = d.nodeIndex(k);
      for (int a = 0; a < 3; ++a)
      {
        for (int side : { -1, 1 })
        {
          auto n = i;
          n[a] += side;
          if (n[a] < 0 || n[a] >= g.Dims[a])
          {
            continue;
          }
          const double through = std::min(d(n), reference[static_cast<size_t>(k)]);
          double& b = reference[static_cast<size_t>(k + side * stride[a])];
          if (through > b)
          {
            b = through;
            changed = true;
          }
        }
      }
    }
  }
  for (size_t k = 0; k < reference.size(); ++k)
  {
    ASSERT_EQ(bottleneck[k], reference[k]) << "node " << k;
  }
}

TEST(AutomaticParameters, OutsideFactorBridgesHolesAndNoMore)
{
  sltk::Context ctx;
  for (double cut : { 2.0, 0.6 }) // closed sphere; a hole of radius 0.53
  {
    sltk::ReconstructionPlan<3> plan;
    sltk::ReconstructionOptions options; // automatic
    options.Runs = 1;
    ASSERT_TRUE(sltk::planReconstruction(sphereWithHole(4000, cut), options, ctx, plan).isOk());
    ASSERT_TRUE(plan.Enclosure.has_value());
    const double k = plan.Options.OutsideThresholdFactor;
    if (cut > 1.0)
    {
      EXPECT_EQ(k, 2.0) << "a closed sampling keeps the thesis's K_P";
    }
    else
    {
      // The initial surface must span the hole: 2 K_P h_P at least its diameter's
      // worth of closing (radius 0.53 -> about 0.53 / h_P), and no rung below does.
      EXPECT_GT(k * plan.CloudSpacing, 0.35) << "K_P = " << k << ", h_P = " << plan.CloudSpacing;
      const auto& ladder = sltk::outsideFactorLadder();
      const size_t best = static_cast<size_t>(std::find(ladder.begin(), ladder.end(), k) - ladder.begin());
      ASSERT_GT(best, 0u);
      EXPECT_LT(plan.Enclosure->EnclosedNodes[best - 1], plan.Enclosure->EnclosedNodes[best] / 10);
    }
  }
}

TEST(AutomaticParameters, OpenHoleReconstructsClosedWithDefaults)
{
  // The thesis's K_P = 2 loses the surface through the hole; the automatic K_P closes it.
  const sltk::PointCloud<3> cloud = sphereWithHole(3000, 0.6);
  sltk::Context ctx;
  sltk::ReconstructionOptions thesis = sltk::ReconstructionOptions::thesis();
  thesis.Runs = 1;
  sltk::ReconstructionResult<3> failed;
  EXPECT_FALSE(sltk::reconstruct(cloud, thesis, ctx, failed).isOk());
  sltk::ReconstructionOptions automatic;
  automatic.Runs = 1;
  sltk::ReconstructionResult<3> result;
  const sltk::Status status = sltk::reconstruct(cloud, automatic, ctx, result);
  ASSERT_TRUE(status.isOk()) << status.message();
  EXPECT_GT(result.OutsideThresholdFactor, 2.0);
  EXPECT_LT(result.Runs.back().CloudError, result.CloudSpacing);
  // The centre is inside.
  const auto& phi = result.SignedDistance;
  const auto& g = phi.spec();
  std::array<sltk::Index, 3> centre;
  for (int a = 0; a < 3; ++a)
  {
    centre[a] = static_cast<sltk::Index>(std::lround(-g.Origin[a] / g.Spacing[a]));
  }
  EXPECT_LT(phi(centre), 0.0);
}

TEST(AutomaticParameters, CellSizeFollowsTheBudget)
{
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(5000);
  sltk::Context ctx;
  sltk::ReconstructionOptions options;
  sltk::ReconstructionPlan<3> roomy, tight;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, ctx, roomy).isOk());
  EXPECT_EQ(roomy.Options.CellSizeFactor, 1.0) << "the thesis's C_dx when it fits";
  options.MemoryBudget = 64u << 20;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, ctx, tight).isOk());
  EXPECT_GT(tight.Options.CellSizeFactor, 1.0);
  EXPECT_LE(tight.memoryEstimate(3), 64.0 * (1 << 20));
  EXPECT_GT(tight.memoryEstimate(3), 0.8 * 64.0 * (1 << 20)) << "the smallest C_dx that fits, within 2% steps";
  // A coarser run 1 keeps the initial surface two of its cells from the cloud.
  EXPECT_GE(tight.Options.OutsideThresholdFactor, 2.0 * tight.Options.CellSizeFactor);
  EXPECT_EQ(roomy.Options.OutsideThresholdFactor, 2.0) << "C_dx = 1 starts the ladder at the thesis's K_P";
  // Given explicitly, C_dx is used as given and a grid beyond the budget is refused.
  options.CellSizeFactor = 1.0;
  sltk::ReconstructionPlan<3> refused;
  EXPECT_EQ(sltk::planReconstruction(cloud, options, ctx, refused).code(), sltk::StatusCode::OutOfMemory);
}

TEST(AutomaticParameters, LadderStartsTwoRunOneCellsOut)
{
  const auto& ladder = sltk::outsideFactorLadder();
  EXPECT_EQ(ladder[sltk::firstOutsideRung(1.0)], 2.0);
  EXPECT_EQ(ladder[sltk::firstOutsideRung(1.2)], 2.5);
  EXPECT_EQ(ladder[sltk::firstOutsideRung(3.28)], 8.0);
  EXPECT_EQ(ladder[sltk::firstOutsideRung(5.0)], 10.0);
  EXPECT_EQ(sltk::firstOutsideRung(100.0), ladder.size() - 1) << "the last rung when none is that large";
}

TEST(AutomaticParameters, CleaningRemovesOnlyGrossOutliers)
{
  sltk::PointCloud<3> cloud = sltk::sphereCloud(3000);
  sltk::Context ctx;
  sltk::CloudCleaningReport report;
  sltk::PointCloud<3> clean = cloud;
  ASSERT_TRUE(sltk::cleanCloud(clean, {}, ctx, report).isOk());
  EXPECT_EQ(report.OutliersRemoved, 0);
  cloud.Points.push_back({ 30.0, 0.0, 0.0 });
  ASSERT_TRUE(sltk::cleanCloud(cloud, {}, ctx, report).isOk());
  EXPECT_TRUE(report.AutomaticOutliers);
  EXPECT_GE(report.OutliersRemoved, 1);
  for (const auto& p : cloud.Points)
  {
    EXPECT_LT(p[0], 2.0);
  }
  sltk::CloudCleaningOptions asGiven;
  asGiven.Automatic = false;
  sltk::PointCloud<3> kept = sltk::sphereCloud(3000);
  kept.Points.push_back({ 30.0, 0.0, 0.0 });
  ASSERT_TRUE(sltk::cleanCloud(kept, asGiven, ctx, report).isOk());
  EXPECT_EQ(kept.size(), 3001);
}

TEST(AutomaticParameters, DenseCloudIsThinnedToTheGrid)
{
  // 200,000 points on a sphere under a 16 MB budget: far denser than the finest grid.
  sltk::Context ctx;
  sltk::ReconstructionOptions options;
  options.MemoryBudget = 16u << 20;
  sltk::ReconstructionPlan<3> plan;
  ASSERT_TRUE(sltk::planReconstruction(sltk::sphereCloud(200000), options, ctx, plan).isOk());
  EXPECT_TRUE(plan.Cleaning.AutomaticThinning);
  EXPECT_LT(plan.Cloud.size(), 50000);
  EXPECT_LE(plan.memoryEstimate(3), 16.0 * (1 << 20));
  options.Cleaning.Automatic = false;
  sltk::ReconstructionPlan<3> asGiven;
  ASSERT_TRUE(sltk::planReconstruction(sltk::sphereCloud(200000), options, ctx, asGiven).isOk());
  EXPECT_EQ(asGiven.Cloud.size(), 200000);
}

namespace
{
/// phi at the node nearest to p.
double phiNear(const sltk::GridField<2>& phi, double x, double y)
{
  const auto& g = phi.spec();
  const std::array<sltk::Index, 2> node{ static_cast<sltk::Index>(std::lround((x - g.Origin[0]) / g.Spacing[0])),
    static_cast<sltk::Index>(std::lround((y - g.Origin[1]) / g.Spacing[1])) };
  return phi(node);
}
} // namespace

TEST(AutomaticParameters, ThinFeatureLostByRunOneIsRecovered)
{
  sltk::Context ctx;
  const sltk::PointCloud<2> cloud = sltk::discWithFinCloud(0.016);
  // A fin 1.6 h_P thick. Given C_dx = 1, run 1 (cells of h_P) loses it; without
  // the seeds (the thesis's transfer) the later runs do not bring it back, and
  // it is said (the far points of the last run). WENO3 here and in the automatic C_dx
  // below: the least-squares Q1 (the automatic choice on this clean cloud) comes after.
  sltk::ReconstructionOptions given;
  given.Interpolator = sltk::InterpolatorKind::Weno3;
  given.CellSizeFactor = 1.0;
  given.SeedFarPoints = false;
  sltk::ReconstructionResult<2> lost;
  ASSERT_TRUE(sltk::reconstruct(cloud, given, ctx, lost).isOk());
  ASSERT_EQ(lost.Runs.size(), 3u);
  EXPECT_GT(lost.Runs.back().FarPoints, 0.01) << "above the warning threshold";
  EXPECT_GT(phiNear(lost.SignedDistance, 0.75, 0.0), 0.0) << "the fin was expected to be lost at C_dx = 1";
  EXPECT_TRUE(lost.Recoveries.empty()) << "an explicit C_dx is used as given";
  // The fin's points lie beyond the last run's band (|phi| cut at gamma = h_P here): they count as
  // far and as missed (RunIterations.h, FarBandShare), so the result says it does not fit the cloud
  // first, then what may help.
  EXPECT_GT(lost.Runs.back().MisfitPoints, sltk::FitShare);
  EXPECT_FALSE(lost.FitsCloud);
  ASSERT_EQ(lost.Warnings.size(), 2u) << "the result says what it does not fit, and what may help";
  EXPECT_NE(lost.Warnings[0].find("does not fit the cloud"), std::string::npos) << lost.Warnings[0];
  EXPECT_NE(lost.Warnings[1].find("try half the C_dx with one run fewer"), std::string::npos) << lost.Warnings[1];

  // With the seeds (SeedFarPoints), run 2 starts from run 1's surface united with
  // balls around the fin's points, and the fin grows back on the same grids.
  given.SeedFarPoints = true;
  sltk::ReconstructionResult<2> seeded;
  ASSERT_TRUE(sltk::reconstruct(cloud, given, ctx, seeded).isOk());
  ASSERT_EQ(seeded.Runs.size(), 3u);
  EXPECT_GT(seeded.Runs[0].FarPoints, 0.01) << "run 1 still loses the fin";
  EXPECT_LT(seeded.Runs.back().FarPoints, 0.01);
  EXPECT_TRUE(seeded.Recoveries.empty());
  EXPECT_TRUE(seeded.Warnings.empty()) << seeded.Warnings.front();
  EXPECT_LT(phiNear(seeded.SignedDistance, 0.75, 0.0), 0.0) << "the fin's middle is inside";
  EXPECT_GT(phiNear(seeded.SignedDistance, 0.75, 0.1), 0.0) << "beside the fin is outside";
  EXPECT_EQ(seeded.SignedDistance.spec().Spacing[0], lost.SignedDistance.spec().Spacing[0]);

  // Automatic C_dx without the seeds: the same first attempt, then half the cell
  // size with one run fewer, which keeps the fin and ends on the same finest grid.
  sltk::ReconstructionOptions automatic;
  automatic.Interpolator = sltk::InterpolatorKind::Weno3;
  automatic.SeedFarPoints = false;
  sltk::ReconstructionResult<2> kept;
  const sltk::Status status = sltk::reconstruct(cloud, automatic, ctx, kept);
  ASSERT_TRUE(status.isOk()) << status.message();
  ASSERT_EQ(kept.Recoveries.size(), 1u);
  EXPECT_NE(kept.Recoveries[0].find("reconstructed again from C_dx = 0.5"), std::string::npos) << kept.Recoveries[0];
  EXPECT_EQ(kept.CellSizeFactor, 0.5);
  EXPECT_EQ(kept.Runs.size(), 2u);
  EXPECT_LT(kept.Runs.back().FarPoints, 0.01);
  EXPECT_TRUE(kept.Warnings.empty()) << "the restart kept the fin: nothing to warn of";
  EXPECT_TRUE(kept.FitsCloud);
  EXPECT_LT(kept.Runs.back().MisfitPoints, 0.05);
  EXPECT_LT(phiNear(kept.SignedDistance, 0.75, 0.0), 0.0) << "the fin's middle is inside";
  EXPECT_GT(phiNear(kept.SignedDistance, 0.75, 0.1), 0.0) << "beside the fin is outside";
  EXPECT_EQ(kept.SignedDistance.spec().Spacing[0], lost.SignedDistance.spec().Spacing[0]) << "the same finest grid";

  // The automatic interpolator takes the least-squares Q1 on this clean cloud. Its run 1
  // loses the fin too but leaves under 1% of the points beyond one run-1 cell (0.5%); the
  // fin's points are missed all the same (more than FitShare beyond two finest cells and
  // h_P), which starts it again from half the C_dx as well, and the fin is kept.
  sltk::ReconstructionOptions chosen; // the defaults: the interpolator automatic
  chosen.SeedFarPoints = false;
  sltk::ReconstructionResult<2> leastSquares;
  ASSERT_TRUE(sltk::reconstruct(cloud, chosen, ctx, leastSquares).isOk());
  EXPECT_EQ(leastSquares.Interpolator, sltk::InterpolatorKind::LeastSquaresQ1);
  ASSERT_EQ(leastSquares.Recoveries.size(), 1u);
  EXPECT_NE(leastSquares.Recoveries[0].find("more than two finest cells and h_P from the surface with C_dx = 1"),
    std::string::npos)
    << leastSquares.Recoveries[0];
  EXPECT_EQ(leastSquares.CellSizeFactor, 0.5);
  EXPECT_LT(phiNear(leastSquares.SignedDistance, 0.75, 0.0), 0.0) << "the fin's middle is inside";
  EXPECT_GT(phiNear(leastSquares.SignedDistance, 0.75, 0.1), 0.0) << "beside the fin is outside";
  EXPECT_TRUE(leastSquares.FitsCloud);
  EXPECT_TRUE(leastSquares.Warnings.empty()) << leastSquares.Warnings.front();

  // With the seeds no restart is needed.
  // (WENO3: with the least-squares Q1 the seeds do not regrow the whole fin, and the
  // restart above keeps it.)
  sltk::ReconstructionOptions seeding;
  seeding.Interpolator = sltk::InterpolatorKind::Weno3;
  seeding.SeedFarPoints = true;
  sltk::ReconstructionResult<2> first;
  ASSERT_TRUE(sltk::reconstruct(cloud, seeding, ctx, first).isOk());
  EXPECT_TRUE(first.Recoveries.empty()) << first.Recoveries.front();
  EXPECT_EQ(first.CellSizeFactor, 1.0);
  EXPECT_LT(first.Runs.back().FarPoints, 0.01);
  EXPECT_LT(phiNear(first.SignedDistance, 0.75, 0.0), 0.0) << "the fin's middle is inside";
}

TEST(AutomaticParameters, ThinFeatureBrokenIntoPiecesIsRecoveredFromHalfTheCellSize)
{
  sltk::Context ctx;
  // A fin 1.2 h_P thick. The first attempt (C_dx = 1, three runs, the automatic
  // least-squares Q1) misses none of its points, yet its run 1's cells break the fin:
  // the result has 2 pieces where the cloud has 1 component. Parts thinner than the cells
  // broke apart, so it starts again from half the C_dx with one run fewer (the same
  // finest grid), whose result is one piece (WENO3 on the first attempt's grids loses the fin).
  const sltk::PointCloud<2> cloud = sltk::discWithFinCloud(0.012);
  sltk::ReconstructionOptions defaults;
  defaults.SeedFarPoints = false;
  sltk::ReconstructionResult<2> kept;
  const sltk::Status status = sltk::reconstruct(cloud, defaults, ctx, kept);
  ASSERT_TRUE(status.isOk()) << status.message();
  EXPECT_EQ(kept.Interpolator, sltk::InterpolatorKind::LeastSquaresQ1);
  ASSERT_EQ(kept.Recoveries.size(), 1u);
  EXPECT_NE(kept.Recoveries[0].find("the result has 2 pieces where the cloud has 1"), std::string::npos)
    << kept.Recoveries[0];
  EXPECT_NE(kept.Recoveries[0].find("reconstructed again from C_dx = 0.5 with 2 run(s)"), std::string::npos)
    << kept.Recoveries[0];
  EXPECT_EQ(kept.CellSizeFactor, 0.5);
  EXPECT_EQ(kept.Runs.size(), 2u);
  EXPECT_EQ(kept.Pieces, 1);
  EXPECT_EQ(kept.CloudComponents, 1);
  EXPECT_TRUE(kept.FitsCloud);
  EXPECT_TRUE(kept.Warnings.empty()) << kept.Warnings.front();
  EXPECT_LT(phiNear(kept.SignedDistance, 0.75, 0.0), 0.0) << "the fin's middle is inside";
  EXPECT_GT(phiNear(kept.SignedDistance, 0.75, 0.1), 0.0) << "beside the fin is outside";
}

TEST(AutomaticParameters, ResultThatMissesTheCloudSaysSo)
{
  // A circle with a needle of points (no thickness) reaching 1.5 radii out: run 1's cells
  // of C_dx = 4 cannot hold the needle, so its far half is missed (more than FitShare).
  const sltk::PointCloud<2> cloud = sltk::circleWithNeedleCloud(80, 1.5);
  sltk::ReconstructionOptions options;
  options.CellSizeFactor = 4.0;
  options.Runs = 1;
  sltk::Context ctx;
  sltk::ReconstructionResult<2> result;
  ASSERT_TRUE(sltk::reconstruct(cloud, options, ctx, result).isOk());
  EXPECT_GT(result.Runs.back().MisfitPoints, sltk::FitShare);
  EXPECT_FALSE(result.FitsCloud);
  ASSERT_FALSE(result.Warnings.empty());
  EXPECT_NE(result.Warnings[0].find("the result does not fit the cloud"), std::string::npos) << result.Warnings[0];
  // And where: the needle's missed far part is one place, on the needle, in the user's units.
  ASSERT_EQ(result.MissedPlaces.size(), 1u) << result.Warnings[0];
  const sltk::MissedPlace<2>& needle = result.MissedPlaces[0];
  EXPECT_GT(needle.Points, 0.05 * 480);
  EXPECT_GT(needle.Lower[0], 1.0);
  EXPECT_EQ(needle.Upper[0], 2.5) << "the needle's tip";
  EXPECT_EQ(needle.Lower[1], 0.0);
  EXPECT_EQ(needle.Upper[1], 0.0);
  EXPECT_NE(
    result.Warnings[0].find("outside it they gather at " + std::to_string(needle.Points) + " point(s) (of the "),
    std::string::npos)
    << result.Warnings[0];
}

TEST(AutomaticParameters, LostPartUnderTheMisfitShareSaysSo)
{
  // The circle with a needle of points (no thickness) 0.3 radii long, 4.5% of the cloud: the
  // cells of C_dx = 1 and WENO3 lose it, and its points are under FitShare. But the surface
  // misses nearly every point where the needle was, which is a lost part (lostPart,
  // MissedPlaces.h): the result says so, and where.
  sltk::PointCloud<2> cloud = sltk::circleWithNeedleCloud(19, 0.3);
  sltk::ReconstructionOptions options;
  options.CellSizeFactor = 1.0;
  options.Interpolator = sltk::InterpolatorKind::Weno3;
  options.SeedFarPoints = false;
  sltk::Context ctx;
  sltk::ReconstructionResult<2> result;
  ASSERT_TRUE(sltk::reconstruct(cloud, options, ctx, result).isOk());
  EXPECT_GT(result.Runs.back().MisfitPoints, sltk::LostPartShare);
  EXPECT_LT(result.Runs.back().MisfitPoints, sltk::FitShare) << "the share alone would call it a fit";
  ASSERT_FALSE(result.MissedPlaces.empty());
  const sltk::MissedPlace<2>& needle = result.MissedPlaces[0];
  EXPECT_GE(needle.Points, sltk::LostPartMissed * needle.Nearby) << needle.Points << " of " << needle.Nearby;
  EXPECT_DOUBLE_EQ(needle.Upper[0], 1.3) << "the needle's tip";
  EXPECT_FALSE(result.FitsCloud);
  ASSERT_FALSE(result.Warnings.empty());
  EXPECT_NE(result.Warnings[0].find("the result does not fit the cloud: it lost a part of the model, " +
              std::to_string(needle.Points) + " of the " + std::to_string(needle.Nearby) + " points around ("),
    std::string::npos)
    << result.Warnings[0];
  EXPECT_NE(result.Warnings[0].find("a C_dx below the 1 that ran"), std::string::npos) << result.Warnings[0];

  // With the automatic C_dx the lost part starts it again from half the C_dx; the needle, no
  // thicker than its points, is lost there too, and the result says so with the C_dx that ran.
  options.CellSizeFactor = 0.0;
  sltk::ReconstructionResult<2> again;
  ASSERT_TRUE(sltk::reconstruct(cloud, options, ctx, again).isOk());
  ASSERT_EQ(again.Recoveries.size(), 1u);
  EXPECT_NE(again.Recoveries[0].find("(a part of the model lost) with C_dx = 1: reconstructed again from C_dx = 0.5"),
    std::string::npos)
    << again.Recoveries[0];
  EXPECT_FALSE(again.FitsCloud);
  ASSERT_FALSE(again.Warnings.empty());
  EXPECT_NE(again.Warnings[0].find("a C_dx below the 0.5 that ran"), std::string::npos) << again.Warnings[0];

  // The circle alone fits: no place is a lost part.
  cloud.Points.resize(400);
  sltk::ReconstructionResult<2> circle;
  ASSERT_TRUE(sltk::reconstruct(cloud, options, ctx, circle).isOk());
  EXPECT_TRUE(circle.FitsCloud) << circle.Warnings.front();
}

TEST(AutomaticParameters, StalledRunFollowsFarPoints)
{
  // A loose energy tolerance stops the thesis's rule (4.33) after 2 iterations,
  // while the initial surface, 10 h_P out, is still far from the points;
  // following the far points goes on until the surface has reached them.
  sltk::PointCloud<2> circle;
  for (int k = 0; k < 300; ++k)
  {
    const double a = 2.0 * 3.14159265358979323846 * k / 300.0;
    circle.Points.push_back({ 0.5 * std::cos(a), 0.5 * std::sin(a) });
  }
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.OutsideThresholdFactor = 10.0;
  options.Runs = 1;
  options.Tolerance = 0.5;
  options.MinIterations = 2;
  sltk::Context ctx;
  sltk::ReconstructionResult<2> energyOnly, following;
  ASSERT_TRUE(sltk::reconstruct(circle, options, ctx, energyOnly).isOk());
  options.FollowFarPoints = true;
  ASSERT_TRUE(sltk::reconstruct(circle, options, ctx, following).isOk());
  EXPECT_GT(energyOnly.Runs[0].FarPoints, 0.01);
  EXPECT_GT(following.Runs[0].Iterations, energyOnly.Runs[0].Iterations);
  EXPECT_LE(following.Runs[0].FarPoints, 0.01);
}
