// SPDX-License-Identifier: GPL-2.0-or-later
// The forest over a cloud (sltk/p4est/CloudForest.h), serially and under
// `mpiexec -n 2` (ctest), 4 ranks by hand: the forest and its distances are
// those of a serial build on every rank (rank invariance), whatever the split
// of the points (a rank may hold none); distances against brute force;
// refinement in the band, 2:1 balance, a tiling of the brick; one failing
// rank fails every rank with its error.
#include "MpiWorld.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/p4est/CloudForest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using sltk::p4est::CloudForest;
using sltk::p4est::CloudForestOptions;
using sltk::p4est::ForestLeaf;

namespace
{
/// An ellipsoid (semi-axes 2, 1, 1) sampled by n Fibonacci points, off the origin:
/// its padded box is not a cube (a brick of two trees).
sltk::PointCloud<3> ellipsoidCloud(int n)
{
  sltk::PointCloud<3> cloud = sltk::sphereCloud(n, 1.0, { 0.3, -0.2, 0.1 });
  for (auto& p : cloud.Points)
  {
    p[0] = 0.3 + 2.0 * (p[0] - 0.3);
  }
  return cloud;
}

enum class Split
{
  RoundRobin,
  AllOnFirst,
  AllOnLast
};

/// This rank's share of `cloud`.
sltk::PointCloud<3> share(const sltk::PointCloud<3>& cloud, const sltk::Communicator& comm, Split split)
{
  sltk::PointCloud<3> mine;
  for (size_t k = 0; k < cloud.Points.size(); ++k)
  {
    const bool keep = split == Split::RoundRobin ? static_cast<int>(k % comm.size()) == comm.rank()
      : split == Split::AllOnFirst               ? comm.rank() == 0
                                                 : comm.rank() == comm.size() - 1;
    if (keep)
    {
      mine.Points.push_back(cloud.Points[k]);
    }
  }
  return mine;
}

CloudForestOptions smallOptions()
{
  CloudForestOptions o;
  o.MinimumLevel = 1;
  o.MaximumLevel = 4;
  return o;
}

std::unique_ptr<CloudForest> build(
  const sltk::Communicator& comm, const sltk::PointCloud<3>& points, const CloudForestOptions& options = smallOptions())
{
  std::unique_ptr<CloudForest> forest;
  const sltk::Status s = CloudForest::build(comm, points, options, sltk::Context{}, forest);
  EXPECT_TRUE(s.isOk()) << s.toString();
  return forest;
}

/// The serial forest of the whole cloud, built on this rank alone.
std::unique_ptr<CloudForest> serialForest(const sltk::PointCloud<3>& cloud)
{
  return build(sltk::serialCommunicator(), cloud);
}

void expectSameLeaves(const std::vector<ForestLeaf>& a, const std::vector<ForestLeaf>& b)
{
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i)
  {
    ASSERT_EQ(a[i].GlobalIndex, static_cast<std::int64_t>(i));
    ASSERT_EQ(b[i].GlobalIndex, static_cast<std::int64_t>(i));
    ASSERT_EQ(a[i].Tree, b[i].Tree) << "leaf " << i;
    ASSERT_EQ(a[i].Level, b[i].Level) << "leaf " << i;
    ASSERT_EQ(a[i].Coords, b[i].Coords) << "leaf " << i;
    ASSERT_EQ(a[i].Distance, b[i].Distance) << "leaf " << i << ": bit-identical distances";
  }
}

double bruteDistance(const std::vector<std::array<double, 3>>& points, const std::array<double, 3>& x)
{
  double best = std::numeric_limits<double>::infinity();
  for (const auto& p : points)
  {
    best = std::min(best, std::hypot(p[0] - x[0], p[1] - x[1], p[2] - x[2]));
  }
  return best;
}

/// Global integer lower corner of a leaf (tree position * root length + coordinates).
std::array<std::int64_t, 3> corner(const CloudForest& forest, const ForestLeaf& leaf)
{
  const auto t = forest.treePosition(leaf.Tree);
  std::array<std::int64_t, 3> c{};
  for (int a = 0; a < 3; ++a)
  {
    c[a] = std::int64_t(t[a]) * sltk::p4est::ForestRootLength + leaf.Coords[a];
  }
  return c;
}

