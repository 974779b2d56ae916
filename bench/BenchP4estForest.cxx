// SPDX-License-Identifier: GPL-2.0-or-later
// The p4est forest over a cloud (P4est/include/sltk/p4est/CloudForest.h),
// thesis 5.1-5.2: leaves against the uniform grid of the same finest level
// (Fig. 5.7, 5.14), build time per phase, peak memory, and a checksum of the
// leaves and their distances that must be the same on any number of ranks.
// Run under mpirun to compare ranks:
//   sltkBenchP4estForest --cloud bunny.xyz --levels 6,7,8
//   mpirun -np 2 sltkBenchP4estForest --cloud bunny.xyz --levels 6,7,8
// Rank 0 reads the cloud; the other ranks start with no points.
#include "common/BenchCli.h"
#include "common/ReadXyz.h"

#include "sltk/exec/Memory.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/mpi/MpiCommunicator.h"
#include "sltk/p4est/CloudForest.h"

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstring>

namespace
{
/// An order-independent checksum of the leaves (index, level, coordinates,
/// distance bits), summed over the ranks in two 32-bit halves.
std::uint64_t checksum(const sltk::p4est::CloudForest& forest, const sltk::Communicator& comm)
{
  std::int64_t halves[2] = { 0, 0 };
  for (const auto& leaf : forest.leaves())
  {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &leaf.Distance, sizeof(bits));
    std::uint64_t h = static_cast<std::uint64_t>(leaf.GlobalIndex) * 0x9E3779B97F4A7C15ull;
    for (std::uint64_t v : { std::uint64_t(leaf.Tree), std::uint64_t(leaf.Level), std::uint64_t(leaf.Coords[0]),
           std::uint64_t(leaf.Coords[1]), std::uint64_t(leaf.Coords[2]), bits })
    {
      h = (h ^ v) * 0x100000001B3ull;
      h ^= h >> 29;
    }
    halves[0] += static_cast<std::int64_t>(h & 0xffffffffu);
    halves[1] += static_cast<std::int64_t>(h >> 32);
  }
  comm.allReduce(halves, 2, sltk::ReduceOp::Sum);
  return static_cast<std::uint64_t>(halves[0]) + (static_cast<std::uint64_t>(halves[1]) << 32);
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  CLI::App app("p4est forest over a cloud: leaves vs the uniform grid, build time, rank invariance");
  sltkbench::takeLastByDefault(app);
  std::string cloudPath, levels = "6,7,8";
  int minLevel = 2, threads = 1;
  app.add_option("--cloud", cloudPath, "x y z text cloud (read by rank 0)")->required();
  app.add_option("--levels", levels, "maximum levels L, comma-separated")->capture_default_str();
  app.add_option("--min-level", minLevel, "minimum level")->capture_default_str();
  app.add_option("--threads", threads, "threads per rank (0: all hardware threads)")->capture_default_str();
  if (const auto code = sltkbench::parseCommandLine(app, argc, argv))
  {
    MPI_Finalize();
    return *code;
  }
  std::unique_ptr<sltk::mpi::MpiCommunicator> comm;
  sltk::Status status = sltk::mpi::MpiCommunicator::world(comm);
  sltk::PointCloud<3> cloud;
  if (status.isOk() && comm->rank() == 0 && !sltkbench::readXyz(cloudPath, cloud))
  {
    status = sltk::Status::ioError("cannot read a cloud from " + cloudPath);
  }
  status = comm ? comm->agree(status) : status;
  if (!status.isOk())
  {
    std::fprintf(stderr, "%s\n", status.toString().c_str());
    MPI_Finalize();
    return 1;
  }
  if (comm->rank() == 0)
  {
    std::printf("%-5s %5s %8s %6s %12s %12s %14s %8s %8s %8s %8s %8s %8s %9s %18s\n", "L", "ranks", "points", "trees",
      "leaves", "finest", "uniform", "%unif", "prep_s", "refine_s", "bal_s", "dist_s", "ghost_s", "peak_MB",
      "checksum");
  }
  sltk::ThreadPool pool(threads);
  sltk::Context ctx;
  ctx.Executor = &pool;
  for (const std::string& item : sltkbench::splitList(levels))
  {
    sltk::p4est::CloudForestOptions options;
    options.MinimumLevel = minLevel;
    options.MaximumLevel = std::stoi(item);
    std::unique_ptr<sltk::p4est::CloudForest> forest;
    comm->barrier();
    status = sltk::p4est::CloudForest::build(*comm, cloud, options, ctx, forest);
    if (!status.isOk())
    {
      if (comm->rank() == 0)
      {
        std::printf("L = %s: %s\n", item.c_str(), status.toString().c_str());
      }
      continue;
    }
    const auto& s = forest->stats();
    const double peak =
      comm->allReduce(static_cast<double>(sltk::peakResidentBytes()) / 1048576.0, sltk::ReduceOp::Max);
    double times[5] = { s.PrepareSeconds, s.RefineSeconds, s.BalanceSeconds, s.DistanceSeconds, s.GhostSeconds };
    comm->allReduce(times, 5, sltk::ReduceOp::Max);
    const std::uint64_t sum = checksum(*forest, *comm);
    if (comm->rank() == 0)
    {
      std::printf("%-5d %5d %8lld %6d %12lld %12lld %14.0f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %9.0f %018llx\n",
        options.MaximumLevel, comm->size(), static_cast<long long>(s.CloudPoints), forest->brick().treeCount(),
        static_cast<long long>(s.GlobalLeaves), static_cast<long long>(s.LeavesAtMaximumLevel), s.UniformCells,
        100.0 * static_cast<double>(s.GlobalLeaves) / s.UniformCells, times[0], times[1], times[2], times[3], times[4],
        peak, static_cast<unsigned long long>(sum));
    }
  }
  comm.reset();
  MPI_Finalize();
  return 0;
}
