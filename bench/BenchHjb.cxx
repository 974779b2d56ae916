// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchHjb.cxx
/// The HJB tests of thesis 3.5 with the scheme (3.7) (sltk/hjb/HjbScheme.h)
/// and the interpolators of the registry (sltk/interp/InterpolatorKind.h; by
/// default the thesis's WENO3, CWENO and CWENOZ), run side by side:
///  - Tables 3.1, 3.3, 3.5, 3.7: L1 errors and orders, ours beside the thesis's;
///  - Table 3.9: min/max of Test 4;
///  - Tables 3.2, 3.4, 3.6, 3.8, 3.10: run times (median of --repeat runs,
///    the interpolators interleaved in each repetition) and the % gain
///    over WENO3 measured in the same run, beside the thesis's
///    (Galileo100 cluster: compare the gains, not the seconds);
///  - objective evaluations and cell builds (prepare()) per node and step.
/// The thesis's numbers are read from a JSON transcription of its tables (--tables).
///
/// Usage: sltkBenchHjb [--test 1|2|3|3h|4|5|all] [--min-n N] [--max-n N] [--repeat R]
///                     [--threads T] [--cache K] [--warm W] [--interp LIST] [--tables PATH]
///   --test    which test (3h: Test 3 with T = 0.5, the text's final time); default all
///   --min-n, --max-n  range of the tables' N to run (default: per-test limits that
///             keep the whole run within minutes: Test 1 <= 321, 2 <= 2561, 3 <= 1006,
///             4 <= 81, 5 <= 126)
///   --repeat  timing repetitions, median reported (default 1)
///   --threads executor size (default 1: the CPU time of one core)
///   --cache   cells per thread chunk (HjbOptions::CellCacheSize: 0 automatic (default), 1, 8, 256, 4096)
///   --warm    MinimizerOptions::WarmTabulationPoints (default -1: the preset's, 5 for Test 4; 0: off)
///   --interp  comma list of interpolators (q1, weno3 or weno, cweno, cwenoz; default
///             weno3,cweno,cwenoz, the thesis's; gains need weno3)
///   --tables  path of thesis_tables.json (default /work/shared/reference/thesis_tables.json)

#include "common/BenchCli.h"
#include "common/ThesisNames.h"
#include "common/ThesisTables.h"

