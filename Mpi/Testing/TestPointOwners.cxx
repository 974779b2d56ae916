// SPDX-License-Identifier: BSD-3-Clause
// Points sent to the ranks that own their slabs, with halos (PointOwners.h), and
// h_P computed from them (CloudSpacing.h cloudSpacingOnRanks): on any number of
// ranks, and whatever share of the cloud each rank read, the one-rank value bit for bit.
#include "MpiWorld.h"

#include "sltk/cloud/CloudCleaning.h"
#include "sltk/cloud/CloudFileShares.h"
#include "sltk/cloud/CloudNoise.h"
#include "sltk/cloud/CloudOutliers.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/CloudThinning.h"
#include "sltk/cloud/LinkedComponents.h"
#include "sltk/cloud/LocalSpacing.h"
#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/core/ExactSum.h"
#include "sltk/exec/OrderStatistics.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/LocalOffset.h"
#include "sltk/recon/MissedPlaces.h"
#include "sltk/recon/PointClusters.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>

namespace
{
using Points = std::vector<std::array<double, 3>>;

/// Rank `rank`'s share of `cloud` as a parallel read leaves it (CloudFileShares.h's
/// cut); `allOnRankZero`: rank 0 read the whole file, the others nothing.
Points shareOf(const Points& cloud, const sltk::Communicator& comm, bool allOnRankZero = false)
{
  const std::int64_t n = static_cast<std::int64_t>(cloud.size());
  sltk::FileShare s = sltk::shareOf(0, n, comm.rank(), comm.size());
  if (allOnRankZero)
  {
    s = comm.rank() == 0 ? sltk::FileShare{ 0, n } : sltk::FileShare{ n, n };
  }
  return Points(cloud.begin() + s.Begin, cloud.begin() + s.End);
}

/// The points of an x y z file of the shared data; none when /work/shared is absent.
Points sharedCloud(const std::string& path)
{
  Points cloud;
  std::ifstream in("/work/shared/data/clouds/" + path);
  double x, y, z;
  while (in >> x >> y >> z)
  {
    cloud.push_back({ x, y, z });
  }
  return cloud;
}

/// The 10 registered Stanford bunny scans, merged (362,272 points).
Points stanfordScans()
{
  return sharedCloud("bunny/scans/bunny_scans_registered.xyz");
}

/// A context of two threads for the statistics.
struct TwoThreads
{
  sltk::ThreadPool Pool{ 2 };
  sltk::Context Ctx;
  TwoThreads() { this->Ctx.Executor = &this->Pool; }
};

/// `n` points uniform in a box [0, 4] x [0, 1] x [0, 1], the same on every rank.
Points boxCloud(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points p(static_cast<size_t>(n));
  for (auto& x : p)
  {
    x = { 4.0 * u(rng), u(rng), u(rng) };
  }
  return p;
}

/// `cloud` with its x coordinates moved to axis `axis` (the others shifted along): a box long along that axis.
Points rotated(const Points& cloud, int axis)
{
  Points out(cloud.size());
  for (size_t j = 0; j < cloud.size(); ++j)
  {
    for (int a = 0; a < 3; ++a)
    {
      out[j][static_cast<size_t>((a + axis) % 3)] = cloud[j][static_cast<size_t>(a)];
    }
  }
  return out;
}

sltk::OwnedPoints<3> owners(const Points& cloud, const sltk::Communicator& comm, double halo, bool allOnRankZero)
{
  const sltk::PointCloud<3> mine{ shareOf(cloud, comm, allOnRankZero) };
  const sltk::SlabCuts cuts = sltk::balancedCuts(mine, comm);
  sltk::OwnedPoints<3> owned;
  const sltk::Status s = sltk::sendToOwners(mine, sltk::firstGlobalIndex(mine.size(), comm), cuts, halo, comm, owned);
  EXPECT_TRUE(s.isOk()) << s.message();
  return owned;
}

/// h_P on the ranks (starting from `halo`) against one rank's, bit for bit.
void expectOneRankSpacing(const Points& cloud, int k, double halo, bool allOnRankZero = false)
{
  auto comm = world();
  const TwoThreads threads;
  const sltk::Context& ctx = threads.Ctx;
  sltk::CloudSpacingOptions options;
  options.DensityNeighbours = k;
  double one = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(sltk::PointCloud<3>{ cloud }, ctx, one, options).isOk());
  sltk::OwnedPoints<3> owned = owners(cloud, *comm, halo, allOnRankZero);
  double ranks = 0.0;
  std::int64_t remote = 0;
  const sltk::Status s =
    sltk::cloudSpacingOnRanks(owned, static_cast<std::int64_t>(cloud.size()), *comm, ctx, ranks, options, &remote);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(ranks, one) << "k = " << k << " on " << comm->size() << " ranks, halo " << halo;
  EXPECT_TRUE(comm->size() > 1 || remote == 0); // one rank holds every neighbour
}

/// The cloud's noise on the ranks (from a halo of 0) against one rank's, bit for bit.
void expectOneRankNoise(const Points& cloud, bool allOnRankZero = false)
{
  auto comm = world();
  const TwoThreads threads;
  const sltk::Context& ctx = threads.Ctx;
  const sltk::PointCloud<3> whole{ cloud };
  const sltk::PointLocator<3> locator(whole);
  double spacing = 0.0, one = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(locator, ctx, spacing).isOk());
  ASSERT_TRUE(sltk::cloudNoise(locator, spacing, ctx, one).isOk());
  sltk::OwnedPoints<3> owned = owners(cloud, *comm, 0.0, allOnRankZero);
  double ranks = 0.0;
  const sltk::Status s =
    sltk::cloudNoiseOnRanks(owned, static_cast<std::int64_t>(cloud.size()), spacing, *comm, ctx, ranks);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(ranks, one) << "on " << comm->size() << " ranks";
}
} // namespace

TEST(PointOwners, EveryPointHasOneOwnerAndItsSlabsNeighboursAsHalo)
{
  auto comm = world();
  const Points cloud = boxCloud(4000, 7);
  const double width = 0.05;
  for (bool allOnRankZero : { false, true })
  {
    const sltk::OwnedPoints<3> owned = owners(cloud, *comm, width, allOnRankZero);
    const sltk::SlabCuts& cuts = owned.Cuts;
    ASSERT_EQ(cuts.ranks(), comm->size());
    EXPECT_EQ(cuts.Axis, 0); // the box's longest axis
    // Every global index once over the ranks' own points.
    std::vector<std::int64_t> mine, halo;
    for (size_t j = 0; j < owned.Ids.size(); ++j)
    {
      (owned.Mine[j] ? mine : halo).push_back(owned.Ids[j]);
      ASSERT_TRUE(j == 0 || owned.Ids[j - 1] < owned.Ids[j]); // increasing global index, as one rank holds them
      ASSERT_EQ(owned.ownedLocal(owned.Ids[j]), owned.Mine[j] ? static_cast<std::int64_t>(j) : -1);
    }
    EXPECT_EQ(static_cast<std::int64_t>(mine.size()), owned.Owned);
    std::vector<std::int64_t> all = comm->allGatherV(mine);
    std::sort(all.begin(), all.end());
    ASSERT_EQ(all.size(), cloud.size());
    for (size_t j = 0; j < all.size(); ++j)
    {
      ASSERT_EQ(all[j], static_cast<std::int64_t>(j));
    }
    // About a rank's share each (the cuts from 128 order statistics per rank).
    EXPECT_NEAR(static_cast<double>(owned.Owned), 4000.0 / comm->size(), 0.05 * 4000.0 / comm->size());
    // The held points: exactly the cloud's points within the halo of this rank's slab.
    const double lower = cuts.Lower[static_cast<size_t>(comm->rank())];
    const double upper = cuts.Lower[static_cast<size_t>(comm->rank()) + 1];
    std::vector<std::int64_t> own, halos;
    for (size_t j = 0; j < cloud.size(); ++j)
    {
      const double x = cloud[j][0];
      if (x >= lower && x < upper)
      {
        own.push_back(static_cast<std::int64_t>(j));
      }
      else if (x >= lower - width && x < upper + width)
      {
        halos.push_back(static_cast<std::int64_t>(j));
      }
    }
    EXPECT_EQ(mine, own);
    EXPECT_EQ(halo, halos);
    for (size_t j = 0; j < owned.Ids.size(); ++j)
    {
      ASSERT_EQ(owned.Cloud.Points[j], cloud[static_cast<size_t>(owned.Ids[j])]);
    }
  }
}

