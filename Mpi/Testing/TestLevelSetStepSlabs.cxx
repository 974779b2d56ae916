// SPDX-License-Identifier: BSD-3-Clause
// One semi-Lagrangian step of the reconstruction (LevelSetStep.h) on the
// slabs of MPI_COMM_WORLD (ctest: 1 and 2 ranks; also right on 3 and 4): with
// ghost rows for the interpolation stencil only, the feet beyond them
// interpolated by their owners (FarFeetExchange.h), each rank's step of its
// owned band nodes is bitwise the one-rank step, with Q1 and CWENO-Z, and
// exchangeGhostRows (SlabExchange.h) then gives every rank the owners' values
// in its ghost rows.
#include "MpiWorld.h"
#include "SlabWindow.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/grid/SlabExchange.h"
#include "sltk/interp/Interpolators.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/FarFeetExchange.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

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
  par.Eta = 3.0; // feet spread over several rows
  par.TimeStep = dx;
  par.Widths = sltk::BandWidths::forSpacing(dx);
  sltk::NodeList band;
  sltk::collectBand(phi, par.Widths.Gamma, sltk::Context{}, band);
  sltk::EnergyResult energy;
  ASSERT_TRUE(sltk::energyFunctional(phi, dist, band, sltk::Context{}, energy).isOk());
  par.Energy = energy.Energy;

  // The one-rank step.
  sltk::GridField<2> one = phi;
  std::vector<double> scratch;
  ASSERT_TRUE((sltk::levelSetStep<Interp, 2>(sltk::Context{}, one, dist, band, par, scratch).isOk()));

  // The slabs: ghost rows for the interpolation stencil (the fewest footInWindow() allows).
  const sltk::Index ghost = Interp::GhostWidth + 2;
  const std::vector<sltk::Index> boundaries = sltk::evenSlabBoundaries(N, comm->size());
  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlabAt(boundaries, ghost, comm->rank(), "the stencil", slab).isOk());
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
  sltk::FarFeet<2> far;
  far.LowEdge = slab.First == 0;
  far.HighEdge = slab.Stop == N;
  EXPECT_TRUE((sltk::levelSetStepValues<Interp, 2>(sltk::Context{}, mine, myDist, owned, par, scratch, &far).isOk()));
  double farFeet = 0.0;
  EXPECT_TRUE(sltk::resolveFarFeet<Interp>(mine, far, whole, boundaries, *comm, farFeet).isOk());
  EXPECT_TRUE(sltk::finishFarNodes(far, scratch).isOk());
  sltk::storeLevelSetStep(sltk::Context{}, mine, owned, scratch);
  if (comm->size() > 1)
  {
    EXPECT_GT(farFeet, 0.0) << "the test should move feet beyond the ghost rows";
  }
  sltk::Index differing = 0;
  for (const sltk::Index node : owned)
  {
    differing += mine(mine.nodeIndex(node)) == one(one.nodeIndex(node + slab.First * N)) ? 0 : 1;
  }
  EXPECT_EQ(differing, 0) << "rank " << comm->rank() << " of " << comm->size() << ", " << owned.size()
                          << " owned band nodes, ghost rows " << ghost << ", " << farFeet << " far feet";

  // The halo exchange: every window row now holds the one-rank step's values,
  // also when the rows go one per message (the chunks of a wide halo).
  sltk::GridField<2> rowByRow = mine;
  sltk::exchangeGhostRows(mine, slab, *comm);
  sltk::exchangeGhostRows(rowByRow, slab, *comm, nullptr, std::numeric_limits<sltk::Index>::max(), sizeof(double));
  EXPECT_TRUE(std::equal(mine.storage().begin(), mine.storage().end(), rowByRow.storage().begin()))
    << "rank " << comm->rank() << ": the exchange one row per message differs";
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
