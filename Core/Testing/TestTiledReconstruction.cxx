// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/octree/TiledReconstruction.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/core/IndexBox.h"
#include "sltk/octree/TiledMemory.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace
{
template <int D>
void compareWithUniform(const sltk::PointCloud<D>& cloud, sltk::ReconstructionOptions options, double errorRatio)
{
  sltk::Context ctx;
  sltk::ReconstructionPlan<D> plan;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, ctx, plan).isOk());
  sltk::ReconstructionResult<D> uniform;
  ASSERT_TRUE(sltk::reconstruct(plan, ctx, uniform).isOk());
  sltk::TiledReconstructionResult<D> tiled;
  const sltk::Status status = sltk::reconstructTiled(plan, ctx, tiled);
  ASSERT_TRUE(status.isOk()) << status.message();
  ASSERT_EQ(tiled.Records.Runs.size(), uniform.Runs.size());
  EXPECT_EQ(tiled.Records.Pieces, uniform.Pieces) << "the tiles' pieces (InsideComponents.h) are the grid's";
  EXPECT_EQ(tiled.Records.CloudComponents, uniform.CloudComponents);
  for (size_t r = 0; r < uniform.Runs.size(); ++r)
  {
    std::cout << "run " << r + 1 << ": uniform " << uniform.Runs[r].Iterations << " iterations, Err_P "
              << uniform.Runs[r].CloudError << "; tiled " << tiled.Records.Runs[r].Iterations << " iterations, Err_P "
              << tiled.Records.Runs[r].CloudError << "\n";
  }
  for (const auto& s : tiled.Storage)
  {
    std::cout << "run " << s.Run << ": " << s.Tiles << " tiles, " << s.StoredNodes << " stored nodes of "
              << s.UniformNodes << " (" << 100.0 * s.StoredNodes / s.UniformNodes << "%), " << s.AddedTiles
              << " added, " << s.FreedTiles << " freed, at most " << s.PeakTiles << " held\n";
    EXPECT_GE(s.PeakTiles, s.Tiles);
  }
  EXPECT_LT(tiled.Records.Runs.back().CloudError, errorRatio * uniform.Runs.back().CloudError);
  // The memory check's estimate of the finest run's tiles (TiledMemory.h) is close to what the run
  // stored: above it on the sphere (and the bunny, the dragon), 3% below on the 64-point circle,
  // whose front lies farther than a tile from its points between them (the run's own check,
  // checkTileMemory, stops a run whose tiles do not fit).
  const double estimate = sltk::estimatedTiledNodes(plan.Cloud, plan.Grids.Runs.back());
  std::cout << "finest run: " << tiled.Storage.back().StoredNodes << " stored nodes, " << estimate << " estimated\n";
  EXPECT_GE(estimate, 0.9 * static_cast<double>(tiled.Storage.back().StoredNodes));
  // Same grid: phi agrees with the uniform result where both are near the front.
  const auto& field = tiled.Field;
  const auto& phi = uniform.SignedDistance; // user units
  double largest = 0.0;
  sltk::Index compared = 0;
  for (std::int32_t id = 0; id < field.tileCount(); ++id)
  {
    for (sltk::Index k = 0; k < sltk::TiledField<D>::Nodes; ++k)
    {
      const auto i = field.node(id, k);
      bool inside = true;
      for (int a = 0; a < D; ++a)
      {
        inside = inside && i[a] < phi.spec().Dims[a];
      }
      const double v = field.phi(id)[k];
      if (inside && std::fabs(v) < 2.0 * field.grid().Spacing[0])
      {
        largest = std::max(largest, std::fabs(v * tiled.Box.Scale - phi(i)));
        ++compared;
      }
    }
  }
  std::cout << compared << " nodes near the front: largest |phi_tiled - phi_uniform| = "
            << largest / (field.grid().Spacing[0] * tiled.Box.Scale) << " cells\n";
  EXPECT_GT(compared, 0);
  // The cloud's centre is inside (-gamma, no tile there), a corner of the grid outside.
  std::array<sltk::Index, D> centre{}, corner{};
  for (int a = 0; a < D; ++a)
  {
    centre[a] = static_cast<sltk::Index>(std::lround(-field.grid().Origin[a] / field.grid().Spacing[a]));
  }
  EXPECT_EQ(field.value(centre), -field.gamma());
  EXPECT_EQ(field.value(corner), field.gamma());
  EXPECT_LT(largest, 0.5 * field.grid().Spacing[0] * tiled.Box.Scale);
  // Every node of the uniform result's band lies in a tile (the tiles follow
  // the band), and every band node of the tiled result has its exact distance.
  sltk::Index uniformBand = 0, untiled = 0;
  for (sltk::Index k = 0; k < phi.spec().nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    if (std::fabs(phi(i)) < field.gamma() * tiled.Box.Scale)
    {
      ++uniformBand;
      std::array<sltk::Index, D> t{};
      for (int a = 0; a < D; ++a)
      {
        t[a] = i[a] >> sltk::TileBits;
      }
      untiled += field.slot(field.slotIndex(t)) < 0 ? 1 : 0;
    }
  }
  EXPECT_GT(uniformBand, 0);
  EXPECT_EQ(untiled, 0);
  sltk::Index bandNodes = 0;
  double distanceError = 0.0;
  for (std::int32_t id = 0; id < field.tileCount(); ++id)
  {
    for (sltk::Index k = 0; k < sltk::TiledField<D>::Nodes; ++k)
    {
      if (std::fabs(field.phi(id)[k]) < field.gamma())
      {
        ++bandNodes;
        const double exact = plan.Locator->nearest(field.position(field.node(id, k))).Distance;
        const double d = field.distance(id)[k];
        distanceError = std::isnan(d) ? HUGE_VAL : std::max(distanceError, std::fabs(d - exact));
      }
    }
  }
  EXPECT_GT(bandNodes, 0);
  EXPECT_EQ(distanceError, 0.0);
  // The tiles follow the band (PruneTiles.h): a tile at one +-gamma throughout
  // holds a node within the reinitialisation's dilation (at least one node) of
  // a band node, where the last iteration may write or read it.
  const sltk::Index reach = std::max(options.ReinitDilation, 1);
  const auto nearBand = [&](std::int32_t id)
  {
    const auto& o = field.tileOrigin(id);
    std::array<sltk::Index, D> lo{}, hi{};
    for (int a = 0; a < D; ++a)
    {
      lo[a] = std::max<sltk::Index>(o[a] - 1, 0);
      hi[a] = std::min<sltk::Index>(o[a] + 1, field.slotDims()[a] - 1);
    }
    bool near = false;
    sltk::forEachIndexInBox<D>(lo, hi,
      [&](const std::array<sltk::Index, D>& t)
      {
        const std::int32_t other = field.slot(field.slotIndex(t));
        for (sltk::Index k = 0; other >= 0 && !near && k < sltk::TiledField<D>::Nodes; ++k)
        {
          if (!(std::fabs(field.phi(other)[k]) < field.gamma()))
          {
            continue;
          }
          const auto i = field.node(other, k);
          bool within = true; // i within `reach` of the tile's nodes, each axis
          for (int a = 0; a < D; ++a)
          {
            within = within && i[a] >= o[a] * sltk::TileEdge - reach && i[a] < (o[a] + 1) * sltk::TileEdge + reach;
          }
          near = within;
        }
      });
    return near;
  };
  sltk::Index lonely = 0, flat = 0;
  for (std::int32_t id = 0; id < field.tileCount(); ++id)
  {
    const double* p = field.phi(id);
    bool atGamma = true;
    for (sltk::Index k = 0; k < sltk::TiledField<D>::Nodes; ++k)
    {
      atGamma = atGamma && std::fabs(p[k]) == field.gamma() && p[k] == p[0];
    }
    flat += atGamma ? 1 : 0;
    lonely += atGamma && !nearBand(id) ? 1 : 0;
  }
  std::cout << flat << " tiles at one +-gamma throughout, " << lonely << " of them away from the band\n";
  EXPECT_EQ(lonely, 0);
}
} // namespace