TEST(PointOwners, AnInfiniteHaloHoldsTheWholeCloudAndBadCutsAreRefused)
{
  auto comm = world();
  const Points cloud = boxCloud(300, 3);
  const sltk::OwnedPoints<3> owned = owners(cloud, *comm, std::numeric_limits<double>::infinity(), true);
  EXPECT_EQ(owned.held(), 300);
  std::set<std::int64_t> ids(owned.Ids.begin(), owned.Ids.end());
  EXPECT_EQ(ids.size(), 300u);
  sltk::OwnedPoints<3> out;
  sltk::SlabCuts wrong;
  wrong.Lower = { -1.0, 1.0 }; // one rank's cuts
  wrong.Lower.resize(static_cast<size_t>(comm->size()) + 2, 2.0);
  EXPECT_FALSE(sltk::sendToOwners(sltk::PointCloud<3>{ cloud }, 0, wrong, 0.1, *comm, out).isOk());
  EXPECT_FALSE(sltk::sendToOwners(sltk::PointCloud<3>{ cloud }, 0, owned.Cuts, -1.0, *comm, out).isOk());
}

TEST(CloudSpacingOnRanks, IsTheOneRankValueBitForBit)
{
  const Points box = boxCloud(5000, 11);
  for (int k : { 0, 8 })
  {
    expectOneRankSpacing(box, k, 0.0);       // every neighbour across a cut found by the ranks beyond it
    expectOneRankSpacing(box, k, 0.2, true); // a halo wide enough at once; one rank read everything
  }
  // A sphere's samples, and the same points twice (duplicates: distance 0, skipped).
  const sltk::PointCloud<3> sphere = sltk::sphereCloud(3000);
  expectOneRankSpacing(sphere.Points, 0, 0.0);
  Points twice = sphere.Points;
  twice.insert(twice.end(), sphere.Points.begin(), sphere.Points.begin() + 1000);
  expectOneRankSpacing(twice, 0, 0.0);
  expectOneRankSpacing(twice, 8, 0.0);
  // Points on a line along the cut axis, spaced unevenly: every neighbour is across a slab's end
  // for some point, and a rank may own only a few.
  Points line;
  for (int i = 0; i < 400; ++i)
  {
    line.push_back({ i * (1.0 + 0.01 * (i % 7)), 0.5 * (i % 3), 0.0 });
  }
  expectOneRankSpacing(line, 0, 0.0);
  expectOneRankSpacing(line, 8, 0.0);
}

TEST(CloudNoiseOnRanks, IsTheOneRankValueBitForBit)
{
  expectOneRankNoise(boxCloud(5000, 13));
  expectOneRankNoise(boxCloud(30000, 17), true); // more points than samples: every 15th
  Points noisy = sltk::sphereCloud(4000).Points;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> jitter(0.0, 0.01);
  for (auto& p : noisy)
  {
    p = { p[0] + jitter(rng), p[1] + jitter(rng), p[2] + jitter(rng) };
  }
  expectOneRankNoise(noisy);
  // Equidistant neighbours (a lattice): the fits take them in the order one rank does.
  Points lattice;
  for (int i = 0; i < 40; ++i)
  {
    for (int j = 0; j < 20; ++j)
    {
      lattice.push_back({ 0.5 * i, 0.5 * j, 0.01 * ((i * 7 + j * 3) % 5) });
    }
  }
  expectOneRankNoise(lattice);
  sltk::OwnedPoints<3> few = owners(lattice, *world(), 0.0, false);
  double noise = 0.0;
  EXPECT_FALSE(sltk::cloudNoiseOnRanks(few, 12, 1.0, *world(), sltk::Context{}, noise).isOk()); // 12 points: too few
}

TEST(CloudSpacingOnRanks, TheMergedStanfordScansGiveTheOneRankSpacingAndNoise)
{
  const Points cloud = stanfordScans();
  if (cloud.empty())
  {
    GTEST_SKIP() << "the Stanford scans (/work/shared) are not available";
  }
  expectOneRankSpacing(cloud, 0, 0.0);
  expectOneRankSpacing(cloud, 8, 0.0);
  expectOneRankNoise(cloud);
}

namespace
{
/// The outlier test on the ranks against one rank's: the same report, and the
/// same points kept, each under its index in the kept cloud.
void expectOneRankOutliers(const Points& cloud, const sltk::OutlierOptions& options, std::int64_t removed)
{
  auto comm = world();
  const TwoThreads threads;
  const sltk::Context& ctx = threads.Ctx;
  sltk::PointCloud<3> kept;
  sltk::OutlierReport one, ranks;
  ASSERT_TRUE(sltk::removeOutliers(sltk::PointCloud<3>{ cloud }, options, ctx, kept, one).isOk());
  EXPECT_EQ(one.Removed, removed);
  sltk::OwnedPoints<3> owned = owners(cloud, *comm, 0.0, false);
  std::int64_t total = static_cast<std::int64_t>(cloud.size());
  const sltk::Status s = sltk::removeOutliersOnRanks(owned, total, options, *comm, ctx, ranks);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(ranks.Removed, one.Removed);
  EXPECT_EQ(ranks.Threshold, one.Threshold);
  EXPECT_EQ(ranks.MeanNeighbourDistance, one.MeanNeighbourDistance);
  EXPECT_EQ(ranks.LargestRatio, one.LargestRatio);
  ASSERT_EQ(total, kept.size());
  for (size_t j = 0; j < owned.Ids.size(); ++j)
  {
    ASSERT_LT(owned.Ids[j], total);
    ASSERT_EQ(owned.Cloud.Points[j], kept.Points[static_cast<size_t>(owned.Ids[j])]) << "global index " << owned.Ids[j];
  }
  EXPECT_EQ(comm->allReduce(owned.Owned, sltk::ReduceOp::Sum), total);
}
} // namespace

TEST(RemoveOutliersOnRanks, RemovesTheOneRankPointsAndRenumbersTheRest)
{
  Points cloud = sltk::sphereCloud(3000).Points;
  // Gross outliers among the points (their indices interleave with the sphere's), one beyond the cloud's end.
  cloud.insert(cloud.begin() + 100, { 9.0, 0.0, 0.0 });
  cloud.insert(cloud.begin() + 2000, { 0.0, -7.0, 0.5 });
  cloud.push_back({ 0.0, 0.0, 12.0 });
  sltk::OutlierOptions options;
  expectOneRankOutliers(cloud, options, 3);
  options.GrossRatio = 20.0; // the automatic cleaning's gate: these are gross
  expectOneRankOutliers(cloud, options, 3);
  options.GrossRatio = 1e6; // no point that far: none removed
  expectOneRankOutliers(cloud, options, 0);
  Points box = boxCloud(4000, 23); // a uniform box: the 3-sigma tail alone
  options = sltk::OutlierOptions{};
  sltk::PointCloud<3> kept;
  sltk::OutlierReport report;
  ASSERT_TRUE(sltk::removeOutliers(sltk::PointCloud<3>{ box }, options, sltk::Context{}, kept, report).isOk());
  ASSERT_GT(report.Removed, 0);
  expectOneRankOutliers(box, options, report.Removed);
}

TEST(RankStatistics, ExactSumsAndOrderStatisticsAreTheOneRankValues)
{
  auto comm = world();
  std::mt19937_64 rng(29);
  std::lognormal_distribution<double> spread(0.0, 3.0);
  std::vector<double> all(10001);
  for (double& v : all)
  {
    v = spread(rng) * (rng() % 5 == 0 ? -1.0 : 1.0);
  }
  all[17] = all[400] = all[9000]; // equal values
  // Each rank its residue class: a split unlike any contiguous share.
  std::vector<double> mine;
  sltk::ExactSum split, whole;
  for (size_t j = 0; j < all.size(); ++j)
  {
    whole.add(all[j]);
    if (static_cast<int>(j % static_cast<size_t>(comm->size())) == comm->rank())
    {
      mine.push_back(all[j]);
      split.add(all[j]);
    }
  }
  split.reduceOver(*comm);
  EXPECT_EQ(split.value(), whole.value());
  std::vector<double> sorted = all;
  std::sort(sorted.begin(), sorted.end());
  for (std::int64_t k :
    { std::int64_t(0), std::int64_t(1), std::int64_t(5000), std::int64_t(9999), std::int64_t(10000) })
  {
    EXPECT_EQ(sltk::kthSmallestOverRanks(mine, k, *comm), sorted[static_cast<size_t>(k)]) << "k = " << k;
  }
}

