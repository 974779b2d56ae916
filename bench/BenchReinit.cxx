// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchReinit.cxx
/// Run time of the constrained reinitialisation (thesis 4.4.6, (1.52)) on a 3D
/// band of about 1e6 nodes: a sphere of radius 0.7 on an n^3 grid of [-1, 1]^3,
/// phi0 = distortion * SDF (|grad phi0| between about 0.7 and 2.5), band
/// |SDF| < 5 dx (gamma + dx with gamma = 4 dx). For each thread count and step
/// count, the median wall time of --repeat runs, and after the run the mean
/// |phi - SDF| over the band in cells (20 steps settle the band: well below 0.1).
/// Steps 0 times the set-up alone (interface nodes and their fixed values).
///
/// Usage: sltkBenchReinit [--n N] [--threads LIST] [--steps LIST] [--repeat R]
///   --n        nodes per axis (default 256)
///   --threads  comma list of executor sizes (default 1,2)
///   --steps    comma list of iteration counts (default 0,20; tolerance 0, so exactly these)
///   --repeat   runs per measurement, median reported (default 3)

#include "common/BenchCli.h"

#include "sltk/exec/ThreadPool.h"
#include "sltk/grid/SampleField.h"
#include "sltk/levelset/Reinitialise.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
constexpr double Radius = 0.7;
constexpr double BandCells = 5.0;

double sphereDistance(const double* x)
{
  return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - Radius;
}

/// Smooth positive distortion of the SDF, between about 0.7 and 2.5.
double distortion(const double* x)
{
  return (1.6 + 0.9 * std::sin(3.0 * x[0] + 0.5) * std::cos(2.0 * x[1] - 0.3)) * (1.0 + 0.15 * std::cos(2.5 * x[2]));
}

std::array<double, 3> point(const sltk::GridSpec<3>& g, const std::array<sltk::Index, 3>& i)
{
  return { g.coordinate(0, i[0]), g.coordinate(1, i[1]), g.coordinate(2, i[2]) };
}

std::vector<int> intList(const std::string& text)
{
  std::vector<int> out;
  for (const std::string& item : sltkbench::splitList(text))
  {
    out.push_back(std::stoi(item));
  }
  return out;
}
} // namespace

int main(int argc, char** argv)
{
  long long n = 256;
  std::string threadList = "1,2";
  std::string stepList = "0,20";
  int repeat = 3;
  CLI::App app("Run time of the constrained reinitialisation on a 3D band; see the header of bench/BenchReinit.cxx",
    "sltkBenchReinit");
  sltkbench::takeLastByDefault(app);
  app.add_option("--n", n, "nodes per axis")->capture_default_str();
  app.add_option("--threads", threadList, "comma list of executor sizes")->capture_default_str();
  app.add_option("--steps", stepList, "comma list of iteration counts")->capture_default_str();
  app.add_option("--repeat", repeat, "runs per measurement, median reported")->capture_default_str();
  if (const auto exit = sltkbench::parseCommandLine(app, argc, argv))
  {
    return *exit;
  }
  repeat = std::max(1, repeat);

  const auto g = sltk::uniformBox<3>(n, -1.0, 1.0);
  const sltk::GridField<3> initial =
    sltk::sampleField(g, 1, [](const double* x) { return distortion(x) * sphereDistance(x); });
  std::vector<sltk::Index> band;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto x = point(g, initial.nodeIndex(k));
    if (std::fabs(sphereDistance(x.data())) < BandCells * g.Spacing[0])
    {
      band.push_back(k);
    }
  }
  std::printf("Reinitialisation (4.4.6): sphere R = %g on %lld^3 nodes, band |SDF| < %g dx: %zu nodes; median of %d\n",
    Radius, n, BandCells, band.size(), repeat);
  std::printf(
    "%7s %6s %9s %9s %9s %10s %14s\n", "threads", "steps", "median s", "min s", "max s", "interface", "mean |e| / dx");
  for (const int threads : intList(threadList))
  {
    sltk::ThreadPool pool(threads);
    sltk::Context ctx;
    ctx.Executor = &pool;
    for (const int steps : intList(stepList))
    {
      std::vector<double> seconds;
      sltk::ReinitReport report;
      double meanError = 0.0;
      for (int r = 0; r < repeat; ++r)
      {
        sltk::GridField<3> phi = initial;
        sltk::ReinitOptions o;
        o.MaxIterations = steps;
        o.Tolerance = 0.0;
        const auto t0 = std::chrono::steady_clock::now();
        const sltk::Status s = sltk::reinitialise<3>(phi, band, o, ctx, &report);
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        if (!s.isOk())
        {
          std::fprintf(stderr, "reinitialisation failed: %s\n", s.toString().c_str());
          return 1;
        }
        double sum = 0.0;
        for (const sltk::Index k : band)
        {
          const auto i = phi.nodeIndex(k);
          sum += std::fabs(phi(i) - sphereDistance(point(g, i).data()));
        }
        meanError = sum / double(band.size()) / g.Spacing[0];
      }
      std::sort(seconds.begin(), seconds.end());
      std::printf("%7d %6d %9.3f %9.3f %9.3f %10lld %14.4f\n", threads, report.Iterations, seconds[seconds.size() / 2],
        seconds.front(), seconds.back(), static_cast<long long>(report.InterfaceNodes), meanError);
      std::fflush(stdout);
    }
  }
  return 0;
}