TEST(TiledReconstruction, SphereAgreesWithTheUniformVersion)
{
  compareWithUniform<3>(sltk::sphereCloud(642), sltk::ReconstructionOptions::thesis(), 1.2);
}

TEST(TiledReconstruction, CircleAgreesWithTheUniformVersion)
{
  compareWithUniform<2>(sltk::circleCloud(64), sltk::ReconstructionOptions::thesis(), 1.2);
}

TEST(TiledReconstruction, CircleAgreesWithTheUniformVersionWithTheThesisLeastSquares)
{
  // The chapter 5 interpolation (5.5, LsqQ1.h) through both storages' dispatch.
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.Interpolator = sltk::InterpolatorKind::LeastSquaresQ1;
  compareWithUniform<2>(sltk::circleCloud(64), options, 1.2);
}

TEST(TiledReconstruction, MemoryCheckSizesTheTilesNotTheUniformGrid)
{
  // A sphere on a fine grid: the tiles need far less than the uniform grid, and the plan's
  // memory check (OctreeStorage) sizes them; the uniform plan is refused at the same budget.
  const auto cloud = sltk::sphereCloud(2562);
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.CellSizeFactor = 0.5;
  sltk::Context ctx;
  sltk::ReconstructionPlan<3> probe;
  ASSERT_TRUE(sltk::planReconstruction(cloud, options, ctx, probe).isOk());
  const auto& finest = probe.Grids.Runs.back();
  const double uniformNeed = static_cast<double>(finest.nodeCount()) * sltk::ReconstructionBytesPerNode;
  const double tiledNeed =
    static_cast<double>(probe.Grids.Runs.front().nodeCount()) * sltk::ReconstructionBytesPerNode +
    4.0 * static_cast<double>(finest.nodeCount()) / 512.0 +
    sltk::estimatedTiledNodes(probe.Cloud, finest) * sltk::TiledBytesPerStoredNode;
  ASSERT_LT(tiledNeed, 0.5 * uniformNeed);
  options.MemoryBudget = static_cast<std::uint64_t>(0.5 * (tiledNeed + uniformNeed));
  sltk::ReconstructionPlan<3> plan;
  const sltk::Status uniformStatus = sltk::planReconstruction(cloud, options, ctx, plan);
  EXPECT_EQ(uniformStatus.code(), sltk::StatusCode::OutOfMemory) << uniformStatus.message();
  // The uniform refusal names the tiled storage, which fits.
  EXPECT_NE(uniformStatus.message().find("--octree"), std::string::npos) << uniformStatus.message();
  options.OctreeStorage = true;
  const sltk::Status tiledStatus = sltk::planReconstruction(cloud, options, ctx, plan);
  EXPECT_TRUE(tiledStatus.isOk()) << tiledStatus.message();
  options.MemoryBudget = static_cast<std::uint64_t>(0.5 * tiledNeed);
  const sltk::Status refused = sltk::planReconstruction(cloud, options, ctx, plan);
  EXPECT_EQ(refused.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_NE(refused.message().find("the octree reconstruction"), std::string::npos) << refused.message();
  EXPECT_NE(refused.message().find("use C_dx >="), std::string::npos) << refused.message();
  // Where the tiles do not fit either, the uniform refusal does not offer them.
  options.OctreeStorage = false;
  const sltk::Status neither = sltk::planReconstruction(cloud, options, ctx, plan);
  EXPECT_EQ(neither.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_EQ(neither.message().find("--octree"), std::string::npos) << neither.message();
}
