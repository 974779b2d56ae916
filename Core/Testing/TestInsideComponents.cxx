// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/InsideComponents.h"

#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/exec/ThreadPool.h"

#include "sltk/octree/TiledReconstruction.h"

#include "sltk/recon/PointClusters.h"
#include "sltk/recon/Reconstruction.h"
#include "sltk/recon/StoppingRule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
template <int D>
sltk::GridSpec<D> unitGrid(const std::array<sltk::Index, D>& dims)
{
  sltk::GridSpec<D> g;
  for (int a = 0; a < D; ++a)
  {
    g.Dims[a] = dims[a];
    g.Origin[a] = 0.0;
    g.Spacing[a] = 1.0;
  }
  return g;
}

/// The components of {phi < 0} by a flood fill over face neighbours: the reference.
template <int D>
std::int64_t floodFillComponents(const sltk::GridField<D>& phi)
{
  const sltk::GridSpec<D>& g = phi.spec();
  std::vector<char> seen(static_cast<size_t>(g.nodeCount()), 0);
  std::int64_t count = 0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    if (seen[static_cast<size_t>(k)] || !(phi(phi.nodeIndex(k)) < 0.0))
    {
      continue;
    }
    ++count;
    std::vector<sltk::Index> stack{ k };
    seen[static_cast<size_t>(k)] = 1;
    while (!stack.empty())
    {
      const std::array<sltk::Index, D> i = phi.nodeIndex(stack.back());
      stack.pop_back();
      for (int a = 0; a < D; ++a)
      {
        for (int s : { -1, 1 })
        {
          std::array<sltk::Index, D> n = i;
          n[a] += s;
          if (n[a] < 0 || n[a] >= g.Dims[a])
          {
            continue;
          }
          sltk::Index m = 0;
          for (int b = D - 1; b >= 0; --b)
          {
            m = m * g.Dims[b] + n[b];
          }
          if (!seen[static_cast<size_t>(m)] && phi(n) < 0.0)
          {
            seen[static_cast<size_t>(m)] = 1;
            stack.push_back(m);
          }
        }
      }
    }
  }
  return count;
}

template <int D>
void expectFloodFillCount(const std::array<sltk::Index, D>& dims, double insideShare, unsigned seed)
{
  sltk::GridField<D> phi;
  phi.resize(unitGrid<D>(dims), 2, 1.0);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (sltk::Index k = 0; k < phi.spec().nodeCount(); ++k)
  {
    phi(phi.nodeIndex(k)) = u(random) < insideShare ? -1.0 : 1.0;
  }
  sltk::SlabPlan whole;
  whole.End = whole.Stop = dims[D - 1];
  const std::int64_t count =
    sltk::insideComponents<D>(sltk::SlabNodes<D>(phi, phi.spec(), whole, 0), sltk::serialCommunicator());
  EXPECT_EQ(count, floodFillComponents<D>(phi)) << "inside share " << insideShare << ", seed " << seed;
}

/// Circles of radius r about each centre, one point every h along them.
sltk::PointCloud<2> circles(const std::vector<std::array<double, 2>>& centres, double r, double h)
{
  sltk::PointCloud<2> cloud;
  const int n = static_cast<int>(std::ceil(2.0 * 3.14159265358979323846 * r / h));
  for (const auto& c : centres)
  {
    for (int k = 0; k < n; ++k)
    {
      const double a = 2.0 * 3.14159265358979323846 * k / n;
      cloud.Points.push_back({ c[0] + r * std::cos(a), c[1] + r * std::sin(a) });
    }
  }
  return cloud;
}

/// Two discs of radius 0.5 centred 2 apart, joined by a neck `thickness` thick: the outline,
/// one point every h (one component of the cloud at 4 h_P).
sltk::PointCloud<2> dumbbell(double thickness, double h)
{
  sltk::PointCloud<2> cloud;
  const double r = 0.5, pi = 3.14159265358979323846;
  const double opening = std::asin(thickness / (2.0 * r));
  for (int side : { -1, 1 })
  {
    const int n = static_cast<int>(std::ceil(2.0 * pi * r / h));
    for (int k = 0; k < n; ++k)
    {
      const double a = 2.0 * pi * k / n; // measured from the neck
      if (a > opening && a < 2.0 * pi - opening)
      {
        cloud.Points.push_back({ side * (1.0 - r * std::cos(a)), r * std::sin(a) });
      }
    }
  }
  const double neckEnd = 1.0 - r * std::cos(opening);
  for (double x = -neckEnd; x <= neckEnd; x += h)
  {
    cloud.Points.push_back({ x, thickness / 2.0 });
    cloud.Points.push_back({ x, -thickness / 2.0 });
  }
  return cloud;
}
} // namespace