TEST(RemoveOutliersOnRanks, TheMergedStanfordScansLoseTheOneRankPoints)
{
  const Points cloud = stanfordScans();
  if (cloud.empty())
  {
    GTEST_SKIP() << "the Stanford scans (/work/shared) are not available";
  }
  sltk::OutlierOptions options;
  options.GrossRatio = sltk::GrossOutlierRatio; // the automatic cleaning's
  expectOneRankOutliers(cloud, options, 509);
}

TEST(CloudSpacingOnRanks, AHaloAtSurveyCoordinatesKeepsTheOneRankValue)
{
  // A cut at 5e6 with a halo of 0.1: U + 0.1 rounds below the real sum there, so a point at
  // fl(U + 0.1) is not sent to the lower slab though it lies within 0.1 of the cut; a point just
  // below the cut must then not take a held neighbour 0.1000000007 away as its nearest.
  const double cut = 5e6, halo = 0.1, x = std::nextafter(cut, 0.0);
  const Points cloud = { { cut - 10, 0, 0 }, { cut - 10, 1, 0 }, { cut - 10, 2, 0 }, { x, 0, 0 },
    { x, 0.1000000007, 0 }, { cut, 5, 0 }, { cut + halo, 0, 0 }, { cut + 10, 0, 0 }, { cut + 10, 1, 0 },
    { cut + 10, 2, 0 }, { cut + 10, 3, 0 } };
  expectOneRankSpacing(cloud, 0, halo);
}

