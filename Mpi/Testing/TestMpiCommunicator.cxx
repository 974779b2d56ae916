// SPDX-License-Identifier: BSD-3-Clause
// The MPI communicator (sltk/mpi/MpiCommunicator.h), serially and under
// `mpiexec -n 2` (ctest label mpi); also right on 4 ranks. The agreement tests
// make one rank fail and check that every rank returns the same error and
// then meets the others in the next collective (a hang would hit the ctest timeout).
#include "sltk/exec/CountingCommunicator.h"
#include "sltk/mpi/MpiCommunicator.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <numeric>

using sltk::ReduceOp;
using sltk::mpi::MpiCommunicator;

namespace
{
std::unique_ptr<MpiCommunicator> world()
{
  std::unique_ptr<MpiCommunicator> comm;
  EXPECT_TRUE(MpiCommunicator::world(comm).isOk());
  return comm;
}
} // namespace

TEST(MpiCommunicator, WorldMatchesMpi)
{
  auto comm = world();
  int rank = -1, size = -1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  EXPECT_EQ(comm->rank(), rank);
  EXPECT_EQ(comm->size(), size);
  ASSERT_NE(comm->nativeHandle(), nullptr);
  int compared = MPI_UNEQUAL;
  MPI_Comm_compare(*static_cast<MPI_Comm*>(comm->nativeHandle()), MPI_COMM_WORLD, &compared);
  EXPECT_EQ(compared, MPI_IDENT);
  comm->barrier();
}

TEST(MpiCommunicator, RejectsNullHandles)
{
  std::unique_ptr<MpiCommunicator> comm;
  EXPECT_EQ(MpiCommunicator::fromHandle(nullptr, comm).code(), sltk::StatusCode::InvalidArgument);
  MPI_Comm null = MPI_COMM_NULL;
  EXPECT_EQ(MpiCommunicator::fromHandle(&null, comm).code(), sltk::StatusCode::InvalidArgument);
  EXPECT_EQ(comm, nullptr);
  EXPECT_TRUE(sltk::mpi::isMpiActive());
  EXPECT_TRUE(sltk::mpi::ensureMpiInitialised().isOk()) << "already initialised: nothing to do";
}

TEST(MpiCommunicator, ReducesDoublesAndIntegers)
{
  auto comm = world();
  const int r = comm->rank(), n = comm->size();
  std::vector<double> d = { 1.0 + r, -0.5 * r, 2.0 * r };
  std::vector<double> dmin = d, dmax = d;
  comm->allReduce(d.data(), d.size(), ReduceOp::Sum);
  comm->allReduce(dmin.data(), dmin.size(), ReduceOp::Min);
  comm->allReduce(dmax.data(), dmax.size(), ReduceOp::Max);
  const double ranksSum = 0.5 * n * (n - 1);
  EXPECT_DOUBLE_EQ(d[0], n + ranksSum);
  EXPECT_DOUBLE_EQ(d[1], -0.5 * ranksSum);
  EXPECT_EQ(dmin[1], -0.5 * (n - 1));
  EXPECT_EQ(dmax[2], 2.0 * (n - 1));
  EXPECT_EQ(dmin[0], 1.0);
  const std::int64_t big = std::int64_t(1) << 40;
  std::vector<std::int64_t> i = { big + r, -r };
  comm->allReduce(i.data(), i.size(), ReduceOp::Sum);
  EXPECT_EQ(i[0], n * big + static_cast<std::int64_t>(ranksSum));
  EXPECT_EQ(comm->allReduce(std::int64_t(r), ReduceOp::Max), n - 1);
  EXPECT_EQ(comm->allReduce(double(r), ReduceOp::Min), 0.0);
}

TEST(MpiCommunicator, BroadcastsFromAnyRoot)
{
  auto comm = world();
  const int root = comm->size() - 1;
  double v[2] = { -1.0, -1.0 };
  if (comm->rank() == root)
  {
    v[0] = 3.25;
    v[1] = 1e300;
  }
  comm->broadcast(v, sizeof(v), root);
  EXPECT_EQ(v[0], 3.25);
  EXPECT_EQ(v[1], 1e300);
}

