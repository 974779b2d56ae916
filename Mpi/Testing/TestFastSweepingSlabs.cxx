// SPDX-License-Identifier: BSD-3-Clause
// FastSweepingSlabs.h on the ranks of MPI_COMM_WORLD (ctest: 1 and 2 ranks;
// also right on 3 and 4): the distance to a few points, fixed near them and
// swept everywhere else, is the one-rank sweep on every owned node to 1e-12
// relative, in 2D and 3D, whatever slab the points fall in (all in the
// lowest rank's here).
#include "MpiWorld.h"
#include "sltk/levelset/FastSweepingSlabs.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>

namespace
{
/// Distance to `points` at the nodes within 1.5 dx of one (frozen), +inf elsewhere.
template <int D>
void pointData(const sltk::GridSpec<D>& g, const std::vector<std::array<double, D>>& points,
  sltk::GridField<D, double>& u, std::vector<std::uint8_t>& frozen)
{
  u.resize(g, 1, std::numeric_limits<double>::infinity());
  frozen.assign(static_cast<size_t>(g.nodeCount()), 0);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& p : points)
    {
      double d2 = 0.0;
      for (int a = 0; a < D; ++a)
      {
        const double d = g.coordinate(a, i[a]) - p[a];
        d2 += d * d;
      }
      nearest = std::min(nearest, std::sqrt(d2));
    }
    if (nearest <= 1.5 * g.Spacing[0])
    {
      u(i) = nearest;
      frozen[static_cast<size_t>(k)] = 1;
    }
  }
}

template <int D>
void expectSameAsOneRank(sltk::Index n, const std::vector<std::array<double, D>>& points)
{
  auto comm = world();
  sltk::GridSpec<D> whole;
  for (int a = 0; a < D; ++a)
  {
    whole.Dims[a] = n;
    whole.Origin[a] = -1.0;
    whole.Spacing[a] = 2.0 / static_cast<double>(n - 1);
  }
  sltk::FastSweepingOptions until;
  until.Tolerance = 0.0; // until nothing changes: the unique discrete solution
  until.MaxCycles = 1000;
  sltk::GridField<D, double> serial;
  std::vector<std::uint8_t> serialFrozen;
  pointData<D>(whole, points, serial, serialFrozen);
  ASSERT_TRUE(sltk::fastSweep(serial, serialFrozen, sltk::Context{}, until).isOk());

  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlab(n, 1, comm->rank(), comm->size(), "the sweep's stencil", slab).isOk());
  sltk::GridSpec<D> part = whole;
  part.Dims[D - 1] = slab.windowRows();
  part.Offset[D - 1] = slab.First;
  sltk::GridField<D, double> window;
  std::vector<std::uint8_t> frozen;
  pointData<D>(part, points, window, frozen);
  sltk::FastSweepingSlabsReport report;
  const sltk::Status s = sltk::fastSweepSlabs(window, frozen, slab, *comm, sltk::Context{}, until, &report);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_TRUE(report.Converged);
  EXPECT_GE(report.Rounds, comm->size() > 1 ? 2 : 1);
  const sltk::Index rowNodes = whole.nodeCount() / n;
  sltk::Index differing = 0;
  double worst = 0.0;
  for (sltk::Index k = (slab.Begin - slab.First) * rowNodes; k < (slab.End - slab.First) * rowNodes; ++k)
  {
    const double mine = window(window.nodeIndex(k));
    const double one = serial(serial.nodeIndex(k + slab.First * rowNodes));
    differing += mine == one ? 0 : 1;
    worst = std::max(worst, std::fabs(mine - one) / one);
  }
  // The Godunov update's rounding (its square root) is not monotone, so the sweeps may settle in the last
  // bits elsewhere than one rank's (measured: 6.5e-14 relative at most, on a few hundred nodes).
  EXPECT_LE(worst, 1e-12) << "rank " << comm->rank() << " of " << comm->size() << ", " << differing << " nodes";
}
} // namespace

TEST(FastSweepingSlabs, DistanceToPointsIsTheOneRankSweepIn2D)
{
  // Points near the bottom only: the lowest rank's slab holds all the data, the others get it by exchanges.
  expectSameAsOneRank<2>(81, { { -0.5, -0.9 }, { 0.3, -0.8 }, { 0.9, -0.95 } });
}

TEST(FastSweepingSlabs, DistanceToPointsIsTheOneRankSweepIn3D)
{
  expectSameAsOneRank<3>(25, { { -0.5, 0.2, -0.9 }, { 0.3, -0.4, 0.85 } });
}

TEST(FastSweepingSlabs, AMaskOfTheWrongSizeIsRefusedOnEveryRank)
{
  auto comm = world();
  sltk::SlabPlan slab;
  ASSERT_TRUE(sltk::planSlab(40, 1, comm->rank(), comm->size(), "the sweep's stencil", slab).isOk());
  sltk::GridSpec<2> g;
  g.Dims = { 10, slab.windowRows() };
  sltk::GridField<2, double> u(g, 1, 1.0);
  std::vector<std::uint8_t> frozen(static_cast<size_t>(g.nodeCount()) - (comm->rank() == 0 ? 1 : 0), 0);
  const sltk::Status s = sltk::fastSweepSlabs(u, frozen, slab, *comm, sltk::Context{});
  EXPECT_FALSE(s.isOk()) << "rank 0's mask is one node short: every rank fails";
  comm->barrier(); // no hang
}
