// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchTiled.cxx
/// The tiled reconstruction (octree/TiledReconstruction.h) against the uniform
/// one on the same plan: iterations and Err_P per run, wall time, stored
/// nodes against the uniform grid, and this process's peak memory. Run each
/// storage in its own process (--storage) under /usr/bin/time -v so that the
/// peaks do not mix: bench/tiled/compare.sh does that side by side.
///
/// Usage: sltkBenchTiled --cloud FILE.xyz [--storage uniform|tiled] [--cdx C] [--kp K] [--runs R] [--threads N]
///                       [--slabs P,P,...] (tiled: how the last run's tiles would split over P ranks)

#include "common/BenchCli.h"
#include "common/ReadXyz.h"

#include "sltk/core/MortonKey.h"
#include "sltk/exec/Memory.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/octree/TiledReconstruction.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace
{
/// What distributing the last run's tiles over `ranks` slabs of slot rows
/// (the last axis) would cost (Documentation/Octree.md, "Distributing the
/// tiled band: slabs or a Morton partition"): the cuts
/// balance the stored tiles, each rank keeps one slot row beyond each inner
/// cut (8 node rows, at least the 6 ghost rows the stencils need), and an
/// exchange sends the tiles of the owned slot row next to each cut (phi only,
/// 8 bytes a node). Prints the largest rank's share of the tiles, ghost rows
/// included, and the most any rank sends per exchange.
void slabProfile(const sltk::TiledField<3>& field, int ranks)
{
  const auto& dims = field.slotDims();
  std::vector<double> rowTiles(static_cast<size_t>(dims[2]), 0.0);
  for (sltk::Index s = 0; s < field.slotCount(); ++s)
  {
    rowTiles[static_cast<size_t>(field.slotCoordinates(s)[2])] += field.slot(s) >= 0 ? 1.0 : 0.0;
  }
  const double total = static_cast<double>(field.tileCount());
  if (ranks > dims[2] || total <= 0.0)
  {
    std::printf("slabs %4d: not possible (%lld slot rows)\n", ranks, static_cast<long long>(dims[2]));
    return;
  }
  // Cuts where the tiles below reach r / ranks of all, at least one row a rank.
  std::vector<sltk::Index> cut(static_cast<size_t>(ranks) + 1, dims[2]);
  cut[0] = 0;
  double below = 0.0;
  sltk::Index row = 0;
  for (int r = 1; r < ranks; ++r)
  {
    while (row < dims[2] - (ranks - r) &&
      (below + rowTiles[static_cast<size_t>(row)] <= total * r / ranks || row < cut[static_cast<size_t>(r) - 1] + 1))
    {
      below += rowTiles[static_cast<size_t>(row++)];
    }
    cut[static_cast<size_t>(r)] = row;
  }
  double largest = 0.0, sent = 0.0;
  for (int r = 0; r < ranks; ++r)
  {
    const sltk::Index first = std::max<sltk::Index>(0, cut[static_cast<size_t>(r)] - 1);
    const sltk::Index stop = std::min(dims[2], cut[static_cast<size_t>(r) + 1] + 1);
    double held = 0.0, sends = 0.0;
    for (sltk::Index k = first; k < stop; ++k)
    {
      held += rowTiles[static_cast<size_t>(k)];
    }
    if (r > 0)
    {
      sends += rowTiles[static_cast<size_t>(cut[static_cast<size_t>(r)])];
    }
    if (r + 1 < ranks)
    {
      sends += rowTiles[static_cast<size_t>(cut[static_cast<size_t>(r) + 1] - 1)];
    }
    largest = std::max(largest, held);
    sent = std::max(sent, sends);
  }
  std::printf("slabs %4d: largest rank %.1f%% of the %.0f tiles (ghost rows included), sends at most %.0f tiles "
              "(%.2f MB) per exchange\n",
    ranks, 100.0 * largest / total, total, sent, sent * sltk::TiledField<3>::Nodes * 8.0 / 1e6);
}
/// The same tiles partitioned as p4est partitions leaves: in Morton order of
/// their tile coordinates, equal counts a rank; each rank also holds the
/// tiles of other ranks next to its own (26 neighbours: one tile, 8 nodes,
/// of ghosts) and receives them at every exchange.
void mortonProfile(const sltk::TiledField<3>& field, int ranks)
{
  const sltk::Index tiles = field.tileCount();
  std::vector<std::pair<std::uint64_t, std::int32_t>> order;
  for (std::int32_t id = 0; id < static_cast<std::int32_t>(tiles); ++id)
  {
    order.emplace_back(sltk::mortonKey<3>(field.tileOrigin(id)), id);
  }
  std::sort(order.begin(), order.end());
  std::vector<int> owner(static_cast<size_t>(tiles));
  for (size_t k = 0; k < order.size(); ++k)
  {
    owner[static_cast<size_t>(order[k].second)] = static_cast<int>(k * static_cast<size_t>(ranks) / order.size());
  }
  std::vector<int> ghostOf(static_cast<size_t>(tiles), -1); // the last rank that counted the tile as its ghost
  std::vector<double> held(static_cast<size_t>(ranks), 0.0), received(static_cast<size_t>(ranks), 0.0);
  const auto& dims = field.slotDims();
  for (size_t k = 0; k < order.size(); ++k) // ranks in order: each rank's tiles are contiguous here
  {
    const std::int32_t id = order[k].second;
    const int r = owner[static_cast<size_t>(id)];
    held[static_cast<size_t>(r)] += 1.0;
    const auto& t = field.tileOrigin(id);
    for (int n = 0; n < 27; ++n)
    {
      std::array<sltk::Index, 3> u{ t[0] + n % 3 - 1, t[1] + n / 3 % 3 - 1, t[2] + n / 9 - 1 };
      if (u[0] < 0 || u[1] < 0 || u[2] < 0 || u[0] >= dims[0] || u[1] >= dims[1] || u[2] >= dims[2])
      {
        continue;
      }
      const std::int32_t other = field.slot(field.slotIndex(u));
      if (other >= 0 && owner[static_cast<size_t>(other)] != r && ghostOf[static_cast<size_t>(other)] != r)
      {
        ghostOf[static_cast<size_t>(other)] = r;
        held[static_cast<size_t>(r)] += 1.0;
        received[static_cast<size_t>(r)] += 1.0;
      }
    }
  }
  const double largest = *std::max_element(held.begin(), held.end());
  const double most = *std::max_element(received.begin(), received.end());
  std::printf("morton %4d: largest rank %.1f%% of the %lld tiles (ghosts included), receives at most %.0f tiles "
              "(%.2f MB) per exchange\n",
    ranks, 100.0 * largest / static_cast<double>(tiles), static_cast<long long>(tiles), most,
    most * sltk::TiledField<3>::Nodes * 8.0 / 1e6);
}
} // namespace

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
  std::string slabs;
  app.add_option(
    "--slabs", slabs, "tiled: rank counts (comma-separated) to cut the last run's tiles for: balance, exchange size");
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
  if (!slabs.empty() && storage != "tiled")
  {
    std::fprintf(stderr, "--slabs splits the tiles of a tiled run: ignored with --storage %s\n", storage.c_str());
  }
  for (const std::string& ranks : sltkbench::splitList(slabs))
  {
    if (storage == "tiled")
    {
      slabProfile(tiled.Field, std::max(1, std::atoi(ranks.c_str())));
      mortonProfile(tiled.Field, std::max(1, std::atoi(ranks.c_str())));
    }
  }
  std::printf("%-8s C_dx %.3g K_P %.3g wall %.2f s peak %.0f MB\n", storage.c_str(), plan.Options.CellSizeFactor,
    plan.Options.OutsideThresholdFactor, seconds, static_cast<double>(sltk::peakResidentBytes()) / 1048576.0);
  return 0;
}