std::int64_t length(int level)
{
  return std::int64_t(sltk::p4est::ForestRootLength) >> level;
}
} // namespace

TEST(CloudForest, BrickOfCubicTreesOverABox)
{
  sltk::Box<3> box;
  box.Min = { 0.0, 0.0, 0.0 };
  box.Max = { 4.0, 1.0, 0.5 };
  const auto brick = sltk::p4est::brickOver(box, 0.0);
  EXPECT_DOUBLE_EQ(brick.TreeEdge, 0.5);
  EXPECT_EQ(brick.Trees, (std::array<int, 3>{ 8, 2, 1 }));
  EXPECT_DOUBLE_EQ(brick.Origin[0], 0.0);
  const auto padded = sltk::p4est::brickOver(box, 0.25); // 1 on every side: 6 x 3 x 2.5
  EXPECT_DOUBLE_EQ(padded.TreeEdge, 3.0);                // 2 x 1 x 1 trees: 54, the least volume
  EXPECT_EQ(padded.Trees, (std::array<int, 3>{ 2, 1, 1 }));
  EXPECT_DOUBLE_EQ(padded.uniformCells(2), 2 * 64.0);
  EXPECT_DOUBLE_EQ(padded.Origin[0], -1.0);
  box.Max = { 1.0, 0.99, 0.8 }; // nearly a cube: one tree
  EXPECT_EQ(sltk::p4est::brickOver(box, 0.1).treeCount(), 1);
  box.Max = { 100.0, 1.0, 1.0 }; // very long: at most 16 trees along an axis
  const auto flat = sltk::p4est::brickOver(box, 0.0);
  EXPECT_EQ(flat.Trees, (std::array<int, 3>{ 16, 1, 1 }));
  EXPECT_DOUBLE_EQ(flat.TreeEdge, 100.0 / 16);
}

TEST(CloudForest, SameForestAndDistancesOnAnyNumberOfRanks)
{
  auto comm = world();
  const auto cloud = ellipsoidCloud(2000);
  const auto serial = serialForest(cloud);
  ASSERT_TRUE(serial);
  EXPECT_EQ(serial->brick().treeCount(), 2);
  for (Split split : { Split::RoundRobin, Split::AllOnFirst, Split::AllOnLast })
  {
    const auto forest = build(*comm, share(cloud, *comm, split));
    ASSERT_TRUE(forest);
    EXPECT_EQ(forest->stats().GlobalLeaves, serial->stats().GlobalLeaves);
    EXPECT_EQ(forest->stats().CloudPoints, 2000);
    EXPECT_EQ(forest->cloudSpacing(), serial->cloudSpacing()) << "h_P of the canonical order";
    expectSameLeaves(forest->gather(), serial->leaves());
    if (comm->size() > 1)
    {
      EXPECT_LT(forest->stats().LocalLeaves, forest->stats().GlobalLeaves) << "the forest is partitioned";
      EXPECT_GT(forest->stats().GhostLeaves, 0);
    }
  }
}

TEST(CloudForest, DistancesAreExactAtLeavesAndGhosts)
{
  auto comm = world();
  const auto cloud = ellipsoidCloud(2000);
  const auto forest = build(*comm, share(cloud, *comm, Split::RoundRobin));
  ASSERT_TRUE(forest);
  sltk::PointCloud<3> unit = cloud;
  forest->unitBox().toUnit(unit);
  for (const auto* set : { &forest->leaves(), &forest->ghosts() })
  {
    for (const ForestLeaf& leaf : *set)
    {
      const double exact = bruteDistance(unit.Points, forest->centre(leaf));
      ASSERT_NEAR(leaf.Distance, exact, 1e-14) << "leaf " << leaf.GlobalIndex;
    }
  }
  for (const ForestLeaf& ghost : forest->ghosts())
  {
    EXPECT_NE(ghost.Owner, comm->rank());
  }
}

