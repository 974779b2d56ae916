// SPDX-License-Identifier: BSD-3-Clause
// `sltk info CLOUD`: validation, size, bounds, h_P and the run grids of (4.36).
#include "Commands.h"
#include "Json.h"
#include "ReadPointCloud.h"
#include "WriteAtomically.h"

#include "sltk/exec/Context.h"
#include "sltk/exec/Memory.h"
#include "sltk/cloud/CloudCleaning.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/recon/GridPlan.h"

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
dx = C_dx h_P / 2^(r-1) (4.36), with its memory estimate. Also prints the density
spacing (r_16 sqrt(pi/16)): well below it, h_P suggests merged, overlapping scans
(see --thin). With the cleaning options, all of it is for the cleaned cloud, as
`sltk reconstruct` with the same options would use it.

options:
  --runs R        number of runs (default 3)
  --cdx C         C_dx of (4.36) (default 1, the thesis's)
  --padding P     empty cells around the cloud per side (default 10)
  --remove-outliers, --outlier-sigma S, --thin F   as for sltk reconstruct
  --threads T     threads (default: all)
  --json FILE     also write the summary as JSON
)";
} // namespace

int commandInfo(const Args& args)
{
  Options opt(args, { "runs", "cdx", "padding", "threads", "json", "outlier-sigma", "thin" },
    { "help", "remove-outliers" });
  if (opt.has("help"))
  {
    std::cout << infoUsage;
    return 0;
  }
  sltk::GridPlanOptions plan;
  plan.Runs = static_cast<int>(opt.number("runs", 3));
  plan.CellSizeFactor = opt.number("cdx", 1.0);
  plan.Padding = static_cast<int>(opt.number("padding", 10));
  const int threads = static_cast<int>(opt.number("threads", 0));
  sltk::CloudCleaningOptions cleaning;
  cleaning.RemoveOutliers = opt.has("remove-outliers");
  cleaning.Outliers.Deviations = opt.number("outlier-sigma", 3.0);
  cleaning.ThinningFactor = opt.number("thin", 0.0);
  if (!opt.ok())
  {
    return fail(opt.error(), 2);
  }
  if (opt.positional().size() != 1)
  {
    return fail("give exactly one point cloud file (see sltk info --help)", 2);
  }
  const std::string path = opt.positional()[0];
  const auto start = std::chrono::steady_clock::now();

  sltk::PointCloud<3> cloud;
  sltk::Status status = readPointCloud(path, cloud);
  if (status.isOk())
  {
    status = sltk::validateCloud(cloud);
  }
  if (!status.isOk())
  {
    return fail(path + ": " + status.message());
  }
  sltk::ThreadPool pool(threads);
  sltk::Context ctx;
  ctx.Executor = &pool;
  const std::int64_t read = cloud.size();
  sltk::CloudCleaningReport cleaned;
  status = sltk::cleanCloud(cloud, cleaning, ctx, cloud, cleaned);
  if (status.isOk())
  {
    status = sltk::validateCloud(cloud);
  }
  double spacing = 0.0, density = 0.0;
  sltk::CloudSpacingOptions densityOptions;
  densityOptions.DensityNeighbours = cleaning.DensityNeighbours;
  if (status.isOk())
  {
    status = sltk::cloudSpacing(cloud, ctx, spacing);
  }
  if (status.isOk() && cloud.size() > densityOptions.DensityNeighbours)
  {
    status = sltk::cloudSpacing(cloud, ctx, density, densityOptions);
  }
  const auto box = sltk::boundingBox(cloud);
  sltk::GridPlan<3> grids;
  if (status.isOk())
  {
    status = sltk::planGrids(box, spacing, plan, grids);
  }
  if (!status.isOk())
  {
    return fail(path + ": " + withMergedScanHint(status.message(), read, cleaning.ThinningFactor > 0));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::printf("cloud        %s\n", path.c_str());
  std::printf("points       %lld\n", static_cast<long long>(read));
  if (cleaning.RemoveOutliers || cleaning.ThinningFactor > 0.0)
  {
    std::printf("cleaned      %lld points (%lld outliers removed, thinning cell %.4g)\n",
      static_cast<long long>(cloud.size()), static_cast<long long>(cleaned.OutliersRemoved), cleaned.ThinningCell);
  }
  std::printf("bounds       [%.6g, %.6g] x [%.6g, %.6g] x [%.6g, %.6g]\n", box.Min[0], box.Max[0], box.Min[1],
    box.Max[1], box.Min[2], box.Max[2]);
  std::printf("h_P          %.6g   (C_dx = %g, padding %d cells)\n", spacing, plan.CellSizeFactor, plan.Padding);
  std::printf("density      %.6g   (spacing from the 16-neighbour radius)\n", density);
  std::printf("\n run        dx          grid            nodes    memory (est.)\n");
  std::vector<JsonObject> runs;
  for (size_t r = 0; r < grids.Runs.size(); ++r)
  {
    const auto& g = grids.Runs[r];
    const double nodes = static_cast<double>(g.nodeCount());
    std::printf("%4zu  %10.4g  %5lld x %5lld x %5lld  %10.3g  %8.1f MB\n", r + 1, g.Spacing[0],
      static_cast<long long>(g.Dims[0]), static_cast<long long>(g.Dims[1]), static_cast<long long>(g.Dims[2]),
      nodes, nodes * plan.BytesPerNode / 1e6);
    runs.push_back(JsonObject()
                     .add("run", static_cast<long long>(r + 1))
                     .add("dx", g.Spacing[0])
                     .add("grid", std::vector<long long>{ g.Dims[0], g.Dims[1], g.Dims[2] }));
  }
  std::printf("\n%.3f s, peak memory %.1f MB\n", seconds, static_cast<double>(sltk::peakResidentBytes()) / 1e6);

  if (opt.has("json"))
  {
    JsonObject summary;
    summary.add("cloud", path)
      .add("points", static_cast<long long>(read))
      .add("points_cleaned", static_cast<long long>(cloud.size()))
      .add("outliers_removed", static_cast<long long>(cleaned.OutliersRemoved))
      .add("h_P", spacing)
      .add("density_spacing", density)
      .add("seconds", seconds)
      .add("peak_memory_mb", static_cast<double>(sltk::peakResidentBytes()) / 1e6)
      .add("runs", runs);
    status = writeTextFile(opt.value("json"), summary.str() + "\n");
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  return 0;
}

} // namespace sltkcli