TEST(InsideComponents, RunsMatchAFloodFill)
{
  // Random inside nodes near the percolation threshold: many components of every shape
  // (U-turns, spirals) that join only through lines labelled later.
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    expectFloodFillCount<2>({ 41, 37 }, 0.55, seed);
    expectFloodFillCount<3>({ 17, 13, 11 }, 0.3, seed);
  }
  expectFloodFillCount<3>({ 9, 8, 7 }, 0.0, 1);
  expectFloodFillCount<3>({ 9, 8, 7 }, 1.0, 1);
}

TEST(InsideComponents, CloudComponentsLinkPointsCloserThanTheLink)
{
  // Evenly sampled (every 0.02): the local spacing is h_P, the link 4 h_P.
  const sltk::PointCloud<2> two = circles({ { -0.8, 0.0 }, { 0.8, 0.0 } }, 0.5, 0.02);
  const sltk::PointLocator<2> locator(two);
  const sltk::Context ctx;
  EXPECT_EQ(sltk::cloudComponents(locator, 0.02, 4.0, 16, ctx), 2);
  EXPECT_EQ(sltk::cloudComponents(locator, 0.175, 4.0, 16, ctx), 1) << "a link longer than the gap joins them";
}

TEST(InsideComponents, UnevenlySampledObjectIsOneComponent)
{
  // One circle, its upper half sampled every 0.005, its lower half every 0.05: h_P is
  // about 0.009, so 4 h_P splits the sparse half point by point; the local spacing
  // (capped at 4 times the median, 0.02) links it.
  const sltk::PointCloud<2> cloud = sltk::unevenHalvesCircleCloud(0.5, { 0.0, 0.0 }, 0.005, 0.05);
  const sltk::PointLocator<2> locator(cloud);
  double h = 0.0;
  ASSERT_TRUE(sltk::cloudSpacing(locator, sltk::Context{}, h).isOk());
  EXPECT_LT(4.0 * h, 0.05);
  EXPECT_GT(sltk::cloudComponents(locator, h, sltk::PieceLinkFactor, 0, sltk::Context{}), 20)
    << "4 h_P alone splits the sparse half";
  sltk::ThreadPool pool(2);
  sltk::Context threaded;
  threaded.Executor = &pool;
  EXPECT_EQ(sltk::cloudComponents(locator, h, sltk::PieceLinkFactor, 16, sltk::Context{}), 1);
  EXPECT_EQ(sltk::cloudComponents(locator, h, sltk::PieceLinkFactor, 16, threaded), 1) << "two threads";
}

TEST(InsideComponents, ObjectsTwentyLocalSpacingsApartAreTwoComponents)
{
  // The uneven circle and a circle sampled every 0.05 below it, their sparse sides 20 of
  // that spacing apart: two components; one spacing apart: one.
  for (const auto& [gap, expected] : { std::pair<double, sltk::Index>{ 20.0, 2 }, { 1.0, 1 } })
  {
    sltk::PointCloud<2> cloud = sltk::unevenHalvesCircleCloud(0.5, { 0.0, 0.0 }, 0.005, 0.05);
    for (const auto& p : sltk::unevenHalvesCircleCloud(0.5, { 0.0, -1.0 - gap * 0.05 }, 0.05, 0.05).Points)
    {
      cloud.Points.push_back(p);
    }
    const sltk::PointLocator<2> locator(cloud);
    double h = 0.0;
    ASSERT_TRUE(sltk::cloudSpacing(locator, sltk::Context{}, h).isOk());
    EXPECT_EQ(sltk::cloudComponents(locator, h, sltk::PieceLinkFactor, 16, sltk::Context{}), expected) << gap;
  }
}

TEST(InsideComponents, SeparateDiscsAreTheirComponents)
{
  // Two discs 0.6 apart: 2 pieces, 2 components at 4 h_P; nothing to say.
  const sltk::PointCloud<2> cloud = circles({ { -0.8, 0.0 }, { 0.8, 0.0 } }, 0.5, 0.02);
  sltk::Context ctx;
  sltk::ReconstructionResult<2> result;
  const sltk::Status status = sltk::reconstruct(cloud, sltk::ReconstructionOptions{}, ctx, result);
  ASSERT_TRUE(status.isOk()) << status.message();
  EXPECT_EQ(result.Pieces, 2);
  EXPECT_EQ(result.CloudComponents, 2);
  EXPECT_TRUE(result.FitsCloud);
  for (const std::string& note : result.Recoveries)
  {
    EXPECT_EQ(note.find("pieces where the cloud has"), std::string::npos) << note;
  }
}

