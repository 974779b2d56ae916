// SPDX-License-Identifier: GPL-2.0-or-later
// Runs serially and under `mpiexec -n 2`: the forest is partitioned, the
// global octant count does not depend on the number of ranks.
#include "sltk/mpi/MpiCommunicator.h"
#include "sltk/p4est/Forest.h"

#include <gtest/gtest.h>
#include <mpi.h>

TEST(Forest, UniformRefinementCountsOctants)
{
  std::unique_ptr<sltk::mpi::MpiCommunicator> world;
  ASSERT_TRUE(sltk::mpi::MpiCommunicator::world(world).isOk());
  for (int level = 0; level <= 4; ++level)
  {
    std::unique_ptr<sltk::p4est::Forest> forest;
    ASSERT_TRUE(sltk::p4est::Forest::createUniform(*world, level, forest).isOk());
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
  std::unique_ptr<sltk::p4est::Forest> forest;
  auto s = sltk::p4est::Forest::createUniform(sltk::serialCommunicator(), 40, forest);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_EQ(forest, nullptr);
}
