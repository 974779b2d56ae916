// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchTiled.cxx
/// The tiled reconstruction (tiled/TiledReconstruction.h) against the uniform
/// one on the same plan: iterations and Err_P per run, wall time, stored
/// nodes against the uniform grid, and this process's peak memory. Run each
/// storage in its own process (--storage) under /usr/bin/time -v so that the
/// peaks do not mix: bench/tiled/compare.sh does that side by side.
///
/// Usage: sltkBenchTiled --cloud FILE.xyz [--storage uniform|tiled] [--cdx C] [--kp K] [--runs R] [--threads N]

#include "common/BenchCli.h"
#include "common/ReadXyz.h"

#include "sltk/exec/Memory.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/recon/ReconstructionPlan.h"
#include "sltk/tiled/TiledReconstruction.h"

#include <chrono>
#include <cstdio>

int main(int argc, char** argv)
{
  CLI::App app("Tiled against uniform reconstruction: Err_P, time, stored nodes, peak memory");
  sltkbench::takeLastByDefault(app);
  std::string cloudPath, storage = "tiled";
  double cdx = 0.0, kp = 0.0;
  int runs = 3, threads = 0;
  app.add_option("--cloud", cloudPath, "x y z text cloud")->required();
  app.add_option("--storage", storage, "uniform or tiled")->check(CLI::IsMember({ "uniform", "tiled" }));
  app.add_option("--cdx", cdx, "C_dx (0: automatic)")->capture_default_str();
  app.add_option("--kp", kp, "K_P (0: automatic)")->capture_default_str();
  app.add_option("--runs", runs, "runs")->capture_default_str();
  app.add_option("--threads", threads, "threads (0: all hardware threads)")->capture_default_str();
  if (const auto code = sltkbench::parseCommandLine(app, argc, argv))
  {
    return *code;
  }
  sltk::PointCloud<3> cloud;
  if (!sltkbench::readXyz(cloudPath, cloud))
  {
    std::fprintf(stderr, "cannot read a cloud from %s\n", cloudPath.c_str());
    return 1;
  }
  sltk::ThreadPool pool(threads);
  sltk::Context ctx;
  ctx.Executor = &pool;
  sltk::ReconstructionOptions options;
  options.CellSizeFactor = cdx;
  options.OutsideThresholdFactor = kp;
  options.Runs = runs;
  const auto start = std::chrono::steady_clock::now();
  sltk::ReconstructionPlan<3> plan;
  sltk::Status status = sltk::planReconstruction(cloud, options, ctx, plan);
  sltk::ReconstructionResult<3> uniform;
  sltk::TiledReconstructionResult<3> tiled;
  if (status.isOk())
  {
    status = storage == "tiled" ? sltk::reconstructTiled(plan, ctx, tiled) : sltk::reconstruct(plan, ctx, uniform);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!status.isOk())
  {
    std::fprintf(stderr, "%s\n", status.toString().c_str());
    return 1;
  }
  const auto& records = storage == "tiled" ? tiled.Records : uniform;
  // stored: at the end of the run; most: the most held at once during its iterations.
  std::printf("%-8s %4s %6s %12s %12s %8s %12s %8s %14s\n", "storage", "run", "iters", "Err_P", "stored", "%", "most",
    "%", "uniform");
  for (size_t r = 0; r < records.Runs.size(); ++r)
  {
    const auto& run = records.Runs[r];
    const double nodes = static_cast<double>(run.Grid.nodeCount());
    const bool tiledRun = storage == "tiled" && r > 0 && r - 1 < tiled.Storage.size();
    const double stored = tiledRun ? static_cast<double>(tiled.Storage[r - 1].StoredNodes) : nodes;
    const double most =
      tiledRun ? static_cast<double>(tiled.Storage[r - 1].PeakTiles) * sltk::TiledField<3>::Nodes : nodes;
    std::printf("%-8s %4zu %6d %12.4e %12.0f %8.2f %12.0f %8.2f %14.0f\n", storage.c_str(), r + 1, run.Iterations,
      run.CloudError, stored, 100.0 * stored / nodes, most, 100.0 * most / nodes, nodes);
  }
  std::printf("%-8s C_dx %.3g K_P %.3g wall %.2f s peak %.0f MB\n", storage.c_str(), plan.Options.CellSizeFactor,
    plan.Options.OutsideThresholdFactor, seconds, static_cast<double>(sltk::peakResidentBytes()) / 1048576.0);
  return 0;
}
