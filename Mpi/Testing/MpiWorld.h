// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file MpiWorld.h
/// The communicator seam on MPI_COMM_WORLD for the GoogleTest programs of
/// Mpi/ (run by MpiTestMain.cxx on one rank and under mpiexec).
#include "sltk/exec/Interrupter.h"
#include "sltk/mpi/MpiCommunicator.h"

#include <gtest/gtest.h>

#include <memory>

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
