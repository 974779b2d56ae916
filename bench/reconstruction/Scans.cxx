// SPDX-License-Identifier: BSD-3-Clause
#include "reconstruction/Scans.h"

#include "common/ReadXyz.h"
#include "reconstruction/Report.h"

#include "sltk/exec/Memory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace sltkbench
{
namespace
{
const double NaN = std::nan("");
} // namespace

void runScan(const ScanCase& c, const std::vector<std::string>& interps, const ReconstructionBenchOptions& args,
  const ThesisTables& thesis, const sltk::Context& ctx)
{
  sltk::PointCloud<3> cloud;
  if (!readXyz(args.Data + "/" + c.File, cloud))
  {
    std::printf("\n=== %s: cannot read %s/%s, skipped ===\n", c.Name.c_str(), args.Data.c_str(), c.File.c_str());
    return;
  }
  const sltk::Box<3> box = sltk::boundingBox(cloud);
  double scale = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    scale = std::max(scale, 0.5 * box.extent(a));
  }
  const double cdx = std::isfinite(args.Cdx) ? args.Cdx : c.Cdx;
  const double kp = std::isfinite(args.Kp) ? args.Kp : c.Kp;
  const int runs = args.Runs > 0 ? args.Runs : 3;
  std::printf("\n=== %s: %s, %lld points, unit-box scale %.6g, C_dx = %g, K_P = %g, guess %s, %d runs %s===\n",
    c.Name.c_str(), c.File.c_str(), static_cast<long long>(cloud.size()), scale, cdx, kp,
    c.Guess == sltk::InitialGuess::OutsideMarking ? "outside marking" : "bounding ellipsoid", runs, c.Note.c_str());
  const auto thesisGrid = thesis.texts({ "table_4_8_grids", c.GridKey });
  const auto thesisMinutes = thesis.numbers({ "table_4_9_minutes", c.GridKey });
  for (const std::string& name : interps)
  {
    sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
    std::string key;
    if (!selectInterpolator(name, options, key))
    {
      continue;
    }
    options.Runs = runs;
    options.CellSizeFactor = cdx;
    options.OutsideThresholdFactor = kp;
    options.Guess = c.Guess;
    options.MaxIterations = c.MaxIterations;
    const bool table = !c.TableKey.empty() && !key.empty();
    const std::vector<double> ten = table ? thesis.numbers({ c.TableKey, key, "energy" }) : std::vector<double>{};
    const std::vector<double> terr = table ? thesis.numbers({ c.TableKey, key, "err_cloud" }) : std::vector<double>{};
    sltk::ReconstructionResult<3> res;
    const auto t0 = std::chrono::steady_clock::now();
    const sltk::Status s = sltk::reconstruct(cloud, options, ctx, res);
    const double wall = seconds(t0);
    std::printf("\n--- %s (h_P = %.4g user, %.4g unit box)%s ---\n", name.c_str(), res.CloudSpacing,
      res.CloudSpacing / scale, s.isOk() ? "" : (" FAILED: " + s.message()).c_str());
    std::printf("%-2s %-12s %-12s %5s | %-9s %-9s %-14s | %-9s %-9s %-14s | %8s %9s %10s\n", "r", "grid", "thesis grid",
      "iter", "E_2 unit", "thesis", "ratio 1.5?", "Err_P unit", "thesis", "ratio 1.5?", "seconds", "s/iter",
      "mean band");
    const double energyScale = std::pow(scale, 2.0); // E_2 ~ length^((2 + d - 1) / 2), d = 3
    for (size_t r = 0; r < res.Runs.size(); ++r)
    {
      const auto& run = res.Runs[r];
      const double e = run.Energy / energyScale;
      const double err = run.CloudError / scale;
      std::printf("%-2zu %-12s %-12s %5d | %s %s %s | %s %s %s | %8.2f %9.4f %10lld\n", r + 1,
        gridText<3>(run.Grid).c_str(), at(thesisGrid, r).c_str(), run.Iterations, sci(e).c_str(),
        sci(at(ten, r)).c_str(), compare(e, at(ten, r), true).c_str(), sci(err).c_str(), sci(at(terr, r)).c_str(),
        compare(err, at(terr, r), false).c_str(), run.Seconds, run.Iterations ? run.Seconds / run.Iterations : 0.0,
        static_cast<long long>(run.MeanBandSize));
    }
    const double tmin = key == "Q1" ? at(thesisMinutes, 1) : (key == "WENO" ? at(thesisMinutes, 2) : NaN);
    std::printf("wall %.2f s; peak RSS of the process so far %.1f MiB; thesis %s min on %s MPI ranks\n", wall,
      static_cast<double>(sltk::peakResidentBytes()) / (1024.0 * 1024.0), sci(tmin).c_str(),
      std::isfinite(at(thesisMinutes, 0)) ? std::to_string(static_cast<int>(at(thesisMinutes, 0))).c_str() : "-");
  }
}

} // namespace sltkbench
