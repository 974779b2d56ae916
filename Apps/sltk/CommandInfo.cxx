// SPDX-License-Identifier: BSD-3-Clause
// `sltk info CLOUD`: validation, size, bounds, h_P and the run grids of (4.36),
// from the same plan (ReconstructionPlan.h) that `sltk reconstruct` runs.
#include "CliOptions.h"
#include "Commands.h"
#include "OutputPaths.h"
#include "ReadPointCloud.h"
#include "SLTKBridge.h"
#include "WriteAtomically.h"

#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/LocalFrame.h"
#include "sltk/exec/Context.h"
#include "sltk/exec/Memory.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

namespace sltkcli
{

namespace
{
const char* infoDescription = R"(validate a point cloud and print its size, bounds, spacing h_P and the grid
of every run of the reconstruction (thesis (4.36))

Reads a point cloud, checks it (empty, NaN/Inf, coincident, flat, huge offsets),
and prints its size, bounding box, resolution h_P (mean nearest-neighbour
distance of a 10% sample, thesis 4.5.2) and the grid of each reconstruction run,
dx = C_dx h_P / 2^(r-1) (4.36), with its memory estimate: the plan that
`sltk reconstruct` with the same options runs (clouds with no z extent in 2D).
With --octree, the plan of `sltk reconstruct --octree`: runs 2..R store only the
tiles near the surface, whose nodes are estimated from the cloud.
Also prints the density spacing (r_16 sqrt(pi/16)): well below it, h_P suggests
merged, overlapping scans (see --thin).
)";

/// The plan's figures, printed and as JSON, for a cloud reconstructed in D dimensions.
template <int D>
int printPlan(const std::string& path, long long read, sltk::PointCloud<D> cloud,
  const sltk::ReconstructionOptions& options, const sltk::Context& ctx, const std::string* json,
  std::chrono::steady_clock::time_point start)
{
  sltk::ReconstructionPlan<D> plan;
  sltk::Status status = sltk::planReconstruction(std::move(cloud), options, ctx, plan);
  double density = 0.0;
  sltk::CloudSpacingOptions densityOptions;
  densityOptions.DensityNeighbours = options.Cleaning.DensityNeighbours;
  if (status.isOk() && plan.Cloud.size() > densityOptions.DensityNeighbours)
  {
    status = sltk::cloudSpacing(*plan.Locator, ctx, density, densityOptions);
    density *= plan.Box.Scale;
  }
  if (!status.isOk())
  {
    return fail(path + ": " +
      withMergedScanHint(status.message(), static_cast<size_t>(read), options.Cleaning.ThinningFactor > 0));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double spacing = plan.userCloudSpacing();
  std::printf("cloud        %s\n", path.c_str());
  std::printf("points       %lld%s\n", read, D == 2 ? "   (no z extent: reconstructed in 2D)" : "");
  if (plan.Cleaning.OutliersRemoved > 0 || plan.Cleaning.ThinningCell > 0.0)
  {
    std::printf("cleaned      %lld points (%lld outliers removed, thinning cell %.4g)\n",
      static_cast<long long>(plan.Cloud.size()), static_cast<long long>(plan.Cleaning.OutliersRemoved),
      plan.Cleaning.ThinningCell);
  }
  std::printf("bounds      ");
  const auto unitBounds = sltk::boundingBox(plan.Cloud);
  for (int a = 0; a < D; ++a)
  {
    // Survey coordinates keep their detail (LocalFrame.h, positionDigits).
    const double low = plan.Box.Centre[a] + plan.Box.Scale * unitBounds.Min[a];
    const double high = plan.Box.Centre[a] + plan.Box.Scale * unitBounds.Max[a];
    const int digits = sltk::positionDigits(std::max(std::fabs(low), std::fabs(high)), 2.0 * plan.Box.Scale);
    std::printf("%s[%.*g, %.*g]", a ? " x " : " ", digits, low, digits, high);
  }
  std::printf("\nh_P          %.6g   (C_dx = %.3g, K_P = %g, padding %d cells)\n", spacing, plan.Options.CellSizeFactor,
    plan.Options.OutsideThresholdFactor, options.Padding);
  for (const std::string& choice : plan.Choices)
  {
    std::printf("automatic    %s\n", choice.c_str());
  }
  std::printf("density      %.6g   (spacing from the 16-neighbour radius)\n", density);
  const bool tiled = plan.Options.OctreeStorage;
  std::printf(tiled ? "\n run        dx                 grid            nodes    stored (est.)    memory (est.)\n"
                    : "\n run        dx                 grid            nodes    memory (est.)\n");
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (int r = 1; r <= plan.Options.Runs; ++r)
  {
    const sltk::GridSpec<D> g = plan.userGrid(r);
    std::vector<long long> dims(3, 1);
    for (int a = 0; a < D; ++a)
    {
      dims[static_cast<size_t>(a)] = static_cast<long long>(g.Dims[a]);
    }
    const double stored = sltk::storedNodesEstimate(plan, r), bytes = sltk::storageMemoryEstimate(plan, r);
    std::printf("%4d  %10.4g  %5lld x %5lld x %5lld  %10.3g", r, g.Spacing[0], dims[0], dims[1], dims[2],
      static_cast<double>(g.nodeCount()));
    if (tiled)
    {
      std::printf("  %10.3g (%4.1f%%)", stored, 100.0 * stored / static_cast<double>(g.nodeCount()));
    }
    std::printf("  %8.1f MB\n", bytes / 1e6);
    nlohmann::ordered_json run = { { "run", r }, { "dx", g.Spacing[0] }, { "grid", dims },
      { "nodes", static_cast<long long>(g.nodeCount()) }, { "memory_mb", bytes / 1e6 } };
    if (tiled)
    {
      run["stored_nodes_estimate"] = static_cast<long long>(std::llround(stored));
    }
    runs.push_back(run);
  }
  std::printf("\n%.3f s, peak memory %.1f MB\n", seconds, static_cast<double>(sltk::peakResidentBytes()) / 1e6);

  if (!json)
  {
    return 0;
  }
  const nlohmann::ordered_json summary = { { "cloud", path }, { "points", read }, { "dimension", D },
    { "points_cleaned", static_cast<long long>(plan.Cloud.size()) },
    { "outliers_removed", static_cast<long long>(plan.Cleaning.OutliersRemoved) }, { "h_P", spacing },
    { "density_spacing", density }, { "cdx", plan.Options.CellSizeFactor },
    { "kp", plan.Options.OutsideThresholdFactor }, { "automatic_choices", plan.Choices }, { "seconds", seconds },
    { "peak_memory_mb", static_cast<double>(sltk::peakResidentBytes()) / 1e6 }, { "runs", runs } };
  status = writeJsonFile(*json, summary);
  return status.isOk() ? 0 : fail(status.message());
}

/// `sltk info`'s command line.
struct Info
{
  CLI::App* Parser = nullptr;
  std::string Cloud;
  sltk::ReconstructionOptions Options;
  int Threads = 0;
  std::string Json;
  bool Octree = false; ///< plan the octree storage (sltk reconstruct --octree)
  int run() const;
};

int Info::run() const
{
  const std::string& path = this->Cloud;
  const std::string paths = outputPathsProblem({ { "input cloud", path } }, { { "--json", this->Json, { "json" } } });
  if (!paths.empty())
  {
    return fail(paths, 2);
  }
  const auto start = std::chrono::steady_clock::now();
  sltk::ReconstructionOptions options = this->Options;
  options.OctreeStorage = this->Octree;
  vtkSmartPointer<vtkPointSet> input;
  sltk::Status status = readPointCloud(path, input); // (its messages name the file)
  if (!status.isOk())
  {
    return fail(status.message());
  }
  sltk::PointCloud<3> cloud;
  status = sltk::vtkbridge::toCloud(input, cloud);
  if (!status.isOk())
  {
    return fail(path + ": " + status.message());
  }
  input = nullptr;
  sltk::ThreadPool pool(this->Threads);
  sltk::Context ctx;
  ctx.Executor = &pool;
  const long long read = cloud.size();
  sltk::PointCloud<2> flat;
  double z = 0.0;
  const std::string* json = this->Parser->count("--json") ? &this->Json : nullptr;
  return sltk::flattenIfPlanar(cloud, flat, z) ? printPlan<2>(path, read, std::move(flat), options, ctx, json, start)
                                               : printPlan<3>(path, read, std::move(cloud), options, ctx, json, start);
}
} // namespace

Command addInfoCommand(CLI::App& sltk)
{
  auto info = std::make_shared<Info>();
  CLI::App* app = addCloudCommand(sltk, "info", infoDescription, info->Cloud);
  info->Parser = app;
  addPlanOptions(app, info->Options);
  addThreadsOption(app, info->Threads);
  app->add_option("--json", info->Json, "also write the summary as JSON")->option_text("FILE");
  app->add_flag("--octree", info->Octree,
    "the plan of sltk reconstruct --octree: runs 2..R store only the tiles\nnear the surface (their nodes estimated "
    "from the cloud), the memory checked\nagainst them");
  return { app, [info] { return info->run(); } };
}

} // namespace sltkcli
