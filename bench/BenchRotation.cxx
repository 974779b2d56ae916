// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchRotation.cxx
/// Thesis Test 1 (3.5.1): rigid rotation of the C2 bump, one revolution, RK3
/// feet, dt = 3 dx, with the linear SL step (2.36) and the WENO3, CWENO and
/// CWENOZ interpolators (and Q1 for reference). Prints
///  - Table 3.1: L1 errors and orders, ours beside the thesis's;
///  - Table 3.2: run times and the % gain of CWENO(Z) over WENO, ours beside
///    the thesis's (Galileo100 cluster: compare ratios, not seconds).
///
/// Usage: sltkBenchRotation [--max-n N] [--threads T]
///   --max-n   largest grid of the table to run (default 641; 1281 takes minutes)
///   --threads executor size (default 1: the CPU time of one core)

#include "common/BenchCli.h"

#include "sltk/hjb/InitialData.h"
#include "sltk/interp/Cweno.h"
#include "sltk/interp/Q1.h"
#include "sltk/interp/Weno3.h"
#include "sltk/sl/LinearSLStep.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{
// Thesis Table 3.1 (L1 errors of Test 1) and Table 3.2 (its CPU seconds on
// the Galileo100 cluster).
const sltk::Index ThesisN[] = { 21, 41, 81, 161, 321, 641, 1281 };
const double ThesisErr[3][7] = { { 2.97e-3, 5.46e-4, 1.24e-4, 2.34e-5, 3.92e-6, 6.11e-7, 8.87e-8 },
  { 2.98e-3, 4.88e-4, 8.18e-5, 1.22e-5, 1.72e-6, 2.27e-7, 2.92e-8 },
  { 2.98e-3, 4.84e-4, 7.85e-5, 1.12e-5, 1.49e-6, 1.79e-7, 2.06e-8 } };
const double ThesisCpu[3][7] = { { 1.05, 1.10, 7.84, 61.9, 486.0, 3870.0, 30900.0 },
  { 0.722, 1.06, 5.42, 43.6, 338.0, 2700.0, 21200.0 }, { 0.101, 0.720, 5.46, 43.7, 336.0, 2670.0, 21200.0 } };
const char* const Names[4] = { "WENO", "CWENO", "CWENOZ", "Q1" };

/// v_t - f_D . grad v = 0, f_D = (-2 pi (y - 0.5), 2 pi (x - 0.5)): PDE velocity f = -f_D.
/// A function object, so that the kernel inlines it (a plain function would be called indirectly).
struct Rotation
{
  std::array<double, 2> operator()(double, const std::array<double, 2>& x) const
  {
    const double twoPi = 6.283185307179586;
    return { twoPi * (x[1] - 0.5), -twoPi * (x[0] - 0.5) };
  }
};

struct Result
{
  double Error = 0.0;
  double Seconds = 0.0;
};

template <class Interp>
Result runTest1(sltk::Index n, const sltk::Context& ctx)
{
  sltk::GridSpec<2> g;
  for (int a = 0; a < 2; ++a)
  {
    g.Dims[a] = n;
    g.Origin[a] = 0.0;
    g.Spacing[a] = 1.0 / double(n - 1);
    g.Bounds[a] = sltk::Boundary::Extrapolate;
  }
  sltk::GridField<2> u(g, 2);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    const auto x = sltk::nodePoint(g, i);
    u(i) = sltk::rotatingBump(x[0], x[1]);
  }
  sltk::LinearSLOptions opt;
  opt.Order = sltk::RkOrder::Kutta3;
  opt.FinalTime = 1.0;
  opt.MaxTimeStep = 3.0 * g.Spacing[0];
  const auto start = std::chrono::steady_clock::now();
  const sltk::Status status = sltk::linearSLAdvance<Interp>(ctx, opt, u, Rotation{});
  Result r;
  r.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!status.isOk())
  {
    std::fprintf(stderr, "N = %lld: %s\n", static_cast<long long>(n), status.toString().c_str());
    std::exit(1);
  }
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    const auto x = sltk::nodePoint(g, i);
    r.Error += std::fabs(u(i) - sltk::rotatingBump(x[0], x[1]));
  }
  r.Error *= g.Spacing[0] * g.Spacing[1];
  return r;
}

double order(const std::vector<Result>& r, size_t l)
{
  return std::log(r[l - 1].Error / r[l].Error) / std::log(double(ThesisN[l] - 1) / double(ThesisN[l - 1] - 1));
}
} // namespace

