// SPDX-License-Identifier: BSD-3-Clause
#include "reconstruction/Synthetic.h"

#include "common/SdfErrors.h"
#include "reconstruction/Report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

namespace sltkbench
{
namespace
{
const double NaN = std::nan("");

} // namespace

template <int D>
void runSynthetic(const SyntheticCase<D>& c, const std::vector<std::string>& interps,
  const ReconstructionBenchOptions& args, const ThesisTables& thesis, const sltk::Context& ctx,
  const std::vector<sltk::RunParameters>& schedule)
{
  const int runs = args.Runs > 0 ? args.Runs : c.Runs;
  std::printf("\n=== %s: %lld points, %d runs, C_dx = %g, K_P = %g ===\n", c.Title.c_str(),
    static_cast<long long>(c.Cloud.size()), runs, std::isfinite(args.Cdx) ? args.Cdx : 1.0,
    std::isfinite(args.Kp) ? args.Kp : 2.0);
  if (std::isfinite(c.SurfaceEnergy))
  {
    std::printf("E_2 of the exact shape (4.1), fine quadrature: %.4e\n", c.SurfaceEnergy);
  }
  const auto thesisGrid = c.TableKey.empty() ? std::vector<std::string>{} : thesis.texts({ c.TableKey, "grid" });
  for (size_t r = 0; r < schedule.size(); ++r)
  {
    std::printf("run %zu%s: p = %g, eta = %g\n", r + 1, r + 1 == schedule.size() ? " and later" : "", schedule[r].P,
      schedule[r].Eta);
  }
  for (const std::string& name : interps)
  {
    sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
    std::string key;
    if (!selectInterpolator(name, options, key))
    {
      continue;
    }
    if (c.TableKey.empty())
    {
      key.clear(); // no thesis table for this case
    }
    options.Schedule = schedule; // empty: Table 4.1
    if (std::isfinite(args.Tolerance))
    {
      options.Tolerance = args.Tolerance;
    }
    if (std::isfinite(args.Cdx))
    {
      options.CellSizeFactor = args.Cdx;
    }
    if (std::isfinite(args.Kp))
    {
      options.OutsideThresholdFactor = args.Kp;
    }
    if (args.Padding >= 0)
    {
      options.Padding = args.Padding;
    }
    const std::vector<double> tl1 = key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, key, "l1" });
    const std::vector<double> ten = key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, key, "energy" });
    const std::vector<double> terr =
      key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, key, "err_cloud" });
    const std::vector<double> tit =
      key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, "iterations_runs_1_3", key });
    const std::vector<double> tsec =
      key.empty() ? std::vector<double>{} : thesis.numbers({ c.TableKey, "seconds_runs_1_3", key });

    // Runs = 1..R: run r of the R-run call is the last run of the r-run call
    // (checked below on grid, iterations and Err_P). --final-only: the R-run call
    // alone, L1 of the last run only.
    std::vector<std::pair<double, double>> l1(static_cast<size_t>(runs), { NaN, NaN });
    std::vector<sltk::RunRecord<D>> last(static_cast<size_t>(runs));
    sltk::ReconstructionResult<D> full;
    double fullSeconds = 0.0;
    bool failed = false;
    for (int r = args.FinalOnly ? runs : 1; r <= runs && !failed; ++r)
    {
      options.Runs = r;
      sltk::ReconstructionResult<D> res;
      const auto t0 = std::chrono::steady_clock::now();
      const sltk::Status s = sltk::reconstruct(c.Cloud, options, ctx, res);
      const double wall = seconds(t0);
      if (!s.isOk())
      {
        std::printf("%s: reconstruction with %d runs failed: %s\n", name.c_str(), r, s.message().c_str());
        failed = true;
        break;
      }
      const auto& phi = res.SignedDistance;
      l1[static_cast<size_t>(r - 1)] = l1Errors<D>(
        phi.spec(), [&phi](const std::array<sltk::Index, D>& i) { return phi(i); }, c.Exact,
        options.GammaFactor * phi.spec().Spacing[0]);
      last[static_cast<size_t>(r - 1)] = res.Runs.back();
      if (r == runs)
      {
        full = std::move(res);
        fullSeconds = wall;
      }
    }
    if (failed)
    {
      continue;
    }
    if (args.FinalOnly)
    {
      std::copy(full.Runs.begin(), full.Runs.end(), last.begin());
    }
    std::printf("\n--- %s (h_P = %.4g) ---\n", name.c_str(), full.CloudSpacing);
    std::printf("%-2s %-12s %-12s %5s %5s | %-9s %-9s %-9s %-14s | %-9s %-9s %-14s | %-9s %-9s %-14s | %8s\n", "r",
      "grid", "thesis grid", "iter", "th.it", "L1(cut)", "L1(band)", "thesis", "ratio 1.5?", "E_2", "thesis",
      "ratio 1.5?", "Err_P", "thesis", "ratio 1.5?", "seconds");
    bool consistent = true;
    for (int r = 0; r < runs; ++r)
    {
      const auto& run = full.Runs[static_cast<size_t>(r)];
      const auto& alone = last[static_cast<size_t>(r)];
      consistent = consistent && gridText<D>(alone.Grid) == gridText<D>(run.Grid) &&
        alone.Iterations == run.Iterations && alone.CloudError == run.CloudError;
      const size_t i = static_cast<size_t>(r);
      const double tIt = at(tit, i);
      std::printf("%-2d %-12s %-12s %5d %5s | %s %s %s %s | %s %s %s | %s %s %s | %8.3f\n", r + 1,
        gridText<D>(run.Grid).c_str(), at(thesisGrid, i).c_str(), run.Iterations,
        std::isfinite(tIt) ? std::to_string(static_cast<int>(tIt)).c_str() : "-", sci(l1[i].first).c_str(),
        sci(l1[i].second).c_str(), sci(at(tl1, i)).c_str(), compare(l1[i].first, at(tl1, i), false).c_str(),
        sci(run.Energy).c_str(), sci(at(ten, i)).c_str(), compare(run.Energy, at(ten, i), true).c_str(),
        sci(run.CloudError).c_str(), sci(at(terr, i)).c_str(), compare(run.CloudError, at(terr, i), false).c_str(),
        run.Seconds);
    }
    double first3 = 0.0;
    for (int r = 0; r < std::min(runs, 3); ++r)
    {
      first3 += full.Runs[static_cast<size_t>(r)].Seconds;
    }
    std::printf("wall %.3f s for %d runs (runs 1-3: %.3f s; thesis runs 1-3: %s s)%s\n", fullSeconds, runs, first3,
      tsec.empty() ? "-" : sci(tsec[0]).c_str(),
      consistent ? "" : "  NOTE: run r of the full call differs from the r-run call");
  }
}

template void runSynthetic<2>(const SyntheticCase<2>&, const std::vector<std::string>&,
  const ReconstructionBenchOptions&, const ThesisTables&, const sltk::Context&,
  const std::vector<sltk::RunParameters>&);
template void runSynthetic<3>(const SyntheticCase<3>&, const std::vector<std::string>&,
  const ReconstructionBenchOptions&, const ThesisTables&, const sltk::Context&,
  const std::vector<sltk::RunParameters>&);

} // namespace sltkbench