TEST(PointOwners, ANeighbourTiedAtTheRadiusAcrossACutIsACandidate)
{
  // y lies at exactly the computed distance R = x_a - y_a from x, but below fl(x_a - R), where the
  // cut is: the rank that owns y must still be asked about x's neighbours within R.
  auto comm = world();
  const double xa = 0.763774618976614, ya = -0.2550690257394217, radius = xa - ya;
  const Points cloud = { { ya, 0, 0 }, { xa, radius, 0 }, { xa, 0, 0 } }; // y (index 0), z, x
  sltk::SlabCuts cuts;
  cuts.Lower.assign(static_cast<size_t>(comm->size()) + 1, std::numeric_limits<double>::infinity());
  cuts.Lower[0] = -std::numeric_limits<double>::infinity();
  if (comm->size() > 1)
  {
    cuts.Lower[1] = xa - radius;
    ASSERT_LT(ya, cuts.Lower[1]);
  }
  sltk::OwnedPoints<3> owned;
  const sltk::PointCloud<3> mine{ comm->rank() == 0 ? cloud : Points{} };
  ASSERT_TRUE(sltk::sendToOwners(mine, 0, cuts, 0.0, *comm, owned).isOk());
  std::vector<sltk::NeighbourRequest<3>> requests;
  if (owned.ownedLocal(2) >= 0)
  {
    requests.push_back({ cloud[2], 2, radius, 1 });
  }
  ASSERT_EQ(comm->allReduce(static_cast<std::int64_t>(requests.size()), sltk::ReduceOp::Sum), 1); // x's owner asks
  std::vector<sltk::NeighbourCandidate<3>> candidates;
  ASSERT_TRUE(sltk::nearestOwnedOnRanks(owned, requests, *comm, candidates).isOk());
  if (!requests.empty())
  {
    ASSERT_EQ(candidates.size(), 2u); // y and z, tied
    EXPECT_EQ(candidates[0].Id, 0);
    EXPECT_EQ(candidates[1].Id, 1);
  }
  sltk::SlabCuts unsorted = cuts;
  if (comm->size() > 1)
  {
    unsorted.Lower[1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(sltk::sendToOwners(mine, 0, unsorted, 0.0, *comm, owned).isOk());
  }
}

namespace
{
/// The points sent to their owners under cuts at `lower` along x (ranks - 1
/// values, non-decreasing; equal cuts and cuts beyond the cloud leave ranks empty).
sltk::OwnedPoints<3> ownersByCuts(const Points& cloud, const sltk::Communicator& comm, std::vector<double> lower)
{
  const sltk::PointCloud<3> mine{ shareOf(cloud, comm) };
  sltk::SlabCuts cuts;
  cuts.Lower = { -std::numeric_limits<double>::infinity() };
  cuts.Lower.insert(cuts.Lower.end(), lower.begin(), lower.end());
  cuts.Lower.push_back(std::numeric_limits<double>::infinity());
  sltk::OwnedPoints<3> owned;
  const sltk::Status s = sltk::sendToOwners(mine, sltk::firstGlobalIndex(mine.size(), comm), cuts, 0.0, comm, owned);
  EXPECT_TRUE(s.isOk()) << s.message();
  return owned;
}

/// The sparsity factors of `owned` (the cloud's points at their owners) against
/// one rank's, bit for bit at every owned point; the halo's points get 1.
void expectOneRankSparsity(
  const Points& cloud, const sltk::OwnedPoints<3>& owned, int k, std::int64_t batch = 32768, bool cutsInTheCloud = true)
{
  auto comm = world();
  TwoThreads threads;
  const sltk::Context& ctx = threads.Ctx;
  const sltk::PointCloud<3> whole{ cloud };
  std::vector<double> one;
  ASSERT_TRUE(sltk::sparsityFactors(sltk::PointLocator<3>(whole), k, ctx, one).isOk());
  std::vector<double> ranks;
  std::int64_t remote = 0;
  const sltk::Status s = sltk::sparsityFactorsOnRanks(owned, k, *comm, ctx, ranks, &remote, batch);
  ASSERT_TRUE(s.isOk()) << s.message();
  ASSERT_EQ(ranks.size(), owned.Ids.size());
  std::int64_t differ = 0;
  for (size_t j = 0; j < owned.Ids.size(); ++j)
  {
    const double expected = owned.Mine[j] ? one[static_cast<size_t>(owned.Ids[j])] : 1.0;
    differ += ranks[j] == expected ? 0 : 1;
  }
  EXPECT_EQ(comm->allReduce(differ, sltk::ReduceOp::Sum), 0) << "k = " << k << " on " << comm->size() << " ranks";
  EXPECT_TRUE(comm->size() > 1 || remote == 0); // one rank holds every neighbour
  EXPECT_TRUE(!cutsInTheCloud || comm->size() == 1 || cloud.size() <= 64 || remote > 0)
    << "no point near a cut was asked again";
}

/// The same from a halo of 0 under balanced cuts.
void expectOneRankSparsity(const Points& cloud, int k, bool allOnRankZero = false)
{
  expectOneRankSparsity(cloud, owners(cloud, *world(), 0.0, allOnRankZero), k);
}
} // namespace

TEST(SparsityFactorsOnRanks, AreTheOneRankFactorsBitForBit)
{
  // Half a box sampled four times more sparsely: factors well above 1 there, 1 elsewhere.
  Points cloud = boxCloud(6000, 31);
  Points uneven;
  for (size_t j = 0; j < cloud.size(); ++j)
  {
    if (cloud[j][0] < 2.0 || j % 4 == 0)
    {
      uneven.push_back(cloud[j]);
    }
  }
  expectOneRankSparsity(uneven, 16);
  expectOneRankSparsity(uneven, 16, true); // every point read by rank 0
  expectOneRankSparsity(uneven, 3);
  // The smoothing in many batches, a different number on each rank: cuts that give rank 0 a
  // fifth of the box, the others the rest; and cuts that leave every rank but the last none.
  const int p = world()->size();
  expectOneRankSparsity(uneven, ownersByCuts(uneven, *world(), std::vector<double>(p - 1, 1.0)), 16, 97);
  expectOneRankSparsity(uneven, ownersByCuts(uneven, *world(), std::vector<double>(p - 1, -1.0)), 16, 97, false);
  // Exact duplicates: ties at every distance, broken by global index as on one rank.
  Points doubled = boxCloud(1500, 5);
  doubled.insert(doubled.end(), doubled.begin(), doubled.end());
  expectOneRankSparsity(doubled, 8);
  // Fewer points than neighbours + 1: every factor 1.
  expectOneRankSparsity(Points(boxCloud(16, 2)), 16);
  // Slabs along y and z (the box's long side moved): the other rows of the cell and index orders.
  expectOneRankSparsity(rotated(uneven, 1), 16);
  expectOneRankSparsity(rotated(uneven, 2), 16);
}

TEST(SparsityFactorsOnRanks, TheMergedStanfordScansGiveTheOneRankFactors)
{
  const Points cloud = stanfordScans();
  if (cloud.empty())
  {
    GTEST_SKIP() << "the Stanford scans (/work/shared) are not available";
  }
  expectOneRankSparsity(cloud, 16);
}

namespace
{
/// The thinning on the ranks against one rank's: the same means under the same
/// indices, every one owned once.
void expectOneRankThinning(const Points& cloud, double cell, bool allOnRankZero = false)
{
  auto comm = world();
  sltk::PointCloud<3> one;
  ASSERT_TRUE(sltk::thinCloud(sltk::PointCloud<3>{ cloud }, cell, one).isOk());
  sltk::OwnedPoints<3> owned = owners(cloud, *comm, 0.0, allOnRankZero);
  std::int64_t total = 0;
  const sltk::Status s = sltk::thinOnRanks(owned, cell, *comm, total);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(total, one.size());
  EXPECT_EQ(comm->allReduce(owned.Owned, sltk::ReduceOp::Sum), one.size());
  std::int64_t differ = 0;
  for (size_t j = 0; j < owned.Ids.size(); ++j) // no ASSERT before the collective below: every rank reaches it
  {
    const bool known = owned.Ids[j] >= 0 && owned.Ids[j] < one.size();
    const bool increasing = j == 0 || owned.Ids[j - 1] < owned.Ids[j]; // in global index order
    differ += known && increasing && owned.Cloud.Points[j] == one.Points[static_cast<size_t>(owned.Ids[j])] ? 0 : 1;
  }
  EXPECT_EQ(comm->allReduce(differ, sltk::ReduceOp::Sum), 0) << "cell " << cell << " on " << comm->size() << " ranks";
}
} // namespace

TEST(ThinOnRanks, GivesTheOneRankMeansUnderTheOneRankIndices)
{
  const Points box = boxCloud(5000, 41);
  expectOneRankThinning(box, 0.05);      // about one point a cell
  expectOneRankThinning(box, 0.3);       // cells straddle every cut
  expectOneRankThinning(box, 0.3, true); // every point read by rank 0
  expectOneRankThinning(box, 1.7);       // cells wider than a slab on 3 or more ranks
  Points doubled = box;                  // duplicates: their cells' sums in global index order
  doubled.insert(doubled.end(), box.begin(), box.begin() + 2500);
  expectOneRankThinning(doubled, 0.1);
  expectOneRankThinning(rotated(box, 1), 0.3); // slabs along y: rows of (z) lines
  expectOneRankThinning(rotated(box, 2), 0.3); // slabs along z, the slowest axis: one row
  auto comm = world();
  sltk::OwnedPoints<3> owned = owners(box, *comm, 0.0, false);
  std::int64_t total = 0;
  EXPECT_FALSE(sltk::thinOnRanks(owned, 0.0, *comm, total).isOk());
  EXPECT_FALSE(sltk::thinOnRanks(owned, 1e-300, *comm, total).isOk()); // too many cells to number
}

TEST(ThinOnRanks, TheMergedStanfordScansThinAsOnOneRank)
{
  const Points cloud = stanfordScans();
  if (cloud.empty())
  {
    GTEST_SKIP() << "the Stanford scans (/work/shared) are not available";
  }
  expectOneRankThinning(cloud, 2.5 * 4.2222732870964941e-4); // --thin 2.5 of the density spacing (k = 8)
}

namespace
{
/// The automatic K_P's probe on the ranks (from a halo of 0, with and without
/// the local sparsity) against one rank's: the same nodes enclosed per rung
/// and the same choice; and its fields, distance and scaled distance, bit for bit.
void expectOneRankProbe(const Points& cloud, double cellSizeFactor, bool allOnRankZero = false)
{
  auto comm = world();
  TwoThreads threads;
  const sltk::Context& ctx = threads.Ctx;
  const sltk::PointCloud<3> whole{ cloud };
  const sltk::PointLocator<3> locator(whole);
  double spacing = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(locator, ctx, spacing).isOk());
  const sltk::Box<3> bounds = sltk::boundingBox(whole);
  std::vector<double> rho;
  ASSERT_TRUE(sltk::sparsityFactors(locator, 16, ctx, rho).isOk());
  const sltk::OwnedPoints<3> owned = owners(cloud, *comm, 0.0, allOnRankZero);
  std::vector<double> heldRho;
  ASSERT_TRUE(sltk::sparsityFactorsOnRanks(owned, 16, *comm, ctx, heldRho).isOk());
  for (const bool local : { false, true })
  {
    sltk::OutsideFactorChoice one, ranks;
    const double dx = cellSizeFactor * spacing;
    ASSERT_TRUE(
      sltk::chooseOutsideFactor(locator, bounds, spacing, dx, local ? rho : std::vector<double>{}, ctx, one).isOk());
    const sltk::Status s = sltk::chooseOutsideFactorOnRanks(
      owned, bounds, spacing, dx, local ? heldRho : std::vector<double>{}, *comm, ctx, ranks);
    ASSERT_TRUE(s.isOk()) << s.message();
    EXPECT_EQ(ranks.Factor, one.Factor) << (local ? "local offset" : "uniform offset");
    EXPECT_EQ(ranks.EnclosedNodes, one.EnclosedNodes);
    EXPECT_EQ(ranks.ProbeNodes, one.ProbeNodes);
    EXPECT_EQ(ranks.FirstRung, one.FirstRung);
  }
  // The fields on a grid around the cloud, node by node.
  sltk::GridSpec<3> g;
  for (int a = 0; a < 3; ++a)
  {
    g.Spacing[a] = 1.5 * spacing;
    g.Origin[a] = bounds.Min[a] - 6.0 * g.Spacing[a];
    g.Dims[a] = static_cast<sltk::Index>(std::ceil(bounds.extent(a) / g.Spacing[a])) + 13;
  }
  sltk::GridField<3, double> d1, dr, u1, ur;
  ASSERT_TRUE(sltk::distanceToCloud(locator, g, ctx, d1).isOk());
  ASSERT_TRUE(sltk::distanceToCloudOnRanks(owned, g, *comm, ctx, dr).isOk());
  const double reach = 8.0 * spacing;
  ASSERT_TRUE(sltk::locallyScaledDistance(d1, locator, rho, reach, ctx, u1).isOk());
  ASSERT_TRUE(sltk::locallyScaledDistanceOnRanks(dr, owned, heldRho, reach, *comm, ctx, ur).isOk());
  std::int64_t differ = 0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = d1.nodeIndex(k);
    differ += d1(i) == dr(i) && u1(i) == ur(i) ? 0 : 1;
  }
  EXPECT_EQ(differ, 0) << "nodes of " << g.nodeCount() << " on " << comm->size() << " ranks";
}
} // namespace

TEST(ChooseOutsideFactorOnRanks, ProbesAsOneRank)
{
  // A sphere with a hole in its sampling and a sparser half: the rungs enclose different counts.
  Points cloud;
  size_t j = 0;
  for (const auto& p : sltk::sphereCloud(3000).Points)
  {
    if (p[0] > 0.8 || (p[2] > 0.0 && j++ % 3 != 0))
    {
      continue;
    }
    cloud.push_back(p);
  }
  expectOneRankProbe(cloud, 2.0);       // (a coarser probe than C_dx 1 gives: the test's time)
  expectOneRankProbe(cloud, 3.0, true); // every point read by rank 0
  expectOneRankProbe(rotated(cloud, 1), 2.0);
}