int main(int argc, char** argv)
{
  long long maxN = 641;
  int threads = 1;
  CLI::App app(
    "Thesis Test 1 (3.5.1) with the linear SL step; see the header of bench/BenchRotation.cxx", "sltkBenchRotation");
  sltkbench::takeLastByDefault(app);
  app.add_option("--max-n", maxN, "largest grid of the table to run (1281 takes minutes)")->capture_default_str();
  app.add_option("--threads", threads, "executor size")->capture_default_str();
  if (const auto exit = sltkbench::parseCommandLine(app, argc, argv))
  {
    return *exit;
  }
  sltk::ThreadPool pool(threads);
  sltk::Context ctx;
  ctx.Executor = &pool;

  size_t levels = 0;
  while (levels < 7 && ThesisN[levels] <= maxN)
  {
    ++levels;
  }
  std::vector<Result> res[4];
  for (size_t l = 0; l < levels; ++l)
  {
    const sltk::Index n = ThesisN[l];
    res[0].push_back(runTest1<sltk::Weno3Interpolator<2>>(n, ctx));
    res[1].push_back(runTest1<sltk::CwenoInterpolator<2, sltk::CwenoVariant::Cweno>>(n, ctx));
    res[2].push_back(runTest1<sltk::CwenoInterpolator<2, sltk::CwenoVariant::CwenoZ>>(n, ctx));
    res[3].push_back(runTest1<sltk::Q1Interpolator<2>>(n, ctx));
    std::fprintf(stderr, "N = %lld done\n", static_cast<long long>(n));
  }

  std::printf("Table 3.1, Test 1 (rotation, RK3 feet, dt = 3 dx, T = 1): L1 error / order, ours | thesis\n");
  std::printf("%6s", "N");
  for (int m = 0; m < 3; ++m)
  {
    std::printf(" | %-8s %9s %5s %9s %5s", Names[m], "ours", "ord", "thesis", "ord");
  }
  std::printf(" | %-3s %9s %5s\n", "Q1", "ours", "ord");
  for (size_t l = 0; l < levels; ++l)
  {
    std::printf("%6lld", static_cast<long long>(ThesisN[l]));
    // Orders of the first row print as "-".
    char ours[4][8], thesis[3][8];
    for (int m = 0; m < 4; ++m)
    {
      std::snprintf(ours[m], sizeof(ours[m]), l ? "%5.2f" : "    -", l ? order(res[m], l) : 0.0);
    }
    for (int m = 0; m < 3; ++m)
    {
      const double thesisOrder = l == 0 ? 0.0
                                        : std::log(ThesisErr[m][l - 1] / ThesisErr[m][l]) /
          std::log(double(ThesisN[l] - 1) / double(ThesisN[l - 1] - 1));
      std::snprintf(thesis[m], sizeof(thesis[m]), l ? "%5.2f" : "    -", thesisOrder);
      std::printf(" | %-8s %9.2e %s %9.2e %s", "", res[m][l].Error, ours[m], ThesisErr[m][l], thesis[m]);
    }
    std::printf(" | %-3s %9.2e %s\n", "", res[3][l].Error, ours[3]);
  }

  std::printf("\nTable 3.2, Test 1 run times in seconds (%d thread%s here; thesis: Galileo100) and %% gain over WENO\n",
    threads, threads == 1 ? "" : "s");
  std::printf("%6s | %9s %9s %6s %9s %6s | %9s %9s %6s %9s %6s | %9s\n", "N", "WENO", "CWENO", "gain", "CWENOZ", "gain",
    "thesis W", "thesis C", "gain", "thesis CZ", "gain", "Q1");
  for (size_t l = 0; l < levels; ++l)
  {
    const double w = res[0][l].Seconds, c = res[1][l].Seconds, z = res[2][l].Seconds;
    const double tw = ThesisCpu[0][l], tc = ThesisCpu[1][l], tz = ThesisCpu[2][l];
    std::printf("%6lld | %9.3e %9.3e %6.1f %9.3e %6.1f | %9.2e %9.2e %6.1f %9.2e %6.1f | %9.3e\n",
      static_cast<long long>(ThesisN[l]), w, c, 100.0 * (w - c) / w, z, 100.0 * (w - z) / w, tw, tc,
      100.0 * (tw - tc) / tw, tz, 100.0 * (tw - tz) / tw, res[3][l].Seconds);
  }
  return 0;
}
