// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchRotation.cxx
/// Thesis Test 1 (3.5.1): rigid rotation of the C2 bump, one revolution, RK3
/// feet, dt = 3 dx, with the linear SL step (2.36) and every interpolator of
/// the registry (sltk/interp/InterpolatorKind.h: Q1, WENO3, CWENO, CWENOZ) on
/// the grids N = 21, 41, ..., 1281 of the thesis. Prints
///  - Table 3.1: L1 errors and orders, ours beside the thesis's;
///  - Table 3.2: run times and the % gain over WENO3, ours beside the thesis's
///    (Galileo100 cluster: compare the gains, not the seconds).
/// The thesis's numbers are read from a JSON transcription of its tables
/// (--tables; bench/common/ThesisTables.h); without the file, or for Q1 (not in
/// the thesis's chapter 3), the thesis columns print '-'.
///
/// Usage: sltkBenchRotation [--max-n N] [--threads T] [--tables PATH]
///   --max-n   largest grid of the table to run (default 641; 1281 takes minutes)
///   --threads executor size (default 1: the CPU time of one core)
///   --tables  path of thesis_tables.json (default /work/shared/reference/thesis_tables.json)

#include "common/BenchCli.h"
#include "common/ThesisNames.h"
#include "common/ThesisTables.h"

#include "sltk/hjb/InitialData.h"
#include "sltk/interp/Interpolators.h"
#include "sltk/sl/LinearSLStep.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
using sltkbench::formatValue;

constexpr int KindCount = static_cast<int>(sltk::HjbInterpolators.size());
constexpr auto Weno3 = static_cast<size_t>(sltk::InterpolatorKind::Weno3);
const char* const ErrTable = "table_3_1_test1_errors";
const char* const CpuTable = "table_3_2_test1_cpu_s";

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

/// The grids of Tables 3.1-3.2: N = 20 2^l + 1 nodes per side, up to maxN.
std::vector<sltk::Index> gridSizes(long long maxN)
{
  std::vector<sltk::Index> ns;
  for (sltk::Index n = 21; n <= maxN; n = 2 * n - 1)
  {
    ns.push_back(n);
  }
  return ns;
}

/// A table of a row per grid and a block per interpolator of the registry,
/// headed by its label and `columns`; block(l, kind) is the text of the block
/// of kind in row l.
template <class Block>
void printTable(const std::vector<sltk::Index>& ns, const char* columns, Block&& block)
{
  std::printf("%6s", "N");
  for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
  {
    std::printf(" | %-8s %s", info.Label, columns);
  }
  std::printf("\n");
  for (size_t l = 0; l < ns.size(); ++l)
  {
    std::printf("%6lld", static_cast<long long>(ns[l]));
    for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
    {
      std::printf(" | %8s %s", "", block(l, info.Kind).c_str());
    }
    std::printf("\n");
  }
}
} // namespace

int main(int argc, char** argv)
{
  long long maxN = 641;
  int threads = 1;
  std::string tablesPath = sltkbench::DefaultThesisTablesPath;
  CLI::App app(
    "Thesis Test 1 (3.5.1) with the linear SL step; see the header of bench/BenchRotation.cxx", "sltkBenchRotation");
  sltkbench::takeLastByDefault(app);
  app.add_option("--max-n", maxN, "largest grid of the table to run (1281 takes minutes)")->capture_default_str();
  app.add_option("--threads", threads, "executor size")->capture_default_str();
  app.add_option("--tables", tablesPath, "thesis_tables.json")->capture_default_str();
  if (const auto exit = sltkbench::parseCommandLine(app, argc, argv))
  {
    return *exit;
  }
  const sltkbench::ThesisTables thesis(tablesPath);
  if (!thesis.loaded())
  {
    std::fprintf(stderr, "cannot read %s: the thesis columns print '-'\n", tablesPath.c_str());
  }
  sltk::ThreadPool pool(threads);
  sltk::Context ctx;
  ctx.Executor = &pool;

  const std::vector<sltk::Index> ns = gridSizes(maxN);
  std::vector<Result> res[KindCount];
  for (const sltk::Index n : ns)
  {
    for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
    {
      res[static_cast<size_t>(info.Kind)].push_back(
        sltk::withInterpolator<2>(info.Kind, [&](auto tag) { return runTest1<typename decltype(tag)::type>(n, ctx); }));
    }
    std::fprintf(stderr, "N = %lld done\n", static_cast<long long>(n));
  }

  using sltk::InterpolatorKind;
  std::printf("Table 3.1, Test 1 (rotation, RK3 feet, dt = 3 dx, T = 1): L1 error / order, ours | thesis\n");
  printTable(ns, "     ours   ord    thesis   ord",
    [&](size_t l, InterpolatorKind kind)
    {
      const std::vector<Result>& r = res[static_cast<size_t>(kind)];
      const std::string key = sltkbench::thesisKey(kind);
      // Orders over N - 1 intervals; the first row has none.
      const double ord = l == 0
        ? std::nan("")
        : std::log(r[l - 1].Error / r[l].Error) / std::log(double(ns[l] - 1) / double(ns[l - 1] - 1));
      return formatValue(r[l].Error, "%9.2e") + " " + formatValue(ord, "%5.2f") + " " +
        formatValue(thesis.valueAtN(ErrTable, key + "/l1", ns[l]), "%9.2e") + " " +
        formatValue(thesis.valueAtN(ErrTable, key + "/order", ns[l]), "%5.2f");
    });

  std::printf(
    "\nTable 3.2, Test 1 run times in seconds (%d thread%s here; thesis: Galileo100) and %% gain over WENO3\n", threads,
    threads == 1 ? "" : "s");
  printTable(ns, "     ours   gain    thesis   gain",
    [&](size_t l, InterpolatorKind kind)
    {
      const double weno = res[Weno3][l].Seconds;
      const double seconds = res[static_cast<size_t>(kind)][l].Seconds;
      const std::string key = sltkbench::thesisKey(kind);
      const double gain = kind == InterpolatorKind::Weno3 ? std::nan("") : 100.0 * (weno - seconds) / weno;
      return formatValue(seconds, "%9.3e") + " " + formatValue(gain, "%6.1f") + " " +
        formatValue(thesis.valueAtN(CpuTable, key, ns[l]), "%9.2e") + " " +
        formatValue(thesis.valueAtN(CpuTable, key + "_gain_pct", ns[l]), "%6.1f");
    });
  return 0;
}
