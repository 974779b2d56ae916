// SPDX-License-Identifier: GPL-2.0-or-later
// Runs serially and under `mpiexec -n 2`: the forest is partitioned, the
// global octant count does not depend on the number of ranks.
#include "sltk/octree/Forest.h"

#include <gtest/gtest.h>
#include <mpi.h>

TEST(Forest, UniformRefinementCountsOctants)
{
  for (int level = 0; level <= 4; ++level)
  {
    std::unique_ptr<sltk::octree::Forest> forest;
    ASSERT_TRUE(sltk::octree::Forest::createUniform(nullptr, level, forest).isOk());
    EXPECT_EQ(forest->globalOctants(), std::int64_t(1) << (3 * level));
    long long local = forest->localOctants(), sum = 0;
    MPI_Allreduce(&local, &sum, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(sum, forest->globalOctants()) << "local octants partition the forest";
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (size > 1 && level >= 2)
    {
      EXPECT_LT(local, sum) << "every rank holds only part of the forest";
    }
  }
}

TEST(Forest, RejectsAbsurdLevels)
{
  std::unique_ptr<sltk::octree::Forest> forest;
  auto s = sltk::octree::Forest::createUniform(nullptr, 40, forest);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_EQ(forest, nullptr);
}

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0)
  {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int failed = RUN_ALL_TESTS();
  int anyFailed = 0;
  MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return anyFailed;
}
