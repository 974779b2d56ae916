// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/Context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cmath>
#include <vector>

TEST(ThreadPool, SizeCountsCallingThread)
{
  sltk::ThreadPool one(1);
  EXPECT_EQ(one.size(), 1);
  sltk::ThreadPool three(3);
  EXPECT_EQ(three.size(), 3);
  sltk::ThreadPool automatic(0);
  EXPECT_GE(automatic.size(), 1);
}

TEST(ThreadPool, ParallelForVisitsEveryIndexOnce)
{
  sltk::ThreadPool pool(4);
  for (sltk::Index n : { 0, 1, 7, 1000, 100003 })
  {
    std::vector<std::atomic<int>> hits(static_cast<size_t>(n));
    pool.parallelFor(0, n, [&](sltk::Index b, sltk::Index e) {
      for (sltk::Index i = b; i < e; ++i)
      {
        hits[static_cast<size_t>(i)]++;
      }
    });
    for (sltk::Index i = 0; i < n; ++i)
    {
      ASSERT_EQ(hits[static_cast<size_t>(i)].load(), 1) << "n = " << n << ", i = " << i;
    }
  }
}

TEST(ThreadPool, ChunksDoNotDependOnThreadCount)
{
  EXPECT_EQ(sltk::ThreadPool::chunkCount(0, 1000, 10), 100);
  EXPECT_EQ(sltk::ThreadPool::chunkCount(5, 5, 10), 0);
  EXPECT_EQ(sltk::ThreadPool::chunkCount(0, 10000, 0), 64);
}

TEST(ThreadPool, SumIsBitIdenticalSerialAndThreaded)
{
  auto body = [](sltk::Index b, sltk::Index e) {
    double s = 0.0;
    for (sltk::Index i = b; i < e; ++i)
    {
      s += std::sin(0.001 * static_cast<double>(i)) / (1.0 + static_cast<double>(i));
    }
    return s;
  };
  sltk::ThreadPool serial(1);
  sltk::ThreadPool threaded(4);
  const double a = serial.parallelSum(0, 1000000, body);
  const double b = threaded.parallelSum(0, 1000000, body);
  EXPECT_EQ(a, b); // exact equality on purpose
  for (int repeat = 0; repeat < 20; ++repeat)
  {
    ASSERT_EQ(threaded.parallelSum(0, 1000000, body), a);
  }
}

TEST(ThreadPool, ReusableManyTimes)
{
  sltk::ThreadPool pool(2);
  std::atomic<long> total{ 0 };
  for (int k = 0; k < 2000; ++k)
  {
    pool.parallelFor(0, 100, [&](sltk::Index b, sltk::Index e) { total += e - b; }, 7);
  }
  EXPECT_EQ(total.load(), 200000);
}

TEST(Context, DefaultRunsSeriallyAndSilently)
{
  sltk::Context ctx;
  EXPECT_FALSE(ctx.interrupter().wasInterrupted(0.5));
  ctx.logger().log(sltk::LogLevel::Info, "dropped");
  std::vector<int> v(100, 0);
  ctx.parallelFor(0, 100, [&](sltk::Index b, sltk::Index e) {
    for (sltk::Index i = b; i < e; ++i)
    {
      v[static_cast<size_t>(i)] = static_cast<int>(i);
    }
  });
  for (int i = 0; i < 100; ++i)
  {
    EXPECT_EQ(v[static_cast<size_t>(i)], i);
  }
  EXPECT_DOUBLE_EQ(ctx.parallelSum(0, 10, [](sltk::Index b, sltk::Index e) { return double(e - b); }), 10.0);
}

TEST(Context, InjectedInterrupterIsUsed)
{
  struct StopAtHalf : sltk::Interrupter
  {
    bool wasInterrupted(double f) override { return f >= 0.5; }
  } stop;
  sltk::Context ctx;
  ctx.Progress = &stop;
  EXPECT_FALSE(ctx.interrupter().wasInterrupted(0.25));
  EXPECT_TRUE(ctx.interrupter().wasInterrupted(0.5));
}

// The one thread rule of every front end (ThreadPool.h): an explicit count
// wins; else the cores shared among the ranks on this machine, capped by
// VTK_SMP_MAX_THREADS. Each test runs in its own process (gtest_discover_tests).
TEST(ThreadPool, ThreadsPerRankShareTheCoresAndHonourTheCap)
{
  ::unsetenv("VTK_SMP_MAX_THREADS");
  ::unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  ::unsetenv("MPI_LOCALNRANKS");
  const int cores = sltk::threadsPerRank(0, 1);
  EXPECT_GE(cores, 1);
  EXPECT_EQ(sltk::threadsPerRank(3, 2), 3);
  EXPECT_EQ(sltk::threadsPerRank(0, 2), std::max(1, cores / 2)); // no launcher's count: both ranks here
  ::setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "1", 1);                 // the other rank on another machine
  EXPECT_EQ(sltk::threadsPerRank(0, 2), cores);
  ::setenv("VTK_SMP_MAX_THREADS", "1", 1);
  EXPECT_EQ(sltk::threadsPerRank(0, 1), 1);
  EXPECT_EQ(sltk::ThreadPool(0).size(), 1);
  EXPECT_EQ(sltk::threadsPerRank(4, 1), 4); // the explicit property is not capped
  ::setenv("VTK_SMP_MAX_THREADS", "0", 1);  // VTK's "no cap"
  EXPECT_EQ(sltk::threadsPerRank(0, 1), cores);
}