TEST(ChooseOutsideFactorOnRanks, TheBunnyProbesAsOneRank)
{
  const Points cloud = sharedCloud("bunny/bunny.xyz");
  if (cloud.empty())
  {
    GTEST_SKIP() << "the Stanford bunny (/work/shared) is not available";
  }
  expectOneRankProbe(cloud, 2.08); // the automatic C_dx with no options
}

namespace
{
/// Clumps of points along [0, 4] x [0, 1] x [0, 1] (radius 0.1 around y = z =
/// 0.5), a chain from the clump at x = 0.3 out along y = 0.85 to x = 3, back
/// along y = 0.15 and into the clump at x = 1 (two clumps of the first slab
/// joined only through the others' slabs), two clumps that overlap across the
/// middle, and scattered points: components across the cuts and singletons.
Points clumpsAndChain(unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), v(0.0, 1.0);
  Points cloud;
  for (const double x : { 0.3, 1.0, 1.35, 1.95, 2.05, 2.7, 3.7 })
  {
    for (int j = 0; j < 150; ++j)
    {
      cloud.push_back({ x + 0.1 * u(rng), 0.5 + 0.1 * u(rng), 0.5 + 0.1 * u(rng) });
    }
  }
  const auto segment = [&cloud](std::array<double, 3> from, std::array<double, 3> to)
  {
    const int steps = static_cast<int>(std::ceil(std::hypot(to[0] - from[0], to[1] - from[1]) / 0.02));
    for (int k = 0; k < steps; ++k)
    {
      const double t = static_cast<double>(k) / steps;
      cloud.push_back({ from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1]), 0.5 });
    }
  };
  segment({ 0.3, 0.5, 0.5 }, { 0.3, 0.85, 0.5 }); // out of the clump at 0.3
  segment({ 0.3, 0.85, 0.5 }, { 3.0, 0.85, 0.5 });
  segment({ 3.0, 0.85, 0.5 }, { 3.0, 0.15, 0.5 });
  segment({ 3.0, 0.15, 0.5 }, { 1.0, 0.15, 0.5 });
  segment({ 1.0, 0.15, 0.5 }, { 1.0, 0.5, 0.5 }); // into the clump at 1.0
  for (int j = 0; j < 40; ++j)
  {
    cloud.push_back({ 4.0 * v(rng), v(rng), v(rng) });
  }
  std::shuffle(cloud.begin(), cloud.end(), rng); // the file's order is not the slabs'
  return cloud;
}

/// The index of the point of `cloud` nearest to x.
size_t nearestTo(const Points& cloud, const std::array<double, 3>& x)
{
  size_t best = 0;
  double d2 = std::numeric_limits<double>::infinity();
  for (size_t j = 0; j < cloud.size(); ++j)
  {
    const double e =
      std::pow(cloud[j][0] - x[0], 2) + std::pow(cloud[j][1] - x[1], 2) + std::pow(cloud[j][2] - x[2], 2);
    best = e < d2 ? j : best;
    d2 = std::min(d2, e);
  }
  return best;
}

/// Every point's label on one rank (linkWithinRadii over the whole cloud): the
/// smallest index in its component.
std::vector<std::int64_t> oneRankLabels(const Points& cloud, const std::vector<double>& radius)
{
  const sltk::PointCloud<3> whole{ cloud };
  const sltk::PointLocator<3> locator(whole);
  std::vector<std::int64_t> parent = sltk::singletonForest<std::int64_t>(cloud.size());
  sltk::linkWithinRadii(locator, radius, nullptr, parent);
  std::vector<std::int64_t> least(cloud.size(), std::numeric_limits<std::int64_t>::max()), label(cloud.size());
  for (size_t j = 0; j < cloud.size(); ++j)
  {
    std::int64_t& l = least[static_cast<size_t>(sltk::findRoot(parent, static_cast<std::int64_t>(j)))];
    l = std::min(l, static_cast<std::int64_t>(j));
  }
  for (size_t j = 0; j < cloud.size(); ++j)
  {
    label[j] = least[static_cast<size_t>(sltk::findRoot(parent, static_cast<std::int64_t>(j)))];
  }
  return label;
}

/// The components on the ranks (`owned`, the points of `cloud` on their
/// owners) against one rank's: the count, and every owned point's label.
void expectOneRankComponents(const Points& cloud, const std::vector<double>& radius, const sltk::OwnedPoints<3>& owned)
{
  auto comm = world();
  TwoThreads threads;
  const std::vector<std::int64_t> one = oneRankLabels(cloud, radius);
  const std::int64_t count = static_cast<std::int64_t>(std::set<std::int64_t>(one.begin(), one.end()).size());
  std::vector<double> held(owned.Ids.size());
  for (size_t j = 0; j < held.size(); ++j)
  {
    held[j] = radius[static_cast<size_t>(owned.Ids[j])];
  }
  sltk::LinkedComponents ranks;
  const sltk::Status s = sltk::linkedComponentsOnRanks(owned, held, *comm, threads.Ctx, ranks);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(ranks.Count, count) << "on " << comm->size() << " ranks, halo " << owned.Halo;
  std::int64_t differ = 0;
  for (size_t j = 0; j < owned.Ids.size(); ++j)
  {
    differ += owned.Mine[j] ? (ranks.Label[j] == one[static_cast<size_t>(owned.Ids[j])] ? 0 : 1)
                            : (ranks.Label[j] == -1 ? 0 : 1);
  }
  EXPECT_EQ(comm->allReduce(differ, sltk::ReduceOp::Sum), 0) << "labels on " << comm->size() << " ranks";
}

void expectOneRankComponents(
  const Points& cloud, const std::vector<double>& radius, double halo, bool allOnRankZero = false)
{
  expectOneRankComponents(cloud, radius, owners(cloud, *world(), halo, allOnRankZero));
}

/// Radii from 0.03 to 0.09 by index: links that only the end with the larger radius sees.
std::vector<double> unevenRadii(size_t n)
{
  std::vector<double> r(n);
  for (size_t j = 0; j < n; ++j)
  {
    r[j] = 0.03 * (1.0 + static_cast<double>(j % 7) / 3.0);
  }
  return r;
}
} // namespace

TEST(LinkedComponentsOnRanks, AreTheOneRankComponentsAndLabels)
{
  const Points cloud = clumpsAndChain(7);
  const std::vector<double> r = unevenRadii(cloud.size());
  // The scenario: the clumps at x = 0.3 and 1 are one component, through the chain only.
  const std::vector<std::int64_t> one = oneRankLabels(cloud, r);
  const std::int64_t first = one[nearestTo(cloud, { 0.3, 0.5, 0.5 })];
  ASSERT_EQ(first, one[nearestTo(cloud, { 1.0, 0.5, 0.5 })]);
  ASSERT_EQ(first, one[nearestTo(cloud, { 3.0, 0.5, 0.5 })]);
  ASSERT_NE(first, one[nearestTo(cloud, { 1.35, 0.5, 0.5 })]);
  ASSERT_NE(first, one[nearestTo(cloud, { 2.7, 0.5, 0.5 })]);
  expectOneRankComponents(cloud, r, 0.0);       // the halo widened to the largest radius
  expectOneRankComponents(cloud, r, 0.5);       // wide enough already
  expectOneRankComponents(cloud, r, 0.0, true); // every point read by rank 0
  expectOneRankComponents(rotated(cloud, 1), r, 0.0);
  expectOneRankComponents(rotated(cloud, 2), r, 0.0);
  expectOneRankComponents(cloud, std::vector<double>(cloud.size(), 0.0), 0.0); // no links: every point alone
  expectOneRankComponents(cloud, std::vector<double>(cloud.size(), 5.0), 0.0); // one component
  // Uneven cuts: every point on the last rank, or ranks between equal cuts left empty.
  const int p = world()->size();
  expectOneRankComponents(cloud, r, ownersByCuts(cloud, *world(), std::vector<double>(p - 1, -1.0)));
  expectOneRankComponents(cloud, r, ownersByCuts(cloud, *world(), std::vector<double>(p - 1, 2.0)));
}