TEST(InsideComponents, BrokenNeckIsSaid)
{
  // A neck one h_P thick on cells of 4 h_P breaks: two pieces where the cloud is one
  // component. WENO3 given: no recovery, the statement comes first, with advice that is
  // not what ran.
  const sltk::PointCloud<2> cloud = dumbbell(0.02, 0.02);
  sltk::ReconstructionOptions given;
  given.Interpolator = sltk::InterpolatorKind::Weno3;
  given.CellSizeFactor = 4.0;
  given.Runs = 1;
  sltk::Context ctx;
  sltk::ReconstructionResult<2> result;
  const sltk::Status status = sltk::reconstruct(cloud, given, ctx, result);
  ASSERT_TRUE(status.isOk()) << status.message();
  EXPECT_EQ(result.CloudComponents, 1);
  ASSERT_GT(result.Pieces, 1) << "the neck was expected to break at C_dx = 4";
  EXPECT_FALSE(result.FitsCloud);
  EXPECT_TRUE(result.Recoveries.empty());
  ASSERT_FALSE(result.Warnings.empty());
  EXPECT_EQ(result.Warnings[0].find("the result has " + std::to_string(result.Pieces) +
              " pieces where the cloud has 1 connected component(s) at 4 local spacings"),
    0u)
    << result.Warnings[0];
  EXPECT_NE(result.Warnings[0].find("a C_dx below the 4 that ran"), std::string::npos) << result.Warnings[0];
  EXPECT_EQ(result.Warnings[0].find("weno3"), std::string::npos) << "WENO3 ran: " << result.Warnings[0];

  // The automatic interpolator takes the least-squares Q1 on this clean cloud: its broken
  // result is run again with WENO3 on the same grid, and what that gives is said.
  given.Interpolator.reset();
  sltk::ReconstructionResult<2> recovered;
  ASSERT_TRUE(sltk::reconstruct(cloud, given, ctx, recovered).isOk());
  ASSERT_FALSE(recovered.Recoveries.empty());
  EXPECT_NE(recovered.Recoveries.back().find("with the automatic interpolator lsq-q1: reconstructed again with weno3"),
    std::string::npos)
    << recovered.Recoveries.back();
  EXPECT_EQ(recovered.Interpolator, sltk::InterpolatorKind::Weno3);
  EXPECT_EQ(recovered.CellSizeFactor, 4.0) << "the same grid";
  EXPECT_EQ(recovered.Pieces, result.Pieces) << "the same grid and interpolator as the given WENO3";
  EXPECT_FALSE(recovered.FitsCloud);
  ASSERT_FALSE(recovered.Warnings.empty());
  EXPECT_EQ(recovered.Warnings[0].find("the result has"), 0u) << recovered.Warnings[0];
}

TEST(InsideComponents, TilesCountTheUniformPieces)
{
  // The tiled band (runs >= 2 on tiles, runs broken at the tiles' edges) counts the pieces
  // of the uniform grid: the broken neck's, and the two discs'.
  sltk::ReconstructionOptions given;
  given.Interpolator = sltk::InterpolatorKind::Weno3;
  given.CellSizeFactor = 4.0;
  given.Runs = 2;
  const sltk::PointCloud<2> clouds[2] = { dumbbell(0.02, 0.02), circles({ { -0.8, 0.0 }, { 0.8, 0.0 } }, 0.5, 0.02) };
  const std::int64_t least[2] = { 1, 2 };
  for (int c = 0; c < 2; ++c)
  {
    const sltk::PointCloud<2>& cloud = clouds[c];
    sltk::Context ctx;
    sltk::ReconstructionPlan<2> plan;
    ASSERT_TRUE(sltk::planReconstruction(cloud, given, ctx, plan).isOk());
    sltk::ReconstructionResult<2> uniform;
    ASSERT_TRUE(sltk::reconstruct(plan, ctx, uniform).isOk());
    sltk::TiledReconstructionResult<2> tiled;
    ASSERT_TRUE(sltk::reconstructTiled(plan, ctx, tiled).isOk());
    EXPECT_GE(uniform.Pieces, least[c]);
    EXPECT_EQ(tiled.Records.Pieces, uniform.Pieces);
    EXPECT_EQ(tiled.Records.FitsCloud, uniform.FitsCloud);
  }
}