#include "sltk/hjb/HjbError.h"
#include "sltk/hjb/HjbScheme.h"
#include "sltk/hjb/Presets.h"
#include "sltk/interp/Interpolators.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace
{

using sltkbench::formatValue;
using sltkbench::ThesisTables;
using Json = nlohmann::json;

constexpr int KindCount = static_cast<int>(sltk::HjbInterpolators.size());
constexpr auto Weno3 = static_cast<size_t>(sltk::InterpolatorKind::Weno3);
using PerKind = std::array<bool, KindCount>; // indexed by InterpolatorKind

/// The leading integer of a grid entry ("126x101": 126), 0 for anything else.
long long leadingNumber(const Json& entry)
{
  return entry.is_string() ? std::atoll(entry.get<std::string>().c_str()) : 0;
}

/// Test 5's table lists grids "126x101": match on the first number.
double thesisGridValue(const ThesisTables& root, const std::string& table, const std::string& field, long long nx)
{
  const Json* grids = root.find(table + "/grid");
  const Json* values = root.find(table + "/" + field);
  if (!grids || !values || !grids->is_array() || !values->is_array())
  {
    return std::nan("");
  }
  for (size_t k = 0; k < grids->size() && k < values->size(); ++k)
  {
    if (leadingNumber((*grids)[k]) == nx && (*values)[k].is_number())
    {
      return (*values)[k].get<double>();
    }
  }
  return std::nan("");
}

std::vector<long long> tableNs(const ThesisTables& root, const std::vector<std::string>& tables)
{
  std::vector<long long> ns;
  for (const auto& t : tables)
  {
    const Json* list = root.find(t + "/N");
    if (!list)
    {
      list = root.find(t + "/grid");
    }
    if (!list || !list->is_array())
    {
      continue;
    }
    for (const Json& v : *list)
    {
      ns.push_back(v.is_number() ? static_cast<long long>(v.get<double>()) : leadingNumber(v));
    }
  }
  std::sort(ns.begin(), ns.end());
  ns.erase(std::unique(ns.begin(), ns.end()), ns.end());
  return ns;
}

// --- runs ----------------------------------------------------------------------------------------

struct Measure
{
  double Error = std::nan("");
  double Min = 0.0;
  double Max = 0.0;
  double Seconds = 0.0;
  double EvalsPerNode = 0.0;
  double BuildsPerNode = 0.0;
  long long Reached = 0;
};

template <class Interp, class Problem, int D>
Measure runOnce(const Problem& problem, const sltk::HjbSetup<D>& setup, const sltk::Context& ctx)
{
  sltk::GridField<D> u(setup.Grid, 2);
  sltk::hjbInitialize(problem, u);
  sltk::HjbStats stats;
  sltk::GridField<D> reach;
  const auto start = std::chrono::steady_clock::now();
  const sltk::Status status =
    sltk::hjbAdvance<Interp>(ctx, setup.Options, problem, u, &stats, Problem::HasObstacle ? &reach : nullptr);
  Measure m;
  m.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!status.isOk())
  {
    std::fprintf(stderr, "run failed: %s\n", status.toString().c_str());
    std::exit(1);
  }
  if constexpr (Problem::HasExact)
  {
    const double t = setup.Options.FinalTime;
    m.Error = sltk::l1Error(u, [&](const std::array<double, D>& x) { return problem.Exact(t, x); });
  }
  const auto range = sltk::valueRange(u);
  m.Min = range.first;
  m.Max = range.second;
  m.EvalsPerNode = stats.evaluationsPerNode();
  m.BuildsPerNode = stats.buildsPerNode();
  for (double r : reach.storage())
  {
    m.Reached += r != sltk::NotReached ? 1 : 0;
  }
  return m;
}

/// The enabled interpolators, interleaved `repeat` times; median seconds.
template <int D, class Problem>
std::array<Measure, KindCount> runAll(
  const Problem& problem, const sltk::HjbSetup<D>& setup, int repeat, const PerKind& enabled, const sltk::Context& ctx)
{
  std::array<Measure, KindCount> out;
  std::array<std::vector<double>, KindCount> seconds;
  // Runs shorter than 0.2 s are repeated and averaged, so that a timing is never a few ms of noise.
  auto timed = [&](auto run)
  {
    Measure m = run();
    const int loops = m.Seconds < 0.2 ? static_cast<int>(std::ceil(0.2 / std::max(m.Seconds, 1e-6))) : 1;
    if (loops > 1)
    {
      double total = 0.0;
      for (int l = 0; l < loops; ++l)
      {
        total += run().Seconds;
      }
      m.Seconds = total / loops;
    }
    return m;
  };
  for (int r = 0; r < repeat; ++r)
  {
    for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
    {
      const auto m = static_cast<size_t>(info.Kind);
      if (enabled[m])
      {
        out[m] = sltk::withInterpolator<D>(info.Kind,
          [&](auto tag) { return timed([&] { return runOnce<typename decltype(tag)::type>(problem, setup, ctx); }); });
      }
      seconds[m].push_back(enabled[m] ? out[m].Seconds : std::nan(""));
    }
  }
  for (size_t m = 0; m < KindCount; ++m)
  {
    std::sort(seconds[m].begin(), seconds[m].end());
    out[m].Seconds = seconds[m][seconds[m].size() / 2];
  }
  return out;
}

/// The interpolators of the thesis's chapter 3: all but Q1.
PerKind thesisKinds()
{
  PerKind kinds{};
  kinds.fill(true);
  kinds[static_cast<size_t>(sltk::InterpolatorKind::Q1)] = false;
  return kinds;
}

struct Config
{
  std::string Test = "all";
  long long MinN = 0;
  long long MaxN = 0; // 0: per-test default
  int Repeat = 1;
  int Threads = 1;
  int Cache = 0;
  int Warm = -1;
  PerKind Interps = thesisKinds();
  std::string Tables = sltkbench::DefaultThesisTablesPath;
};

