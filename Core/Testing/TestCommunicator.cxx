// SPDX-License-Identifier: BSD-3-Clause
// The serial communicator (exec/Communicator.h): one rank, every collective
// is the identity or a copy, and the status agreement returns the rank's own
// status unchanged. The MPI implementation is tested on 1 and 2 ranks in
// Mpi/Testing/TestMpiCommunicator.cxx.
#include "sltk/exec/Communicator.h"

#include <gtest/gtest.h>

using sltk::ReduceOp;

TEST(Communicator, SerialIsOneRank)
{
  const sltk::Communicator& comm = sltk::serialCommunicator();
  EXPECT_EQ(comm.rank(), 0);
  EXPECT_EQ(comm.size(), 1);
  EXPECT_EQ(comm.nativeHandle(), nullptr);
  comm.barrier();
}

TEST(Communicator, SerialReductionsKeepValues)
{
  const sltk::Communicator& comm = sltk::serialCommunicator();
  std::vector<double> d = { 1.5, -2.0, 7.25 };
  for (ReduceOp op : { ReduceOp::Sum, ReduceOp::Min, ReduceOp::Max })
  {
    comm.allReduce(d.data(), d.size(), op);
    EXPECT_EQ(d, (std::vector<double>{ 1.5, -2.0, 7.25 }));
  }
  std::vector<std::int64_t> i = { 3, -(std::int64_t(1) << 40) };
  comm.allReduce(i.data(), i.size(), ReduceOp::Sum);
  EXPECT_EQ(i[1], -(std::int64_t(1) << 40));
  EXPECT_EQ(comm.allReduce(4.5, ReduceOp::Max), 4.5);
  EXPECT_EQ(comm.allReduce(std::int64_t(9), ReduceOp::Min), 9);
}

TEST(Communicator, SerialGathersCopy)
{
  const sltk::Communicator& comm = sltk::serialCommunicator();
  const double x[2] = { 1.0, 2.0 };
  double out[2] = { 0.0, 0.0 };
  comm.allGather(x, sizeof(x), out);
  EXPECT_EQ(out[1], 2.0);
  std::vector<std::int64_t> counts;
  const std::vector<float> v = { 1.f, 2.f, 3.f };
  EXPECT_EQ(comm.allGatherV(v, &counts), v);
  EXPECT_EQ(counts, (std::vector<std::int64_t>{ 3 }));
  EXPECT_TRUE(comm.allGatherV(std::vector<int>{}, &counts).empty());
  EXPECT_EQ(counts, (std::vector<std::int64_t>{ 0 }));
}

TEST(Communicator, SerialAgreementReturnsTheRankStatus)
{
  const sltk::Communicator& comm = sltk::serialCommunicator();
  EXPECT_TRUE(comm.agree(sltk::Status::ok()).isOk());
  const sltk::Status s = comm.agree(sltk::Status::invalidArgument("cloud has NaN at point 3"));
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_EQ(s.message(), "cloud has NaN at point 3");
}

TEST(Communicator, NewSerialCommunicatorIsOneRank)
{
  const std::unique_ptr<sltk::Communicator> comm = sltk::newSerialCommunicator();
  EXPECT_EQ(comm->size(), 1);
  EXPECT_EQ(comm->agree(sltk::Status::ioError("disk full")).message(), "disk full");
}
