// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/tiled/TiledReconstruction.h"

#include "sltk/cloud/SyntheticClouds.h"
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
              << " added\n";
  }
  EXPECT_LT(tiled.Records.Runs.back().CloudError, errorRatio * uniform.Runs.back().CloudError);
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