struct TestSpec
{
  const char* Id;
  const char* Title;
  std::string ErrTable; // empty: no errors (Test 5)
  std::string CpuTable;
  long long DefaultMaxN;
  double NMinusOneFactor = -1.0; // the orders count N + this intervals per axis: N - 1, periodic grids N
  bool MinMaxTable = false;      // Table 3.9's min and max as well (Test 4)
};

// The thesis's tests of 3.5 and their tables (Test 3 also with the text's T = 0.5).
const char* const Test1Title = "Test 1 (3.5.1): rotation, RK3, dt = 3 dx, T = 1 -- Tables 3.1, 3.2";
const char* const Test2Title = "Test 2 (3.5.2): 1D semi-concave, RK1, dt = 10 dx, T = 1 -- Tables 3.3, 3.4";
const char* const Test3Title = "Test 3 (3.5.3): 1D eikonal, periodic, RK3 over A^3, dt = dx, T = 1 -- Tables 3.5, 3.6";
const char* const Test3hTitle = "Test 3 with the text's T = 0.5 (thesis columns are Table 3.5's, T = 1 caption)";
const char* const Test4Title =
  "Test 4 (3.5.4): 2D semi-convex, disc R = 2.2, RK1, dt = 5/4 dx, T = 0.5 -- Tables 3.7, 3.8";
const char* const Test5Title = "Test 5 (3.5.5): Zermelo with obstacles, RK3 over A^3, dt = dx, T = 3 -- Table 3.10";
const TestSpec Test1{ "1", Test1Title, "table_3_1_test1_errors", "table_3_2_test1_cpu_s", 321 };
const TestSpec Test2{ "2", Test2Title, "table_3_3_test2_errors", "table_3_4_test2_cpu_s", 2561 };
const TestSpec Test3{ "3", Test3Title, "table_3_5_test3_errors", "table_3_6_test3_cpu_s", 1006, 0.0 };
const TestSpec Test3h{ "3h", Test3hTitle, "table_3_5_test3_errors", "table_3_6_test3_cpu_s", 1006, 0.0 };
const TestSpec Test4{ "4", Test4Title, "table_3_7_test4_errors", "table_3_8_test4_cpu_s", 81, -1.0, true };
const TestSpec Test5{ "5", Test5Title, "", "table_3_10_test5_cpu_s", 126 };

void printHeader(const TestSpec& spec, bool errors)
{
  std::printf("\n=== %s ===\n", spec.Title);
  if (errors)
  {
    std::printf("%7s | %-6s | %9s %5s | %9s %5s | %9s %6s | %9s %7s | %9s %7s | %7s %6s\n", "N", "interp", "L1 ours",
      "ord", "L1 thesis", "ord", "ours/th", "", "time s", "gain%", "thesis s", "gain%", "eval/n", "bld/n");
  }
  else
  {
    std::printf("%7s | %-6s | %9s %7s | %9s %7s | %7s %6s | %9s\n", "grid", "interp", "time s", "gain%", "thesis s",
      "gain%", "eval/n", "bld/n", "reached");
  }
}

