// SPDX-License-Identifier: BSD-3-Clause
// One semi-Lagrangian step of the reconstruction (LevelSetStep.h) on the
// slabs of MPI_COMM_WORLD (ctest: 1 and 2 ranks; also right on 3 and 4): with
// as many ghost rows as the feet reach (LevelSetStepReach.h) plus the
// interpolation stencil, each rank's step of its owned band nodes is bitwise
// the one-rank step, with Q1 and CWENO-Z, and exchangeGhostRows (SlabExchange.h)
// then gives every rank the owners' values in its ghost rows.
#include "MpiWorld.h"
#include "SlabWindow.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/grid/SlabExchange.h"
#include "sltk/interp/Interpolators.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/LevelSetStepReach.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
constexpr sltk::Index N = 81;
constexpr int PhiGhost = 2;

template <class Interp>
void expectStepSameAsOneRank()
{
  auto comm = world();
  const sltk::GridSpec<2> whole = sltk::uniformBox<2>(N, -1.5, 1.5);
  const double dx = whole.Spacing[0];
  sltk::GridField<2> dist, phi(whole, PhiGhost);
  ASSERT_TRUE(sltk::distanceToCloud(sltk::circleCloud(200), whole, sltk::Context{}, dist).isOk());
  for (sltk::Index k = 0; k < whole.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    phi(i) = sltk::circleSdf({ whole.coordinate(0, i[0]), whole.coordinate(1, i[1]) }, 1.3); // outside the cloud
  }
  phi.fillGhosts();
  sltk::LevelSetStepParameters par;
  par.P = 1.0;
  par.Eta = 0.5;
  par.TimeStep = dx;
  par.Widths = sltk::BandWidths::forSpacing(dx);
  sltk::NodeList band;
  sltk::collectBand(phi, par.Widths.Gamma, sltk::Context{}, band);
  sltk::EnergyResult energy;
  ASSERT_TRUE(sltk::energyFunctional(phi, dist, band, sltk::Context{}, energy).isOk());
  par.Energy = energy.Energy;
  const double reach = sltk::levelSetStepReach(phi, dist, band, par);
  EXPECT_GT(reach, 1.0) << "the test should move feet across rows";

  // The one-rank step.
  sltk::GridField<2> one = phi;
  std::vector<double> scratch;
  ASSERT_TRUE((sltk::levelSetStep<Interp, 2>(sltk::Context{}, one, dist, band, par, scratch).isOk()));

  // The slabs: ghost rows for the reach, the centred gradients and the stencil (3 rows, as HJB's).
  sltk::SlabPlan slab;
  const auto ghost = static_cast<sltk::Index>(std::ceil(reach)) + 3;
  ASSERT_TRUE(sltk::planSlab(N, ghost, comm->rank(), comm->size(), "the feet's reach", slab).isOk());
  sltk::GridField<2> mine = windowOf(phi, slab);
  const sltk::GridField<2> myDist = windowOf(dist, slab);
  sltk::NodeList owned; // the band nodes of my owned rows, in my window's numbering
  for (const sltk::Index node : band)
  {
    const sltk::Index row = node / N;
    if (row >= slab.Begin && row < slab.End)
    {
      owned.push_back(node - slab.First * N);
    }
  }
  ASSERT_TRUE((sltk::levelSetStep<Interp, 2>(sltk::Context{}, mine, myDist, owned, par, scratch).isOk()));
  sltk::Index differing = 0;
  for (const sltk::Index node : owned)
  {
    differing += mine(mine.nodeIndex(node)) == one(one.nodeIndex(node + slab.First * N)) ? 0 : 1;
  }
  EXPECT_EQ(differing, 0) << "rank " << comm->rank() << " of " << comm->size() << ", " << owned.size()
                          << " owned band nodes, ghost rows " << ghost;

  // The halo exchange: every window row now holds the one-rank step's values.
  sltk::exchangeGhostRows(mine, slab, *comm);
  sltk::Index stale = 0;
  for (sltk::Index k = 0; k < mine.spec().nodeCount(); ++k)
  {
    stale += mine(mine.nodeIndex(k)) == one(one.nodeIndex(k + slab.First * N)) ? 0 : 1;
  }
  EXPECT_EQ(stale, 0) << "rank " << comm->rank() << " of " << comm->size();
}
} // namespace

TEST(LevelSetStepSlabs, Q1StepOnSlabsIsTheOneRankStep)
{
  expectStepSameAsOneRank<sltk::Q1Interpolator<2>>();
}

TEST(LevelSetStepSlabs, CwenoZStepOnSlabsIsTheOneRankStep)
{
  expectStepSameAsOneRank<sltk::CwenoInterpolator<2, sltk::CwenoVariant::CwenoZ>>();
}
