// SPDX-License-Identifier: BSD-3-Clause
// main() of the GoogleTest programs that run serially and under `mpiexec -n N`
// (Mpi/, P4est/): MPI around the tests, results printed by rank 0, the
// failures of the other ranks printed by them (with their rank), and the exit
// code is 1 on every rank when a test failed on any rank.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdio>

namespace
{
/// The failed assertions of a rank other than 0, which prints no summary.
class RankFailurePrinter : public ::testing::EmptyTestEventListener
{
public:
  explicit RankFailurePrinter(int rank)
    : Rank(rank)
  {
  }
  void OnTestPartResult(const ::testing::TestPartResult& result) override
  {
    if (result.failed())
    {
      std::fprintf(stderr, "rank %d: %s:%d: failure\n%s\n", this->Rank, result.file_name() ? result.file_name() : "",
        result.line_number(), result.message());
    }
  }

private:
  int Rank;
};
} // namespace

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
    listeners.Append(new RankFailurePrinter(rank));
  }
  int failed = RUN_ALL_TESTS();
  int anyFailed = 0;
  MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return anyFailed;
}
