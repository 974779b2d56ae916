// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchInterp.cxx
/// Reconstruction cost per kernel of the interpolator registry
/// (sltk/interp/InterpolatorKind.h: Q1, WENO3, CWENO, CWENOZ) in 2D and 3D,
/// as a function of the number of evaluations per prepared cell (1, 4, 16, 64).
///
/// The thesis's point (Remarks 3.1-3.2, Tables 3.2/3.4/3.6/3.8/3.10): CWENO
/// builds one polynomial per cell in prepare() and evaluates it cheaply, while
/// WENO3 (2.3.4) has point-dependent linear weights (2.76) and redoes all its
/// work at every evaluation. In an SL step each foot usually lands in a
/// different cell (1 evaluation per cell); the ratio CWENO/WENO then falls as
/// evaluations per cell grow.
///
/// Each measurement visits random cells of a field (sin products plus a kink),
/// prepares each once and evaluates it E times at precomputed random local
/// coordinates, accumulating the results into a volatile sink. Times are
/// medians over the repetitions.
///
/// Usage: sltkBenchInterp [--evals N] [--reps R]
///   --evals  evaluations per measurement in 2D (3D uses a quarter; default 262144)
///   --reps   repetitions per measurement, median reported (default 7)

#include "common/BenchCli.h"

#include "sltk/interp/Interpolators.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace
{
volatile double Sink = 0.0;

constexpr int EvalsPerCell[4] = { 1, 4, 16, 64 };
constexpr int LocalCount = 4096; // distinct local points, reused cyclically

template <int D>
sltk::GridField<D> makeField(sltk::Index n)
{
  sltk::GridSpec<D> g;
  for (int a = 0; a < D; ++a)
  {
    g.Dims[a] = n;
    g.Origin[a] = -1.0;
    g.Spacing[a] = 2.0 / double(n - 1);
    g.Bounds[a] = sltk::Boundary::Extrapolate;
  }
  sltk::GridField<D> u(g, 2);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    double v = std::fabs(g.coordinate(0, i[0]) - 0.1);
    for (int a = 0; a < D; ++a)
    {
      v += std::sin(3.0 * g.coordinate(a, i[a]) + a);
    }
    u(i) = v;
  }
  u.fillGhosts();
  return u;
}

/// Random cells and local points, generated outside the timed loops.
template <int D>
struct Workload
{
  std::vector<std::array<sltk::Index, D>> Cells;
  std::vector<std::array<double, D>> Locals;
};

template <int D>
Workload<D> makeWorkload(const sltk::GridSpec<D>& g, long cells)
{
  std::mt19937_64 rng(42);
  Workload<D> w;
  w.Cells.resize(static_cast<size_t>(cells));
  for (auto& c : w.Cells)
  {
    for (int a = 0; a < D; ++a)
    {
      c[a] = std::uniform_int_distribution<sltk::Index>(0, g.Dims[a] - 2)(rng);
    }
  }
  w.Locals.resize(LocalCount);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (auto& t : w.Locals)
  {
    for (int a = 0; a < D; ++a)
    {
      t[a] = unit(rng);
    }
  }
  return w;
}

/// Seconds of one run: prepare each cell once, evaluate it `evals` times.
template <class Interp>
double timeOnce(Interp& interp, const Workload<Interp::Dim>& w, long cells, int evals)
{
  double sum = 0.0;
  size_t next = 0;
  const auto start = std::chrono::steady_clock::now();
  for (long c = 0; c < cells; ++c)
  {
    interp.prepare(w.Cells[static_cast<size_t>(c)]);
    for (int e = 0; e < evals; ++e)
    {
      sum += interp.eval(w.Locals[next]);
      next = (next + 1) & (LocalCount - 1);
    }
  }
  const auto stop = std::chrono::steady_clock::now();
  Sink = Sink + sum;
  return std::chrono::duration<double>(stop - start).count();
}

double median(std::vector<double> v)
{
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Kernels: the registry's, in its order; a new kind is measured and printed without a change here.
constexpr int KernelCount = static_cast<int>(sltk::HjbInterpolators.size());
constexpr auto Weno = static_cast<size_t>(sltk::InterpolatorKind::Weno3);

/// One timing of the interpolator of `kind` on `u`.
template <int D>
double timeKind(sltk::InterpolatorKind kind, const sltk::GridField<D>& u, const Workload<D>& w, long cells, int evals)
{
  return sltk::withInterpolator<D>(kind,
    [&](auto tag)
    {
      typename decltype(tag)::type interp(u);
      return timeOnce(interp, w, cells, evals);
    });
}

template <int D>
void runDimension(sltk::Index n, long totalEvals, int reps)
{
  const auto u = makeField<D>(n);
  const long maxCells = totalEvals / EvalsPerCell[0];
  const auto w = makeWorkload<D>(u.spec(), maxCells);
  std::printf("\n%dD, %lld^%d nodes, %ld evaluations per measurement, median of %d\n", D, static_cast<long long>(n), D,
    totalEvals, reps);
  std::printf("%-8s %6s %14s %12s %16s\n", "kernel", "E/cell", "Mevals/s", "ns/eval", "time/WENO3 time");
  for (const int evals : EvalsPerCell)
  {
    const long cells = totalEvals / evals;
    // Kernels interleaved within each repetition, so that load changes hit them alike.
    std::vector<double> runs[KernelCount];
    for (int r = 0; r < reps; ++r)
    {
      for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
      {
        runs[static_cast<size_t>(info.Kind)].push_back(timeKind<D>(info.Kind, u, w, cells, evals));
      }
    }
    double seconds[KernelCount];
    for (int k = 0; k < KernelCount; ++k)
    {
      seconds[k] = median(runs[k]);
    }
    for (const sltk::InterpolatorInfo& info : sltk::HjbInterpolators)
    {
      const auto k = static_cast<size_t>(info.Kind);
      const double count = double(cells) * evals;
      std::printf("%-8s %6d %14.2f %12.1f %16.3f\n", info.Label, evals, count / seconds[k] * 1e-6,
        seconds[k] / count * 1e9, seconds[k] / seconds[Weno]);
    }
  }
}
} // namespace

int main(int argc, char** argv)
{
  long totalEvals = 1L << 18;
  int reps = 7;
  CLI::App app("Reconstruction cost per kernel; see the header of bench/BenchInterp.cxx", "sltkBenchInterp");
  sltkbench::takeLastByDefault(app);
  app.add_option("--evals", totalEvals, "evaluations per measurement in 2D (3D: a quarter; at least 64)")
    ->capture_default_str();
  app.add_option("--reps", reps, "repetitions per measurement, median reported")->capture_default_str();
  if (const auto exit = sltkbench::parseCommandLine(app, argc, argv))
  {
    return *exit;
  }
  totalEvals = std::max(64L, totalEvals);
  reps = std::max(1, reps);
  std::printf("Reconstruction cost: prepare() once per cell, then E evaluations (one thread).\n"
              "time/WENO3 time < 1: cheaper than WENO3 for the same evaluations.\n");
  runDimension<2>(513, totalEvals, reps);
  runDimension<3>(97, totalEvals / 4, reps);
  std::printf("\n(sink %g)\n", static_cast<double>(Sink));
  return 0;
}
