// SPDX-License-Identifier: BSD-3-Clause
// The whole cloud from the ranks' pieces (sltk/cloud/CloudPieces.h), serially
// and under `mpiexec -n 2` (also right on 3 and 4 ranks).
#include "sltk/cloud/CloudPieces.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/mpi/MpiCommunicator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace
{
std::unique_ptr<sltk::mpi::MpiCommunicator> world()
{
  std::unique_ptr<sltk::mpi::MpiCommunicator> comm;
  EXPECT_TRUE(sltk::mpi::MpiCommunicator::world(comm).isOk());
  return comm;
}

/// Rank r's contiguous block of `cloud`, and with `overlap` the next block's first point too.
sltk::PointCloud<3> blockOf(const sltk::PointCloud<3>& cloud, int rank, int size, bool overlap)
{
  const size_t n = cloud.Points.size();
  const size_t begin = n * static_cast<size_t>(rank) / static_cast<size_t>(size);
  size_t end = n * static_cast<size_t>(rank + 1) / static_cast<size_t>(size);
  end = overlap ? std::min(n, end + 1) : end;
  sltk::PointCloud<3> piece;
  piece.Points.assign(
    cloud.Points.begin() + static_cast<std::ptrdiff_t>(begin), cloud.Points.begin() + static_cast<std::ptrdiff_t>(end));
  return piece;
}
} // namespace

TEST(CloudPieces, TheSameCloudInAnyOrderIsKept)
{
  auto comm = world();
  sltk::PointCloud<3> cloud = sltk::sphereCloud(500);
  if (comm->rank() % 2 == 1)
  {
    std::reverse(cloud.Points.begin(), cloud.Points.end());
  }
  const sltk::PointCloud<3> before = cloud;
  EXPECT_FALSE(sltk::joinCloudPieces(cloud, *comm));
  EXPECT_EQ(cloud.Points, before.Points);
}

TEST(CloudPieces, PiecesJoinInRankOrderWithoutDuplicates)
{
  auto comm = world();
  const sltk::PointCloud<3> whole = sltk::sphereCloud(500);
  for (bool overlap : { false, true })
  {
    sltk::PointCloud<3> piece = blockOf(whole, comm->rank(), comm->size(), overlap);
    EXPECT_EQ(sltk::joinCloudPieces(piece, *comm), comm->size() > 1);
    EXPECT_EQ(piece.Points, whole.Points) << (overlap ? "overlapping pieces" : "disjoint pieces");
  }
  // Everything on rank 0, nothing elsewhere: rank 0's cloud, in its order.
  sltk::PointCloud<3> mine = comm->rank() == 0 ? whole : sltk::PointCloud<3>{};
  EXPECT_EQ(sltk::joinCloudPieces(mine, *comm), comm->size() > 1);
  EXPECT_EQ(mine.Points, whole.Points);
}

TEST(CloudPieces, ANonFiniteCoordinateStopsTheJoin)
{
  auto comm = world();
  sltk::PointCloud<3> piece = blockOf(sltk::sphereCloud(500), comm->rank(), comm->size(), false);
  if (comm->rank() == comm->size() - 1)
  {
    piece.Points[0][1] = std::numeric_limits<double>::quiet_NaN();
  }
  const size_t before = piece.Points.size();
  EXPECT_FALSE(sltk::joinCloudPieces(piece, *comm)) << "the validation refuses it, with no gather";
  EXPECT_EQ(piece.Points.size(), before);
}
