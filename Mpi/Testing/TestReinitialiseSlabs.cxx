// SPDX-License-Identifier: BSD-3-Clause
// reinitialiseSlabs() (ReinitialiseSlabs.h) on the ranks of MPI_COMM_WORLD
// (ctest: 1 and 2 ranks; also right on 3 and 4): a level-set function that is
// not a distance, reinitialised on the band of each rank's owned rows with the
// ghost rows exchanged after every pseudo-time step, is bitwise the one-rank
// reinitialisation with the same step count, for the constrained (4.4.5) and
// the plain method; a front inside one rank's rows leaves the others an empty
// band, and they still take part. On one rank the steps go in skewed rounds
// (no rows to exchange), which must give the plain steps' values too.
#include "MpiWorld.h"
#include "SlabWindow.h"
#include "sltk/grid/SlabExchange.h"
#include "sltk/levelset/ReinitialiseSlabs.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
constexpr sltk::Index N = 81;

void expectSameAsOneRank(double cy, double r, sltk::ReinitMethod method)
{
  auto comm = world();
  const sltk::GridSpec<2> whole = sltk::uniformBox<2>(N, -1.0, 1.0);
  const double dx = whole.Spacing[0];
  sltk::GridField<2> phi(whole, 2);
  for (sltk::Index k = 0; k < whole.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    const double x = whole.coordinate(0, i[0]), y = whole.coordinate(1, i[1]);
    phi(i) = (std::hypot(x - 0.1, y - cy) - r) * (1.0 + 0.6 * x + 0.3 * y * y); // not |grad phi| = 1
  }
  phi.fillGhosts();
  sltk::NodeList band, wide;
  sltk::collectBand(phi, 4.0 * dx, sltk::Context{}, band);
  sltk::dilateBand(whole, band, 2, sltk::Context{}, wide);
  sltk::ReinitOptions options;
  options.Method = method;
  sltk::GridField<2> one = phi;
  sltk::ReinitReport oneReport;
  ASSERT_TRUE(sltk::reinitialise<2>(one, wide, options, sltk::Context{}, &oneReport).isOk());

  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlab(N, 2, comm->rank(), comm->size(), "the reinitialisation's stencil", slab).isOk());
  sltk::GridField<2> mine = windowOf(phi, slab);
  sltk::NodeList owned;
  for (const sltk::Index node : wide)
  {
    if (node / N >= slab.Begin && node / N < slab.End)
    {
      owned.push_back(node - slab.First * N);
    }
  }
  sltk::ReinitReport report;
  sltk::ReinitWorkspace workspace;
  workspace.SkewedBandNodes = 0; // one rank: skewed steps (Reinitialise.cxx), against the plain ones above
  const sltk::Status s =
    sltk::reinitialiseSlabs<2>(mine, owned, slab, *comm, options, sltk::Context{}, &report, &workspace);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(report.Iterations, oneReport.Iterations);
  EXPECT_EQ(report.Converged, oneReport.Converged);
  sltk::Index differing = 0;
  for (sltk::Index k = (slab.Begin - slab.First) * N; k < (slab.End - slab.First) * N; ++k)
  {
    differing += mine(mine.nodeIndex(k)) == one(one.nodeIndex(k + slab.First * N)) ? 0 : 1;
  }
  EXPECT_EQ(differing, 0) << "rank " << comm->rank() << " of " << comm->size() << ", " << owned.size()
                          << " owned band nodes, " << report.Iterations << " steps";
}
} // namespace

TEST(ReinitialiseSlabs, ConstrainedAcrossTheSlabsIsTheOneRankReinitialisation)
{
  expectSameAsOneRank(0.0, 0.6, sltk::ReinitMethod::Constrained);
}

TEST(ReinitialiseSlabs, PlainAcrossTheSlabsIsTheOneRankReinitialisation)
{
  expectSameAsOneRank(0.0, 0.6, sltk::ReinitMethod::Plain);
}

TEST(ReinitialiseSlabs, AFrontInOneRanksRowsLeavesTheOthersAnEmptyBand)
{
  expectSameAsOneRank(-0.8, 0.12, sltk::ReinitMethod::Constrained);
}