TEST(LinkedComponentsOnRanks, RefusesABadRadiusOnEveryRank)
{
  auto comm = world();
  TwoThreads threads;
  const sltk::OwnedPoints<3> owned = owners(clumpsAndChain(3), *comm, 0.0, false);
  std::vector<double> r(owned.Ids.size(), 0.05);
  if (comm->rank() == comm->size() - 1 && !r.empty())
  {
    r.back() = std::numeric_limits<double>::quiet_NaN(); // on one rank only: every rank refuses
  }
  sltk::LinkedComponents c;
  const sltk::Status s = sltk::linkedComponentsOnRanks(owned, r, *comm, threads.Ctx, c);
  EXPECT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("radius"), std::string::npos) << s.message();
}

namespace
{
/// The cloud's components (cloudComponents: radii from the local spacing) on the
/// ranks against one rank's count.
void expectOneRankCloudComponents(
  const Points& cloud, int k, bool allOnRankZero = false, sltk::Index expectedCount = -1)
{
  auto comm = world();
  TwoThreads threads;
  const sltk::PointCloud<3> whole{ cloud };
  const sltk::PointLocator<3> locator(whole);
  double spacing = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(locator, threads.Ctx, spacing).isOk());
  const sltk::Index one = sltk::cloudComponents(locator, spacing, sltk::PieceLinkFactor, k, threads.Ctx);
  if (expectedCount >= 0)
  {
    EXPECT_EQ(one, expectedCount);
  }
  const sltk::OwnedPoints<3> owned = owners(cloud, *comm, 0.0, allOnRankZero);
  std::int64_t ranks = 0;
  const sltk::Status s =
    sltk::cloudComponentsOnRanks(owned, spacing, sltk::PieceLinkFactor, k, *comm, threads.Ctx, ranks);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(ranks, one) << "k = " << k << " on " << comm->size() << " ranks";
}
} // namespace

TEST(CloudComponentsOnRanks, AreTheOneRankCount)
{
  const Points cloud = clumpsAndChain(11);
  expectOneRankCloudComponents(cloud, 16);
  expectOneRankCloudComponents(cloud, 16, true);
  expectOneRankCloudComponents(cloud, 0); // h_P alone
  expectOneRankCloudComponents(rotated(cloud, 2), 4);
  expectOneRankCloudComponents(Points(cloud.begin(), cloud.begin() + 10), 16); // at most k points: h_P alone
}

TEST(CloudComponentsOnRanks, TheBunnyIsOneComponentOnAnyRanks)
{
  const Points cloud = sharedCloud("bunny/bunny.xyz");
  if (cloud.empty())
  {
    GTEST_SKIP() << "the Stanford bunny (/work/shared) is not available";
  }
  expectOneRankCloudComponents(cloud, 16, false, 1);
}

TEST(GroupBoxesOnRanks, AreTheOneRankGroupsBoxes)
{
  auto comm = world();
  TwoThreads threads;
  Points cloud = clumpsAndChain(5);
  const double link = 0.12; // the clumps at 1.95 and 2.05 and the chain's ends join
  // One rank's groups (pointGroups, the points closer than the link) and their boxes.
  std::vector<sltk::OutsidePoint> all(cloud.size());
  for (size_t j = 0; j < all.size(); ++j)
  {
    all[j].Point = static_cast<sltk::Index>(j);
  }
  const std::vector<sltk::Index> group = sltk::pointGroups(sltk::PointCloud<3>{ cloud }, all, link);
  std::map<sltk::Index, sltk::Box<3>> oneBoxes;
  for (size_t j = 0; j < cloud.size(); ++j)
  {
    auto [it, created] = oneBoxes.try_emplace(group[j], sltk::Box<3>{ cloud[j], cloud[j] });
    for (int a = 0; a < 3 && !created; ++a)
    {
      it->second.Min[a] = std::min(it->second.Min[a], cloud[j][a]);
      it->second.Max[a] = std::max(it->second.Max[a], cloud[j][a]);
    }
  }
  std::set<std::array<double, 6>> expected;
  for (const auto& entry : oneBoxes)
  {
    const auto& b = entry.second;
    expected.insert({ b.Min[0], b.Min[1], b.Min[2], b.Max[0], b.Max[1], b.Max[2] });
  }
  const sltk::OwnedPoints<3> owned = owners(cloud, *comm, 0.0, false);
  std::vector<sltk::Box<3>> boxes;
  ASSERT_TRUE(sltk::groupBoxesOnRanks(owned, link, 64, *comm, threads.Ctx, boxes).isOk());
  std::set<std::array<double, 6>> got;
  for (const auto& b : boxes)
  {
    got.insert({ b.Min[0], b.Min[1], b.Min[2], b.Max[0], b.Max[1], b.Max[2] });
  }
  EXPECT_GE(expected.size(), 2u);
  EXPECT_EQ(got, expected) << expected.size() << " groups on one rank, " << got.size() << " on " << comm->size();
  // As many groups as asked for: the boxes; more, or one group: none.
  ASSERT_TRUE(
    sltk::groupBoxesOnRanks(owned, link, static_cast<std::int64_t>(expected.size()), *comm, threads.Ctx, boxes).isOk());
  EXPECT_EQ(boxes.size(), expected.size());
  ASSERT_TRUE(
    sltk::groupBoxesOnRanks(owned, link, static_cast<std::int64_t>(expected.size()) - 1, *comm, threads.Ctx, boxes)
      .isOk());
  EXPECT_TRUE(boxes.empty());
  ASSERT_TRUE(sltk::groupBoxesOnRanks(owned, 5.0, 64, *comm, threads.Ctx, boxes).isOk());
  EXPECT_TRUE(boxes.empty());
}

namespace
{
/// The points in this rank's interval [low, high] along `axis` (pointsInIntervals)
/// against the whole cloud's, filtered as a run selects its window's points
/// (recon/RunPoints.h): the same points in the same order, with their values.
void expectWholeCloudsInterval(
  const Points& cloud, int axis, double low, double high, bool allOnRankZero = false, bool valued = true)
{
  auto comm = world();
  const sltk::OwnedPoints<3> owned = owners(cloud, *comm, 0.0, allOnRankZero);
  std::vector<double> values;
  for (size_t j = 0; valued && j < owned.Ids.size(); ++j)
  {
    values.push_back(0.5 + static_cast<double>(owned.Ids[j]));
  }
  sltk::PointsInInterval<3> got;
  const sltk::Status s = sltk::pointsInIntervals(owned, values, axis, low, high, *comm, got);
  ASSERT_TRUE(s.isOk()) << s.message();
  std::vector<std::int64_t> expected;
  for (size_t k = 0; k < cloud.size(); ++k)
  {
    if (cloud[k][static_cast<size_t>(axis)] >= low && cloud[k][static_cast<size_t>(axis)] <= high)
    {
      expected.push_back(static_cast<std::int64_t>(k));
    }
  }
  std::int64_t differ = got.Ids == expected ? 0 : 1;
  for (size_t j = 0; differ == 0 && j < expected.size(); ++j)
  {
    differ += got.Cloud.Points[j] == cloud[static_cast<size_t>(expected[j])] ? 0 : 1;
    differ += !valued || got.Values[j] == 0.5 + static_cast<double>(expected[j]) ? 0 : 1;
  }
  differ += valued || got.Values.empty() ? 0 : 1;
  EXPECT_EQ(differ, 0) << "rank " << comm->rank() << " of " << comm->size() << ": " << got.Ids.size() << " points in ["
                       << low << ", " << high << "] along " << axis << ", one rank " << expected.size();
}
} // namespace

TEST(PointsInIntervals, AreTheWholeCloudsPointsInItsOrder)
{
  auto comm = world();
  const double r = comm->rank(), p = comm->size();
  Points cloud = boxCloud(5000, 17);
  cloud.push_back(cloud[7]); // an exact duplicate, taken twice in the index order
  // Windows along z overlapping their neighbours, growing with the rank (a run's slabs),
  // across the owners' slabs along x.
  expectWholeCloudsInterval(cloud, 2, r / p - 0.1, (r + 1) / p + 0.1);
  expectWholeCloudsInterval(cloud, 0, 4.0 * r / p - 0.3, 4.0 * (r + 1) / p + 0.3, true); // along the owners' axis
  // Not ordered by rank: rank r takes rank p - 1 - r's window.
  expectWholeCloudsInterval(cloud, 2, (p - 1 - r) / p - 0.05, (p - r) / p + 0.05);
  // Bounds exactly at points' coordinates (both ends are in), and an empty interval on rank 0.
  expectWholeCloudsInterval(cloud, 1, cloud[3][1], cloud[9][1] > cloud[3][1] ? cloud[9][1] : cloud[3][1]);
  const double inf = std::numeric_limits<double>::infinity();
  expectWholeCloudsInterval(cloud, 1, r == 0 ? 2.0 : -inf, r == 0 ? 1.0 : inf, false, false);
  expectWholeCloudsInterval(cloud, 2, r / p + 0.5, r / p + 0.4); // every interval empty, still ordered
}