TEST(MpiCommunicator, GathersFixedAndVariableCounts)
{
  auto comm = world();
  const int r = comm->rank(), n = comm->size();
  const std::int64_t mine[2] = { r, 10 * r };
  std::vector<std::int64_t> all(static_cast<size_t>(2 * n));
  comm->allGather(mine, sizeof(mine), all.data());
  for (int k = 0; k < n; ++k)
  {
    EXPECT_EQ(all[static_cast<size_t>(2 * k)], k);
    EXPECT_EQ(all[static_cast<size_t>(2 * k + 1)], 10 * k);
  }
  // Rank k sends k elements (rank 0 none): the concatenation in rank order.
  std::vector<double> local(static_cast<size_t>(r));
  std::iota(local.begin(), local.end(), 100.0 * r);
  std::vector<std::int64_t> counts;
  const std::vector<double> gathered = comm->allGatherV(local, &counts);
  ASSERT_EQ(counts.size(), static_cast<size_t>(n));
  std::vector<double> expected;
  for (int k = 0; k < n; ++k)
  {
    EXPECT_EQ(counts[static_cast<size_t>(k)], k);
    for (int j = 0; j < k; ++j)
    {
      expected.push_back(100.0 * k + j);
    }
  }
  EXPECT_EQ(gathered, expected);
}

TEST(MpiCommunicator, SendsPersonalisedCountsToEveryRank)
{
  auto comm = world();
  const int r = comm->rank(), n = comm->size();
  // Rank r sends r + k bytes to rank k (rank 0 sends none to itself), each byte 16 r + k.
  std::vector<std::int64_t> sendCounts;
  std::vector<unsigned char> send;
  for (int k = 0; k < n; ++k)
  {
    sendCounts.push_back(r + k);
    send.insert(send.end(), static_cast<size_t>(r + k), static_cast<unsigned char>(16 * r + k));
  }
  std::vector<unsigned char> received;
  std::vector<std::int64_t> receiveCounts;
  comm->allToAllV(send.data(), sendCounts, received, receiveCounts);
  ASSERT_EQ(receiveCounts.size(), static_cast<size_t>(n));
  std::vector<unsigned char> expected;
  for (int k = 0; k < n; ++k)
  {
    EXPECT_EQ(receiveCounts[static_cast<size_t>(k)], k + r);
    expected.insert(expected.end(), static_cast<size_t>(k + r), static_cast<unsigned char>(16 * k + r));
  }
  EXPECT_EQ(received, expected);
}

TEST(MpiCommunicator, ExchangesWithNeighboursOnly)
{
  auto comm = world();
  const int r = comm->rank(), n = comm->size();
  // A ring: 100 + r bytes (each r) to the next rank, an empty message to the one before (when
  // distinct); the matching receives.
  const int next = (r + 1) % n, before = (r + n - 1) % n;
  std::vector<unsigned char> send(static_cast<size_t>(100 + r), static_cast<unsigned char>(r));
  std::vector<unsigned char> fromBefore(static_cast<size_t>(100 + before), 255);
  std::vector<sltk::Communicator::Outgoing> out = { { next, send.data(), send.size() } };
  std::vector<sltk::Communicator::Incoming> in = { { before, fromBefore.data(), fromBefore.size() } };
  unsigned char nothing = 0;
  if (n > 2)
  {
    out.push_back({ before, &nothing, 0 });
    in.push_back({ next, &nothing, 0 });
  }
  EXPECT_TRUE(comm->neighbourExchange(out, in));
  EXPECT_EQ(
    fromBefore, std::vector<unsigned char>(static_cast<size_t>(100 + before), static_cast<unsigned char>(before)));
}

