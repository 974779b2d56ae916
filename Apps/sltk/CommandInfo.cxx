// SPDX-License-Identifier: BSD-3-Clause
// `sltk info CLOUD`: validation, size, bounds, h_P and the run grids of (4.36),
// from the same plan (ReconstructionPlan.h) that `sltk reconstruct` runs.
#include "Commands.h"
#include "Json.h"
#include "ReadPointCloud.h"
#include "SLTKBridge.h"
#include "WriteAtomically.h"

#include "sltk/cloud/CloudSpacing.h"
#include "sltk/exec/Context.h"
#include "sltk/exec/Memory.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <chrono>
#include <cstdio>
#include <iostream>

namespace sltkcli
{

namespace
{
const char* infoUsage = R"(usage: sltk info CLOUD [options]

Reads a point cloud, checks it (empty, NaN/Inf, coincident, flat, huge offsets),
and prints its size, bounding box, resolution h_P (mean nearest-neighbour
distance of a 10% sample, thesis 4.5.2) and the grid of each reconstruction run,
dx = C_dx h_P / 2^(r-1) (4.36), with its memory estimate: the plan that
`sltk reconstruct` with the same options runs (clouds with no z extent in 2D).
Also prints the density spacing (r_16 sqrt(pi/16)): well below it, h_P suggests
merged, overlapping scans (see --thin).

options:
  --runs R        number of runs (default 3)
  --cdx C         C_dx of (4.36) (default 1, the thesis's)
  --kp K          K_P (default 2): run 1's grid holds the initial surface K_P h_P outside the cloud
  --initial NAME  outside | sphere | ellipsoid (default outside), as for sltk reconstruct
  --padding P     empty cells around the cloud per side (default 10)
  --remove-outliers, --outlier-sigma S, --thin F   as for sltk reconstruct
  --threads T     threads (default: all)
  --json FILE     also write the summary as JSON
)";

/// The plan's figures, printed and as JSON, for a cloud reconstructed in D dimensions.
template <int D>
int printPlan(const std::string& path, long long read, sltk::PointCloud<D> cloud,
  const sltk::ReconstructionOptions& options, const sltk::Context& ctx, const Options& opt,
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
  if (options.Cleaning.RemoveOutliers || options.Cleaning.ThinningFactor > 0.0)
  {
    std::printf("cleaned      %lld points (%lld outliers removed, thinning cell %.4g)\n",
      static_cast<long long>(plan.Cloud.size()), static_cast<long long>(plan.Cleaning.OutliersRemoved),
      plan.Cleaning.ThinningCell);
  }
  std::printf("bounds      ");
  const auto unitBounds = sltk::boundingBox(plan.Cloud);
  for (int a = 0; a < D; ++a)
  {
    std::printf("%s[%.6g, %.6g]", a ? " x " : " ", plan.Box.Centre[a] + plan.Box.Scale * unitBounds.Min[a],
      plan.Box.Centre[a] + plan.Box.Scale * unitBounds.Max[a]);
  }
  std::printf("\nh_P          %.6g   (C_dx = %g, K_P = %g, padding %d cells)\n", spacing, options.CellSizeFactor,
    options.OutsideThresholdFactor, options.Padding);
  std::printf("density      %.6g   (spacing from the 16-neighbour radius)\n", density);
  std::printf("\n run        dx                 grid            nodes    memory (est.)\n");
  std::vector<JsonObject> runs;
  for (int r = 1; r <= options.Runs; ++r)
  {
    const sltk::GridSpec<D> g = plan.userGrid(r);
    std::vector<long long> dims(3, 1);
    for (int a = 0; a < D; ++a)
    {
      dims[static_cast<size_t>(a)] = static_cast<long long>(g.Dims[a]);
    }
    std::printf("%4d  %10.4g  %5lld x %5lld x %5lld  %10.3g  %8.1f MB\n", r, g.Spacing[0], dims[0], dims[1], dims[2],
      static_cast<double>(g.nodeCount()), plan.memoryEstimate(r) / 1e6);
    runs.push_back(JsonObject().add("run", static_cast<long long>(r)).add("dx", g.Spacing[0]).add("grid", dims));
  }
  std::printf("\n%.3f s, peak memory %.1f MB\n", seconds, static_cast<double>(sltk::peakResidentBytes()) / 1e6);

  if (!opt.has("json"))
  {
    return 0;
  }
  JsonObject summary;
  summary.add("cloud", path)
    .add("points", read)
    .add("dimension", static_cast<long long>(D))
    .add("points_cleaned", static_cast<long long>(plan.Cloud.size()))
    .add("outliers_removed", static_cast<long long>(plan.Cleaning.OutliersRemoved))
    .add("h_P", spacing)
    .add("density_spacing", density)
    .add("seconds", seconds)
    .add("peak_memory_mb", static_cast<double>(sltk::peakResidentBytes()) / 1e6)
    .add("runs", runs);
  status = writeTextFile(opt.value("json"), summary.str() + "\n");
  return status.isOk() ? 0 : fail(status.message());
}
} // namespace

int commandInfo(const Args& args)
{
  Options opt(args, { "runs", "cdx", "kp", "initial", "padding", "threads", "json", "outlier-sigma", "thin" },
    { "help", "remove-outliers" });
  if (opt.has("help"))
  {
    std::cout << infoUsage;
    return 0;
  }
  sltk::ReconstructionOptions options;
  options.Runs = static_cast<int>(opt.number("runs", 3));
  options.CellSizeFactor = opt.number("cdx", 1.0);
  options.OutsideThresholdFactor = opt.number("kp", 2.0);
  options.Padding = static_cast<int>(opt.number("padding", 10));
  const int threads = static_cast<int>(opt.number("threads", 0));
  options.Cleaning.RemoveOutliers = opt.has("remove-outliers");
  options.Cleaning.Outliers.Deviations = opt.number("outlier-sigma", 3.0);
  options.Cleaning.ThinningFactor = opt.number("thin", 0.0);
  if (!opt.ok())
  {
    return fail(opt.error(), 2);
  }
  if (!parseInitialGuess(opt.value("initial", "outside"), options.Guess))
  {
    return fail("unknown initial guess '" + opt.value("initial") + "': use outside, sphere or ellipsoid", 2);
  }
  if (opt.positional().size() != 1)
  {
    return fail("give exactly one point cloud file (see sltk info --help)", 2);
  }
  const std::string path = opt.positional()[0];
  const auto start = std::chrono::steady_clock::now();

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
  sltk::ThreadPool pool(threads);
  sltk::Context ctx;
  ctx.Executor = &pool;
  const long long read = cloud.size();
  sltk::PointCloud<2> flat;
  double z = 0.0;
  return sltk::flattenIfPlanar(cloud, flat, z) ? printPlan<2>(path, read, std::move(flat), options, ctx, opt, start)
                                               : printPlan<3>(path, read, std::move(cloud), options, ctx, opt, start);
}

} // namespace sltkcli