TEST(PointsInIntervals, RefusesABadAxisANaNBoundOrMissingValuesOnEveryRank)
{
  auto comm = world();
  const sltk::OwnedPoints<3> owned = owners(boxCloud(400, 3), *comm, 0.0, false);
  sltk::PointsInInterval<3> got;
  const bool last = comm->rank() == comm->size() - 1;
  EXPECT_FALSE(sltk::pointsInIntervals(owned, {}, last ? 3 : 0, 0.0, 1.0, *comm, got).isOk());
  EXPECT_FALSE(
    sltk::pointsInIntervals(owned, {}, 0, last ? std::numeric_limits<double>::quiet_NaN() : 0.0, 1.0, *comm, got)
      .isOk());
  const std::vector<double> values(last ? 0 : owned.Ids.size(), 1.0); // one rank gives none
  const sltk::Status s = sltk::pointsInIntervals(owned, values, 0, 0.0, 1.0, *comm, got);
  const std::int64_t lastHeld = comm->allReduce(last ? owned.held() : std::int64_t(0), sltk::ReduceOp::Sum);
  EXPECT_EQ(s.isOk(), comm->size() == 1 || lastHeld == 0) << s.message(); // an empty rank may give none
  // Intervals along different axes on different ranks.
  const sltk::Status axes = sltk::pointsInIntervals(owned, {}, last ? 1 : 0, 0.0, 1.0, *comm, got);
  EXPECT_EQ(axes.isOk(), comm->size() == 1) << axes.message();
}

namespace
{
/// The missed places from the ranks' own missed points and pointsNearOnRanks (the points
/// on their owners, `owned`) against one rank's from all of them and pointsNear.
void expectOneRankMissedPlaces(const Points& cloud, const sltk::OwnedPoints<3>& owned, double link)
{
  auto comm = world();
  const sltk::PointCloud<3> whole{ cloud };
  const sltk::PointLocator<3> locator(whole);
  // "Missed": the middle of the two clumps across the middle cut, the chain's lower leg and
  // the scattered points there; their neighbours just outside count as nearby, not missed.
  const auto missed = [](const std::array<double, 3>& x) { return (x[0] > 1.9 && x[0] < 2.1) || x[1] < 0.2; };
  std::vector<sltk::PlacedPoint<3>> all, local;
  for (size_t k = 0; k < cloud.size(); ++k)
  {
    if (missed(cloud[k]))
    {
      all.push_back({ static_cast<sltk::Index>(k), 1.0, cloud[k] });
    }
  }
  for (size_t j = 0; j < owned.Ids.size(); ++j)
  {
    if (owned.Mine[j] && missed(owned.Cloud.Points[j]))
    {
      local.push_back({ owned.Ids[j], 1.0, owned.Cloud.Points[j] });
    }
  }
  const auto one = sltk::gatherMissedPlaces<3>(all, link, sltk::serialCommunicator(),
    [&](const std::vector<sltk::PlacedPoint<3>>& a, const std::vector<size_t>& members)
    { return sltk::pointsNear(locator, a, members, link); });
  const auto ranks = sltk::gatherMissedPlaces<3>(local, link, *comm,
    [&](const std::vector<sltk::PlacedPoint<3>>& a, const std::vector<size_t>& members)
    { return sltk::pointsNearOnRanks(owned, a, members, link, *comm); });
  ASSERT_EQ(one.size(), sltk::MissedPlacesNamed);
  ASSERT_EQ(ranks.size(), one.size());
  for (size_t g = 0; g < one.size(); ++g)
  {
    EXPECT_EQ(ranks[g].Points, one[g].Points) << "place " << g << ", link " << link;
    EXPECT_EQ(ranks[g].Nearby, one[g].Nearby) << "place " << g << ", link " << link;
    EXPECT_EQ(ranks[g].Centre, one[g].Centre) << "place " << g;
    EXPECT_EQ(ranks[g].Lower, one[g].Lower) << "place " << g;
    EXPECT_EQ(ranks[g].Upper, one[g].Upper) << "place " << g;
  }
  if (link > 0.0)
  {
    EXPECT_GT(one[0].Nearby, one[0].Points); // the clumps' points just outside the middle are near, not missed
  }
}
} // namespace

TEST(MissedPlacesOnRanks, AreTheOneRankPlacesWithTheirNearbyCounts)
{
  Points cloud = clumpsAndChain(13);
  cloud.push_back(cloud[nearestTo(cloud, { 2.0, 0.5, 0.5 })]); // an exact duplicate of a missed point
  const int p = world()->size();
  expectOneRankMissedPlaces(cloud, owners(cloud, *world(), 0.0, false), 0.05);
  expectOneRankMissedPlaces(cloud, owners(cloud, *world(), 0.0, false), 0.0); // no link: the members alone
  // Ranks left empty by equal cuts.
  expectOneRankMissedPlaces(cloud, ownersByCuts(cloud, *world(), std::vector<double>(p - 1, 2.0)), 0.05);
}

namespace
{
/// validateCloudShares on the ranks' shares of `cloud` against validateCloud of the whole: the same verdict and
/// message.
void expectOneRankValidation(const Points& cloud, bool allOnRankZero = false, bool noneOnRankZero = false)
{
  auto comm = world();
  const sltk::Status one = sltk::validateCloud(sltk::PointCloud<3>{ cloud });
  sltk::PointCloud<3> mine{ shareOf(cloud, *comm, allOnRankZero) };
  if (noneOnRankZero && comm->size() > 1) // rank 0 reads nothing, the others the file in order
  {
    const sltk::FileShare f = comm->rank() == 0
      ? sltk::FileShare{ 0, 0 }
      : sltk::shareOf(0, static_cast<std::int64_t>(cloud.size()), comm->rank() - 1, comm->size() - 1);
    mine.Points.assign(cloud.begin() + f.Begin, cloud.begin() + f.End);
  }
  const sltk::Status ranks = sltk::validateCloudShares(mine, sltk::firstGlobalIndex(mine.size(), *comm), *comm);
  EXPECT_EQ(ranks.isOk(), one.isOk()) << one.message();
  EXPECT_EQ(ranks.message(), one.message()) << "on " << comm->size() << " ranks";
}
} // namespace

TEST(ValidateCloudShares, GiveTheOneRankVerdictAndMessage)
{
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const Points good = boxCloud(300, 41);
  expectOneRankValidation(good);
  expectOneRankValidation(good, true);
  expectOneRankValidation(good, false, true);                      // point 0 on rank 1
  expectOneRankValidation({});                                     // empty
  expectOneRankValidation(Points(good.begin(), good.begin() + 3)); // fewer than D + 1
  // The first non-finite point, wherever it is read; a later one (on the same rank, or on a later one) is not named.
  for (const auto& [at, later] : std::vector<std::pair<size_t, size_t>>{ { 0, 7 }, { 100, 250 }, { 299, 299 } })
  {
    Points bad = good;
    bad[later][2] = inf;
    bad[at][1] = nan;
    expectOneRankValidation(bad);
    expectOneRankValidation(bad, false, true);
  }
  Points same(40, { 1.0, 2.0, 3.0 }); // every point coincides
  expectOneRankValidation(same);
  Points huge = good;
  huge[200] = { 1e200, 0.0, 0.0 };
  expectOneRankValidation(huge);
  Points survey = good; // an extent too small against the offset
  for (auto& p : survey)
  {
    p = { 1e9 + 1e-3 * p[0], 1e9 + 1e-3 * p[1], 1e9 + 1e-3 * p[2] };
  }
  expectOneRankValidation(survey);
  Points line, plane, tied;
  for (int k = 0; k < 200; ++k)
  {
    line.push_back({ 0.5 * k, 1.0 + 0.25 * k, -0.1 * k });
    plane.push_back({ std::sin(0.3 * k), std::cos(0.7 * k), 0.25 });
    tied.push_back({ static_cast<double>(k % 2), static_cast<double>((k / 2) % 2), static_cast<double>(k % 3 == 0) });
  }
  expectOneRankValidation(line);
  expectOneRankValidation(plane);
  expectOneRankValidation(plane, false, true);
  plane[123][2] = 0.26; // one point off the plane
  expectOneRankValidation(plane);
  expectOneRankValidation(tied); // many points at the same largest distances: the lowest index wins
}