template <int D, class Problem, class SetupFn>
void runTable(const ThesisTables& tables, const TestSpec& spec, const Config& cfg, const sltk::Context& ctx,
  const Problem& problem, SetupFn&& makeSetup)
{
  const double nMinusOneFactor = spec.NMinusOneFactor;
  const bool minMaxTable = spec.MinMaxTable;
  std::vector<std::string> names;
  if (!spec.ErrTable.empty())
  {
    names.push_back(spec.ErrTable);
  }
  names.push_back(spec.CpuTable);
  if (minMaxTable)
  {
    names.push_back("table_3_9_test4_min_max");
  }
  const long long maxN = cfg.MaxN > 0 ? cfg.MaxN : spec.DefaultMaxN;
  const bool errors = !spec.ErrTable.empty();
  printHeader(spec, errors);
  std::array<double, KindCount> prevErr{};
  long long prevN = 0;
  std::vector<std::pair<long long, std::array<Measure, KindCount>>> all;
  for (long long n : tableNs(tables, names))
  {
    if (n < cfg.MinN || n > maxN)
    {
      continue;
    }
    auto setup = makeSetup(n);
    setup.Options.CellCacheSize = cfg.Cache;
    if (cfg.Warm >= 0)
    {
      setup.Options.Minimizer.WarmTabulationPoints = cfg.Warm;
    }
    const auto m = runAll<D>(problem, setup, cfg.Repeat, cfg.Interps, ctx);
    all.emplace_back(n, m);
    for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
    {
      const auto k = static_cast<size_t>(info.Kind);
      if (!cfg.Interps[k])
      {
        continue;
      }
      const std::string key = sltkbench::thesisKey(info.Kind);
      const bool againstWeno = k != Weno3 && cfg.Interps[Weno3];
      const double gain = againstWeno ? 100.0 * (1.0 - m[k].Seconds / m[Weno3].Seconds) : std::nan("");
      const double thesisCpu =
        errors ? tables.valueAtN(spec.CpuTable, key, n) : thesisGridValue(tables, spec.CpuTable, key, n);
      const double thesisGain = errors ? tables.valueAtN(spec.CpuTable, key + "_gain_pct", n)
                                       : thesisGridValue(tables, spec.CpuTable, key + "_gain_pct", n);
      if (errors)
      {
        const double thErr = tables.valueAtN(spec.ErrTable, key + "/l1", n);
        const double thOrd = tables.valueAtN(spec.ErrTable, key + "/order", n);
        // Orders in the thesis use N - 1 intervals (N + factor for periodic grids).
        const double ord = prevN > 0 ? std::log(prevErr[k] / m[k].Error) /
            std::log((double(n) + nMinusOneFactor) / (double(prevN) + nMinusOneFactor))
                                     : std::nan("");
        std::printf("%7lld | %-6s | %s %s | %s %s | %s %6s | %s %s | %s %s | %7.1f %6.2f\n", n, info.Label,
          formatValue(m[k].Error).c_str(), formatValue(ord, "%5.2f").c_str(), formatValue(thErr).c_str(),
          formatValue(thOrd, "%5.2f").c_str(), formatValue(m[k].Error / thErr, "%9.3f").c_str(), "",
          formatValue(m[k].Seconds).c_str(), formatValue(gain, "%7.2f").c_str(), formatValue(thesisCpu).c_str(),
          formatValue(thesisGain, "%7.2f").c_str(), m[k].EvalsPerNode, m[k].BuildsPerNode);
      }
      else
      {
        const long long ny = 4 * (n - 1) / 5 + 1;
        std::printf("%3lldx%-3lld | %-6s | %s %s | %s %s | %7.1f %6.2f | %9lld\n", n, ny, info.Label,
          formatValue(m[k].Seconds).c_str(), formatValue(gain, "%7.2f").c_str(), formatValue(thesisCpu).c_str(),
          formatValue(thesisGain, "%7.2f").c_str(), m[k].EvalsPerNode, m[k].BuildsPerNode, m[k].Reached);
      }
      prevErr[k] = m[k].Error;
    }
    prevN = n;
    std::fflush(stdout);
  }
  if (minMaxTable && !all.empty())
  {
    const std::string table = "table_3_9_test4_min_max";
    std::printf("\n--- Table 3.9: range of the Test 4 solution (exact range [0, 1]) ---\n");
    std::printf(
      "%7s | %-6s | %10s %10s | %10s %10s\n", "N", "interp", "min ours", "max ours", "min thesis", "max thesis");
    for (const auto& entry : all)
    {
      for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
      {
        const auto k = static_cast<size_t>(info.Kind);
        if (!cfg.Interps[k])
        {
          continue;
        }
        const std::string key = sltkbench::thesisKey(info.Kind);
        std::printf("%7lld | %-6s | %10.3e %10.4f | %s %s\n", entry.first, info.Label, entry.second[k].Min,
          entry.second[k].Max, formatValue(tables.valueAtN(table, key + "/min", entry.first), "%10.3e").c_str(),
          formatValue(tables.valueAtN(table, key + "/max", entry.first), "%10.4f").c_str());
      }
    }
  }
}

} // namespace