TEST(CloudForest, RefinedInTheBandBalancedAndTiling)
{
  const auto cloud = ellipsoidCloud(2000);
  const auto forest = serialForest(cloud);
  ASSERT_TRUE(forest);
  const int maxLevel = forest->options().MaximumLevel;
  const std::vector<ForestLeaf>& leaves = forest->leaves();
  // The leaves tile the brick: their volumes add up to the trees'.
  std::int64_t volume = 0;
  for (const ForestLeaf& leaf : leaves)
  {
    volume += std::int64_t(1) << (3 * (maxLevel - leaf.Level));
    if (forest->inBand(forest->centre(leaf), forest->edge(leaf)))
    {
      EXPECT_EQ(leaf.Level, maxLevel) << "a leaf in the band is at the finest level";
    }
  }
  EXPECT_EQ(volume, forest->brick().treeCount() * (std::int64_t(1) << (3 * maxLevel)));
  EXPECT_LT(static_cast<double>(leaves.size()), forest->stats().UniformCells);
  EXPECT_GT(forest->stats().LeavesAtMaximumLevel, 0);
  // Every point lies in a finest leaf.
  sltk::PointCloud<3> unit = cloud;
  forest->unitBox().toUnit(unit);
  for (size_t k = 0; k < unit.Points.size(); k += 7)
  {
    int level = -1;
    for (const ForestLeaf& leaf : leaves)
    {
      const auto c = forest->centre(leaf);
      const double h = 0.5 * forest->edge(leaf);
      bool inside = true;
      for (int a = 0; a < 3; ++a)
      {
        inside = inside && std::abs(unit.Points[k][a] - c[a]) <= h;
      }
      level = inside ? std::max(level, leaf.Level) : level;
    }
    EXPECT_EQ(level, maxLevel) << "point " << k;
  }
  // 2:1 balance over faces, edges and corners: touching leaves differ by at most one level.
  std::vector<std::array<std::int64_t, 3>> corners;
  for (const ForestLeaf& leaf : leaves)
  {
    corners.push_back(corner(*forest, leaf));
  }
  std::int64_t touching = 0;
  for (size_t i = 0; i < leaves.size(); ++i)
  {
    for (size_t j = i + 1; j < leaves.size(); ++j)
    {
      if (std::abs(leaves[i].Level - leaves[j].Level) <= 1)
      {
        continue;
      }
      bool touch = true;
      for (int a = 0; a < 3 && touch; ++a)
      {
        touch = corners[i][a] <= corners[j][a] + length(leaves[j].Level) &&
          corners[j][a] <= corners[i][a] + length(leaves[i].Level);
      }
      touching += touch ? 1 : 0;
    }
  }
  EXPECT_EQ(touching, 0) << "pairs of touching leaves more than one level apart";
}

TEST(CloudForest, OneFailingRankFailsEveryRankWithItsError)
{
  auto comm = world();
  const int last = comm->size() - 1;
  const auto cloud = ellipsoidCloud(200);
  CloudForestOptions options = smallOptions();
  if (comm->rank() == last)
  {
    options.MaximumLevel = 40;
  }
  std::unique_ptr<CloudForest> forest;
  sltk::Status s = CloudForest::build(*comm, share(cloud, *comm, Split::RoundRobin), options, {}, forest);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_NE(s.message().find("MaximumLevel = 40"), std::string::npos) << s.message();
  EXPECT_EQ(forest, nullptr);

  // A NaN in one rank's points: the gathered cloud is refused on every rank.
  sltk::PointCloud<3> mine = share(cloud, *comm, Split::RoundRobin);
  if (comm->rank() == last)
  {
    mine.Points.push_back({ std::nan(""), 0.0, 0.0 });
  }
  s = CloudForest::build(*comm, mine, smallOptions(), {}, forest);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_NE(s.message().find("non-finite"), std::string::npos) << s.message();

  // No points anywhere.
  s = CloudForest::build(*comm, sltk::PointCloud<3>{}, smallOptions(), {}, forest);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument) << s.message();

  // A level that does not fit the budget is refused before it is built, naming one that fits.
  options = smallOptions();
  options.MaximumLevel = 9;
  options.MemoryBudget = 4u << 20;
  s = CloudForest::build(*comm, share(cloud, *comm, Split::RoundRobin), options, {}, forest);
  EXPECT_EQ(s.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_NE(s.message().find("use MaximumLevel <="), std::string::npos) << s.message();
  comm->barrier(); // every rank is here: no one hangs in a collective
}