TEST(ValidateCloudShares, RefusesSharesNotInRankOrderOnEveryRank)
{
  auto comm = world();
  const Points cloud = boxCloud(100, 9);
  const sltk::PointCloud<3> mine{ shareOf(cloud, *comm) };
  const std::int64_t first = sltk::firstGlobalIndex(mine.size(), *comm);
  EXPECT_TRUE(sltk::validateCloudShares(mine, first, *comm).isOk());
  const sltk::Status s = sltk::validateCloudShares(mine, first + (comm->rank() == comm->size() - 1 ? 1 : 0), *comm);
  EXPECT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("consecutive"), std::string::npos) << s.message();
}

namespace
{
/// A 2D cloud: rings of points along x (each a component; two of them overlap across the
/// middle), and a chain along y = 0.9 over every slab (a component of its own).
std::vector<std::array<double, 2>> rings2D()
{
  std::vector<std::array<double, 2>> cloud;
  for (const double x : { 0.3, 1.0, 1.55, 1.95, 2.7, 3.7 })
  {
    for (int k = 0; k < 120; ++k)
    {
      const double t = 2.0 * M_PI * k / 120.0;
      cloud.push_back({ x + 0.25 * std::cos(t), 0.5 + 0.25 * std::sin(t) });
    }
  }
  for (double x = 0.3; x <= 3.7; x += 0.01)
  {
    cloud.push_back({ x, 0.75 + 0.15 * (x > 0.31 && x < 3.69) });
  }
  return cloud;
}
} // namespace

TEST(LinkedComponentsOnRanks, AreTheOneRankComponentsIn2D)
{
  auto comm = world();
  TwoThreads threads;
  const std::vector<std::array<double, 2>> cloud = rings2D();
  const std::vector<double> radius(cloud.size(), 0.02);
  // One rank's components.
  const sltk::PointCloud<2> whole{ cloud };
  const sltk::PointLocator<2> locator(whole);
  std::vector<std::int64_t> parent = sltk::singletonForest<std::int64_t>(cloud.size());
  sltk::linkWithinRadii(locator, radius, nullptr, parent);
  std::set<std::int64_t> roots;
  for (size_t j = 0; j < cloud.size(); ++j)
  {
    roots.insert(sltk::findRoot(parent, static_cast<std::int64_t>(j)));
  }
  // On the ranks, from their shares, with a halo of 0 (widened).
  const sltk::FileShare f = sltk::shareOf(0, static_cast<std::int64_t>(cloud.size()), comm->rank(), comm->size());
  const sltk::PointCloud<2> mine{ std::vector<std::array<double, 2>>(cloud.begin() + f.Begin, cloud.begin() + f.End) };
  sltk::OwnedPoints<2> owned;
  ASSERT_TRUE(sltk::sendToOwners(mine, f.Begin, sltk::balancedCuts(mine, *comm), 0.0, *comm, owned).isOk());
  sltk::LinkedComponents ranks;
  const sltk::Status s =
    sltk::linkedComponentsOnRanks(owned, std::vector<double>(owned.Ids.size(), 0.02), *comm, threads.Ctx, ranks);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_GE(roots.size(), 3u);
  EXPECT_EQ(ranks.Count, static_cast<std::int64_t>(roots.size())) << "on " << comm->size() << " ranks";
  // The groups' boxes and the validation in 2D.
  std::vector<sltk::Box<2>> boxes;
  ASSERT_TRUE(sltk::groupBoxesOnRanks(owned, 0.02, 16, *comm, threads.Ctx, boxes).isOk());
  EXPECT_EQ(boxes.size(), roots.size());
  EXPECT_EQ(sltk::validateCloudShares(mine, f.Begin, *comm).message(), sltk::validateCloud(whole).message());
  std::vector<std::array<double, 2>> line(50);
  for (size_t j = 0; j < line.size(); ++j)
  {
    line[j] = { 0.1 * static_cast<double>(j), 0.3 * static_cast<double>(j) };
  }
  const sltk::FileShare g = sltk::shareOf(0, 50, comm->rank(), comm->size());
  const sltk::PointCloud<2> lineShare{ std::vector<std::array<double, 2>>(
    line.begin() + g.Begin, line.begin() + g.End) };
  const sltk::Status refused = sltk::validateCloudShares(lineShare, g.Begin, *comm);
  EXPECT_FALSE(refused.isOk());
  EXPECT_EQ(refused.message(), sltk::validateCloud(sltk::PointCloud<2>{ line }).message());
}

namespace
{
/// NearestOverRanks' batches against one rank's locator over the whole cloud:
/// the same distances bit for bit and the same nearest points (their global
/// indices, the lowest at a tie). `queries` makes a batch (the same on every rank).
template <class Queries>
void expectWholeCloudNearest(const Points& cloud, double halo, double radius, Queries&& queries)
{
  auto comm = world();
  const TwoThreads threads;
  const sltk::Context& ctx = threads.Ctx;
  const sltk::PointCloud<3> whole{ cloud };
  const sltk::PointLocator<3> one(whole);
  const sltk::OwnedPoints<3> owned = owners(cloud, *comm, halo, false);
  const sltk::NearestOverRanks<3> nearest(owned);
  std::int64_t differ = 0, asked = 0;
  for (int batch = 0; batch < 3; ++batch)
  {
    const Points x = queries(batch);
    std::vector<double> distance;
    std::vector<std::int64_t> ids;
    nearest.find(x, radius, *comm, ctx, distance, ids);
    for (size_t q = 0; q < x.size(); ++q)
    {
      const auto hit = one.nearest(x[q]);
      differ += distance[q] == hit.Distance && ids[q] == hit.Index ? 0 : 1;
      ++asked;
    }
  }
  EXPECT_EQ(differ, 0) << "of " << asked << " queries, halo " << halo << ", radius " << radius << " on " << comm->size()
                       << " ranks";
}
} // namespace

TEST(NearestOverRanks, BatchesFindTheWholeCloudsNearestPoint)
{
  const Points box = boxCloud(4000, 41);
  const auto random = [](int batch)
  {
    std::mt19937_64 rng(7 + static_cast<unsigned>(batch));
    std::uniform_real_distribution<double> coordinate(-0.5, 4.5);
    Points x(200);
    for (auto& q : x)
    {
      q = { coordinate(rng), coordinate(rng), coordinate(rng) };
    }
    return x;
  };
  expectWholeCloudNearest(box, 0.0, 0.2, random);  // every held point owned
  expectWholeCloudNearest(box, 0.3, 0.2, random);  // a halo: its points found on two ranks
  expectWholeCloudNearest(box, 0.0, 1e-9, random); // most queries asked again without a bound
  // Ties: a lattice in shuffled order queried at half-integer places, equally far from
  // several points that may lie on different ranks (the lowest global index wins).
  Points lattice;
  for (int i = 0; i < 16; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int k = 0; k < 4; ++k)
      {
        lattice.push_back({ 0.25 * i, 0.25 * j, 0.25 * k });
      }
    }
  }
  std::shuffle(lattice.begin(), lattice.end(), std::mt19937_64(3));
  const auto halves = [](int batch)
  {
    Points x;
    for (int i = 0; i < 32; ++i)
    {
      x.push_back({ 0.125 * i, 0.125 * (1 + batch), 0.125 * (3 - batch) });
    }
    return x;
  };
  for (const double halo : { 0.0, 0.15, 0.6 })
  {
    expectWholeCloudNearest(lattice, halo, 0.3, halves);
  }
}