int main(int argc, char** argv)
{
  Config cfg;
  std::string interps;
  CLI::App app("SLTK HJB benchmark (thesis 3.5); see the header of bench/BenchHjb.cxx", "sltkBenchHjb");
  sltkbench::takeLastByDefault(app);
  app.add_option("--test", cfg.Test, "1, 2, 3, 3h (Test 3 with T = 0.5), 4, 5 or all")->capture_default_str();
  app.add_option("--min-n", cfg.MinN, "smallest N of the tables to run");
  app.add_option("--max-n", cfg.MaxN, "largest N of the tables to run (0: per-test default)");
  app.add_option("--repeat", cfg.Repeat, "timing repetitions, median reported")->capture_default_str();
  app.add_option("--threads", cfg.Threads, "executor size")->capture_default_str();
  app.add_option("--cache", cfg.Cache, "cells per thread chunk (0: automatic)")->capture_default_str();
  app.add_option("--warm", cfg.Warm, "warm tabulation points (-1: the preset's; 0: off)")->capture_default_str();
  app.add_option("--interp", interps,
    "comma list of " + sltk::hjbInterpolatorNameList() + " (weno: weno3; default weno3,cweno,cwenoz)");
  app.add_option("--tables", cfg.Tables, "thesis_tables.json")->capture_default_str();
  if (const auto exit = sltkbench::parseCommandLine(app, argc, argv))
  {
    return *exit;
  }
  cfg.Repeat = std::max(1, cfg.Repeat);
  if (app.count("--interp") > 0)
  {
    cfg.Interps.fill(false);
    for (const std::string& name : sltkbench::splitList(interps))
    {
      sltk::InterpolatorKind kind;
      if (!sltkbench::parseBenchInterpolator(name, kind) || !sltk::offeredByHjb(kind))
      {
        std::fprintf(
          stderr, "--interp: unknown interpolator %s (%s)\n", name.c_str(), sltk::hjbInterpolatorNameList().c_str());
        return 2;
      }
      cfg.Interps[static_cast<size_t>(kind)] = true;
    }
  }
  const ThesisTables tables(cfg.Tables);
  if (!tables.loaded())
  {
    std::fprintf(
      stderr, "cannot read %s: thesis columns and the tables' N lists are unavailable\n", cfg.Tables.c_str());
    return 1;
  }
  sltk::ThreadPool pool(cfg.Threads);
  sltk::Context ctx;
  ctx.Executor = &pool;
  std::printf("SLTK HJB benchmark (thesis 3.5): threads %d, cell cache %d (0: automatic), warm start %d (-1: "
              "preset), median of %d run(s)\n",
    cfg.Threads, cfg.Cache, cfg.Warm, cfg.Repeat);
  // A table runs when --test names it (or is "all"), in the dimension of its preset's grid.
  auto run = [&](const TestSpec& spec, const auto& problem, auto makeSetup)
  {
    if (cfg.Test == "all" || cfg.Test == spec.Id)
    {
      runTable<decltype(makeSetup(0LL).Grid)::Dim>(tables, spec, cfg, ctx, problem, makeSetup);
    }
  };
  run(Test1, sltk::test1Problem(), [](long long n) { return sltk::test1Setup(n); });
  run(Test2, sltk::test2Problem(), [](long long n) { return sltk::test2Setup(n); });
  run(Test3, sltk::test3Problem(), [](long long n) { return sltk::test3Setup(n, 1.0); });
  run(Test3h, sltk::test3Problem(), [](long long n) { return sltk::test3Setup(n, 0.5); });
  run(Test4, sltk::test4Problem(), [](long long n) { return sltk::test4Setup(n); });
  run(Test5, sltk::test5Problem(), [](long long n) { return sltk::test5Setup(n); });
  return 0;
}
