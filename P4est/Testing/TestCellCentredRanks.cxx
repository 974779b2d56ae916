// SPDX-License-Identifier: GPL-2.0-or-later
// The cell-centred scheme on several ranks (run by P4est.Forest.TwoRanks
// under mpiexec, and on one rank by P4est.Forest.Serial): every rank also
// runs the whole case alone, and the ranks' leaves, gathered in rank order
// (the global Morton order), must be that run's leaves, value for value.
#include "CellCentredCases.h"
#include "MpiWorld.h"

#include "sltk/p4est/CellCentredReconstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace
{
using namespace sltk::p4est;
using sltk::Index;

/// Runs `plan` alone and over `comm`, and compares them.
template <int D>
void expectTheSameOnEveryRankCount(
  const sltk::ReconstructionPlan<D>& plan, const CellCentredOptions& cc, const sltk::Communicator& comm)
{
  CellCentredResult<D> alone, shared;
  ASSERT_TRUE(reconstructCellCentred(plan, cc, sltk::Context{}, alone).isOk());
  ASSERT_TRUE(reconstructCellCentred(plan, cc, sltk::Context{}, shared, comm).isOk());
  ASSERT_EQ(shared.Runs.size(), alone.Runs.size());
  for (size_t r = 0; r < alone.Runs.size(); ++r)
  {
    EXPECT_EQ(shared.Runs[r].Iterations, alone.Runs[r].Iterations);
    EXPECT_EQ(shared.Runs[r].TreeChanges, alone.Runs[r].TreeChanges);
  }
  ASSERT_EQ(shared.History.size(), alone.History.size());
  for (size_t n = 0; n < alone.History.size(); ++n)
  {
    // The sums are added in the one-rank order: equal, not close.
    EXPECT_EQ(shared.History[n].Energy, alone.History[n].Energy) << "iteration " << n;
    EXPECT_EQ(shared.History[n].CloudError, alone.History[n].CloudError) << "iteration " << n;
    EXPECT_EQ(shared.History[n].Leaves, alone.History[n].Leaves) << "iteration " << n;
    EXPECT_EQ(shared.History[n].FinestLeaves, alone.History[n].FinestLeaves) << "iteration " << n;
  }
  std::vector<std::int64_t> counts;
  const std::vector<CellCentredLeaf<D>> all = comm.allGatherV(shared.Leaves, &counts);
  ASSERT_EQ(all.size(), alone.Leaves.size());
  double phi = 0.0, distance = 0.0;
  Index different = 0; // NaN-proof: a leaf whose values are not those of one rank
  for (size_t i = 0; i < all.size(); ++i)
  {
    const CellCentredLeaf<D>& one = alone.Leaves[i];
    ASSERT_EQ(all[i].Centre, one.Centre) << "leaf " << i;
    ASSERT_EQ(all[i].Level, one.Level) << "leaf " << i;
    phi = std::max(phi, std::fabs(all[i].Phi - one.Phi));
    distance = std::max(distance, std::fabs(all[i].Distance - one.Distance));
    different += all[i].Phi == one.Phi && all[i].Distance == one.Distance && all[i].Polynomial.C == one.Polynomial.C &&
        all[i].Polynomial.Centre == one.Polynomial.Centre
      ? 0
      : 1;
  }
  if (comm.rank() == 0)
  {
    std::printf("%d ranks, %zu leaves (%lld on rank 0): largest differences from one rank: phi %g, d %g\n", comm.size(),
      all.size(), static_cast<long long>(counts[0]), phi, distance);
  }
  EXPECT_EQ(different, 0) << "leaves with another phi, d or polynomial than on one rank";
  if (comm.size() > 1)
  {
    for (const std::int64_t count : counts)
    {
      EXPECT_GT(count, 0) << "p4est's partition shares the leaves out";
    }
  }
}

} // namespace

TEST(CellCentredRanks, TheThesisCircleIsTheSameOnEveryRankCount)
{
  auto comm = world();
  CellCentredOptions cc;
  cc.FirstCellSize = 2.0 / 64.0;
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(planThesisCircle(plan).isOk());
  expectTheSameOnEveryRankCount(plan, cc, *comm);
}

TEST(CellCentredRanks, ASphereIsTheSameOnEveryRankCount)
{
  auto comm = world();
  sltk::ReconstructionPlan<3> plan;
  ASSERT_TRUE(planIcosphere(plan).isOk());
  CellCentredOptions cc;
  cc.FirstCellSize = 1.0 / 8.0;
  expectTheSameOnEveryRankCount(plan, cc, *comm);
}

TEST(CellCentredRanks, AMemoryFailureOnOneRankEndsEveryRank)
{
  // The last rank's budget holds its share of run 1's tree (2,416 leaves)
  // but not of run 3's (6,436): every rank returns its refusal, and none
  // waits in a collective.
  auto comm = world();
  CellCentredOptions cc;
  cc.FirstCellSize = 2.0 / 64.0;
  const double leaves = 4000.0 / comm->size();
  cc.MemoryBudget = comm->rank() == comm->size() - 1 ? static_cast<std::uint64_t>(leaves * CellCentredBytesPerLeaf) : 0;
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(planThesisCircle(plan).isOk());
  CellCentredResult<2> result;
  const sltk::Status s = reconstructCellCentred(plan, cc, sltk::Context{}, result, *comm);
  EXPECT_EQ(s.code(), sltk::StatusCode::OutOfMemory) << s.message();
  EXPECT_NE(s.message().find("grew beyond"), std::string::npos) << s.message();
}

TEST(CellCentredRanks, AnInterruptionOnOneRankEndsEveryRank)
{
  auto comm = world();
  StopOnOneRank stop;
  stop.StopAt = comm->rank() == comm->size() - 1 ? 30 : 0;
  sltk::Context ctx;
  ctx.Progress = &stop;
  CellCentredOptions cc;
  cc.FirstCellSize = 2.0 / 64.0;
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(planThesisCircle(plan).isOk());
  CellCentredResult<2> result;
  const sltk::Status s = reconstructCellCentred(plan, cc, ctx, result, *comm);
  EXPECT_EQ(s.code(), sltk::StatusCode::Aborted) << s.message();
}
