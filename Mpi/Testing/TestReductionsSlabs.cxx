// SPDX-License-Identifier: BSD-3-Clause
// The global quantities of a reconstruction iteration on the slabs of
// MPI_COMM_WORLD (ctest: 1 and 2 ranks; also right on 3 and 4): the energy
// E_p, E_2 (4.29) over the band cells of each rank's owned rows, reduced
// (reduceEnergy), and Err_P (4.35) summed over the points of each rank's
// owned cells (cloudErrorSum), are the one-rank values to rounding (the same
// terms added in another order), with the same number of front cells.
#include "MpiWorld.h"
#include "SlabWindow.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/interp/Interpolators.h"
#include "sltk/recon/CloudError.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/EnergyFunctional.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
constexpr sltk::Index N = 81;

} // namespace

TEST(ReductionsSlabs, EnergyAndCloudErrorAreTheOneRankValues)
{
  auto comm = world();
  const sltk::GridSpec<2> whole = sltk::uniformBox<2>(N, -1.5, 1.5);
  const sltk::PointCloud<2> cloud = sltk::circleCloud(300);
  sltk::GridField<2> dist, phi(whole, 2);
  ASSERT_TRUE(sltk::distanceToCloud(cloud, whole, sltk::Context{}, dist).isOk());
  for (sltk::Index k = 0; k < whole.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    phi(i) = sltk::circleSdf({ whole.coordinate(0, i[0]), whole.coordinate(1, i[1]) }, 1.1, { 0.05, -0.1 });
  }
  phi.fillGhosts();
  sltk::NodeList band;
  sltk::collectBand(phi, 4.0 * whole.Spacing[0], sltk::Context{}, band);
  sltk::EnergyOptions options;
  options.P = 1.0;
  options.SecondP = 2.0;
  sltk::EnergyResult one;
  ASSERT_TRUE(sltk::energyFunctional(phi, dist, band, sltk::Context{}, one, options).isOk());
  using Interp = sltk::CwenoInterpolator<2, sltk::CwenoVariant::CwenoZ>;
  const double oneError = sltk::cloudErrorSum<2, Interp>(phi, cloud, sltk::Context{}) / cloud.size();

  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlab(N, 3, comm->rank(), comm->size(), "the CWENO stencil", slab).isOk());
  const sltk::GridField<2> myPhi = windowOf(phi, slab), myDist = windowOf(dist, slab);
  sltk::NodeList owned; // band cells whose lowest corner is in my owned rows, in my window's numbering
  for (const sltk::Index node : band)
  {
    if (node / N >= slab.Begin && node / N < slab.End)
    {
      owned.push_back(node - slab.First * N);
    }
  }
  sltk::EnergyResult mine;
  ASSERT_TRUE(sltk::energyFunctional(myPhi, myDist, owned, sltk::Context{}, mine, options).isOk());
  sltk::reduceEnergy(mine, options, *comm);
  EXPECT_EQ(mine.FrontCells, one.FrontCells);
  EXPECT_NEAR(mine.Energy, one.Energy, 1e-13 * one.Energy);
  EXPECT_NEAR(mine.SecondEnergy, one.SecondEnergy, 1e-13 * one.SecondEnergy);
  const double sum = comm->allReduce(
    sltk::cloudErrorSum<2, Interp>(myPhi, cloud, sltk::Context{}, slab.Begin, slab.End, N), sltk::ReduceOp::Sum);
  EXPECT_NEAR(sum / cloud.size(), oneError, 1e-13 * oneError);
  EXPECT_GT(oneError, 0.05) << "the front is off the cloud: Err_P measures something";
}
