// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file MpiWorld.h
/// The communicator seam on MPI_COMM_WORLD for the GoogleTest programs of
/// Mpi/ (run by MpiTestMain.cxx on one rank and under mpiexec), and their shared checks.
#include "sltk/exec/Interrupter.h"
#include "sltk/mpi/MpiCommunicator.h"
#include "sltk/recon/MissedPlaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

inline std::unique_ptr<sltk::mpi::MpiCommunicator> world()
{
  std::unique_ptr<sltk::mpi::MpiCommunicator> comm;
  EXPECT_TRUE(sltk::mpi::MpiCommunicator::world(comm).isOk());
  return comm;
}

/// Counts the progress checks (Calls) and stops the run from the `StopAt`-th
/// on (0: never): set on one rank only, an interruption the others must follow.
struct StopOnOneRank : sltk::Interrupter
{
  int Calls = 0, StopAt = 0;
  bool wasInterrupted(double) override { return ++Calls >= StopAt && StopAt > 0; }
};

/// Where the surface misses points (MissedPlaces.h: each rank's points gathered in the cloud's
/// order) on the ranks, `mine`, against one rank's, `one`: the same places with their counts.
template <int D>
void expectSameMissedPlaces(const std::vector<sltk::MissedPlace<D>>& mine, const std::vector<sltk::MissedPlace<D>>& one)
{
  EXPECT_EQ(mine.size(), one.size());
  for (size_t k = 0; k < std::min(one.size(), mine.size()); ++k)
  {
    EXPECT_EQ(mine[k].Points, one[k].Points) << "place " << k;
    EXPECT_EQ(mine[k].Nearby, one[k].Nearby) << "place " << k;
    EXPECT_EQ(mine[k].Lower, one[k].Lower) << "place " << k;
    EXPECT_EQ(mine[k].Upper, one[k].Upper) << "place " << k;
  }
}