TEST(MpiCommunicator, CountsEachRanksTrafficByKind)
{
  auto comm = world();
  const sltk::CountingCommunicator counted(*comm);
  const int r = counted.rank(), n = counted.size();
  const std::int64_t others = n - 1;
  EXPECT_EQ(comm->traffic().Collectives, 0) << "an uncounted communicator reports zeros";
  double sums[3] = { 1.0, 2.0, 3.0 };
  counted.allReduce(sums, 3, ReduceOp::Sum); // 24 bytes to each other rank
  const sltk::CommTraffic afterReduce = counted.traffic();
  std::vector<char> mine(static_cast<size_t>(10 + r), 'x');
  counted.allGatherV(mine); // 10 + r bytes to each other rank
  int value = r;
  counted.broadcast(&value, sizeof value, 0); // the root's 4 bytes to each other rank
  std::vector<std::int64_t> sendCounts(static_cast<size_t>(n), 5);
  std::vector<unsigned char> send(static_cast<size_t>(5 * n), 1), received;
  std::vector<std::int64_t> receiveCounts;
  counted.allToAllV(send.data(), sendCounts, received, receiveCounts); // 5 bytes point to point to each other rank
  const sltk::CommTraffic t = counted.traffic();
  EXPECT_EQ(t.Collectives, 4);
  EXPECT_EQ(t.CollectiveBytes, (24 + 10 + r + (r == 0 ? 4 : 0)) * others);
  EXPECT_EQ(t.PointToPointBytes, 5 * others);
  const sltk::CommTraffic since = t.since(afterReduce);
  EXPECT_EQ(since.Collectives, 3);
  EXPECT_EQ(since.CollectiveBytes, (10 + r + (r == 0 ? 4 : 0)) * others);
  EXPECT_EQ(counted.bytesSent(), t.PointToPointBytes);
}

TEST(MpiCommunicator, AgreementOkWhenEveryRankIsOk)
{
  auto comm = world();
  EXPECT_TRUE(comm->agree(sltk::Status::ok()).isOk());
}

TEST(MpiCommunicator, OneFailingRankEndsEveryRankWithItsError)
{
  auto comm = world();
  const int failing = comm->size() - 1;
  const sltk::Status local = comm->rank() == failing
    ? sltk::Status::outOfMemory("the forest needs 9 GB, 2 GB available: lower MaximumLevel")
    : sltk::Status::ok();
  const sltk::Status agreed = comm->agree(local);
  EXPECT_EQ(agreed.code(), sltk::StatusCode::OutOfMemory);
  const std::string message = "the forest needs 9 GB, 2 GB available: lower MaximumLevel";
  if (comm->size() == 1)
  {
    EXPECT_EQ(agreed.message(), message);
  }
  else
  {
    EXPECT_EQ(
      agreed.message(), "rank " + std::to_string(failing) + " of " + std::to_string(comm->size()) + ": " + message);
  }
  comm->barrier(); // every rank reaches the next collective
}

TEST(MpiCommunicator, SeveralFailingRanksGiveTheLowestRanksError)
{
  auto comm = world();
  const sltk::Status local =
    sltk::Status::invalidArgument("point " + std::to_string(comm->rank()) + " is NaN: remove it");
  const sltk::Status agreed = comm->agree(local);
  EXPECT_EQ(agreed.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_NE(agreed.message().find("point 0 is NaN"), std::string::npos) << agreed.message();
  // An empty message travels too.
  const sltk::Status empty = comm->agree(comm->rank() == 0 ? sltk::Status::aborted("") : sltk::Status::ok());
  EXPECT_EQ(empty.code(), sltk::StatusCode::Aborted);
}

TEST(MpiCommunicator, SelfIsOneRank)
{
  std::unique_ptr<MpiCommunicator> self;
  ASSERT_TRUE(MpiCommunicator::self(self).isOk());
  EXPECT_EQ(self->size(), 1);
  EXPECT_EQ(self->rank(), 0);
  const sltk::Status s = self->agree(sltk::Status::invalidArgument("x"));
  EXPECT_EQ(s.message(), "x");
}
