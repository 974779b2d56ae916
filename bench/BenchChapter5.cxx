// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchChapter5.cxx
/// The thesis's adaptive tests (5.3) on the tiled band (octree/TiledReconstruction.h,
/// Documentation/Octree.md): the circle (64 points), the square (24) and the
/// heart (24) in 2D, Cube&Spheres (2346) in 3D, with the chapter's parameters:
///  - the finest cell of run 1 from (5.10)-(5.11): L0 = ceil(log2(Delta_P / (C h_P))),
///    C = 0.5, so dx_1 = Delta_P / 2^L0 (Delta_P the longest edge of the cloud's
///    box, 2 in the unit box of 4.5), one level more per run (3 runs);
///  - dt = dx_min of each run (5.12; the library's dt = dx, 4.36);
///  - the initial data a sphere (circle) around the cloud (5.3: "the signed
///    distance function associated to a circle, or a sphere, encompassing the
///    whole point cloud"), K_P = 2 beyond the farthest point;
///  - p and eta of Table 4.1, the stopping rule (4.33) alone, at most 100
///    iterations, no cleaning.
/// It prints each run's iterations against the thesis's (issue 14: within
/// +-50%), E_2 and Err_P (the circle's as ratios to the thesis's 1.17e-1 and
/// 1.20e-3), and the nodes stored against the uniform grid of the same finest
/// cell (Fig. 5.7, 5.14; --per-iteration: every iteration's), and where the
/// exact shape is known (not the heart) the L1 error of phi over its band.
///
/// What differs from the thesis (Documentation/Octree.md): run 1 is uniform
/// (the coarsest grid); runs 2 and 3 store 8^D-node tiles of the finest grid
/// around the band, not cells of every level; the interpolation is ours
/// (--interp q1, weno3) or the thesis's least squares Q1 (5.5) on the finest
/// nodes (lsq-q1, LsqQ1.h), with d's gradient from our scheme, not from the
/// cell's polynomial; the heart's formula is our choice (SyntheticClouds.h:
/// the thesis gives none).
///
/// Usage: sltkBenchChapter5 [--case circle,square,heart,cubespheres] [--interp q1,weno3,lsq-q1]
///                          [--threads N] [--per-iteration] [--tables thesis_tables.json]

#include "common/BenchCli.h"
#include "common/Chapter5.h"
#include "common/SdfErrors.h"
#include "common/ThesisTables.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/exec/Context.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/interp/InterpolatorKind.h"
#include "sltk/interp/LsqQ1.h"
#include "sltk/octree/TiledReconstruction.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
using namespace sltkbench;

struct Arguments
{
  std::vector<std::string> Cases{ "circle", "square", "heart", "cubespheres" };
  std::vector<std::string> Interps{ "q1", "weno3", "lsq-q1" };
  int Threads = 0;
  double OutsideFactor = 2.0; ///< K_P: the initial sphere's margin beyond the farthest point, in h_P
  bool PerIteration = false;
  std::string Tables = DefaultThesisTablesPath;
};

template <int D>
using ExactDistance = std::function<double(const std::array<double, D>&)>;

/// What the thesis's zero level set looks like with the least squares Q1
/// (5.5) drawn cell by cell ("noticeably disconnected", 5.3.1): at the
/// middle of every edge the front crosses (adjacent nodes of opposite signs),
/// the jump between the two nodes' polynomials, in cells. Our surface is
/// contoured from the node values instead, so it is continuous with any
/// interpolator. Mean and largest jump; the finest grid is copied into one
/// field, so only grids of at most MaxSeamNodes nodes are measured.
struct SeamJumps
{
  double Mean = 0.0, Largest = 0.0;
  sltk::Index Edges = 0;
};
constexpr sltk::Index MaxSeamNodes = 20'000'000;

template <int D>
SeamJumps leastSquaresSeams(const sltk::TiledField<D>& field)
{
  const sltk::GridSpec<D>& g = field.grid();
  sltk::GridField<D> phi(g, 2);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    phi(i) = field.value(i);
  }
  phi.fillGhosts();
  sltk::LsqQ1Interpolator<D> lsq(phi);
  SeamJumps seams;
  double sum = 0.0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    for (int a = 0; a < D; ++a)
    {
      auto j = i;
      j[a] += 1;
      if (j[a] >= g.Dims[a] || (phi(i) < 0.0) == (phi(j) < 0.0))
      {
        continue;
      }
      double below[D], above[D];
      for (int b = 0; b < D; ++b)
      {
        below[b] = above[b] = g.coordinate(b, i[b]);
      }
      below[a] += (0.5 - 1e-9) * g.Spacing[a];
      above[a] += (0.5 + 1e-9) * g.Spacing[a];
      const double jump = std::fabs(sltk::interpolate(lsq, g, above) - sltk::interpolate(lsq, g, below)) / g.Spacing[a];
      sum += jump;
      seams.Largest = std::max(seams.Largest, jump);
      ++seams.Edges;
    }
  }
  seams.Mean = seams.Edges > 0 ? sum / static_cast<double>(seams.Edges) : 0.0;
  return seams;
}

template <int D>
void runCase(const std::string& name, const sltk::PointCloud<D>& cloud, const ExactDistance<D>& exact,
  const std::vector<double>& thesisIterations, double thesisEnergy, double thesisCloudError, const Arguments& args,
  const sltk::Context& ctx)
{
  for (const std::string& interp : args.Interps)
  {
    sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
    options.Runs = 3;
    options.Guess = sltk::InitialGuess::BoundingSphere;
    options.OutsideThresholdFactor = args.OutsideFactor;
    options.OctreeStorage = true;
    sltk::InterpolatorKind kind{};
    options.Interpolator = sltk::parseInterpolator(interp, kind) ? std::optional(kind) : std::nullopt;
    if (!options.Interpolator) // lsq-q1: the thesis's own (5.5), LsqQ1.h
    {
      std::fprintf(stderr, "unknown interpolator %s\n", interp.c_str());
      return;
    }
    // h_P is the plan's (unit box); plan once to learn it, then at (5.10)'s cell.
    sltk::ReconstructionPlan<D> plan;
    sltk::Status status = sltk::planReconstruction(cloud, options, ctx, plan);
    Chapter5Grid level;
    if (status.isOk())
    {
      // Delta_P: the unit box (4.5, UnitBox.h) maps the cloud's longest edge to 2.
      level = chapter5Grid(2.0, plan.CloudSpacing);
      options.CellSizeFactor = level.CellSizeFactor;
      status = sltk::planReconstruction(cloud, options, ctx, plan);
    }
    sltk::TiledReconstructionResult<D> result;
    const auto start = std::chrono::steady_clock::now();
    if (status.isOk())
    {
      status = sltk::reconstructTiled(plan, ctx, result);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("\n%s (%zu points), %s: L0 = %d, C_dx = %.4f (dx_1 = Delta_P / 2^L0), %.2f s\n", name.c_str(),
      cloud.Points.size(), interp.c_str(), level.Level, level.CellSizeFactor, seconds);
    if (!status.isOk())
    {
      std::printf("  failed: %s\n", status.toString().c_str());
      continue;
    }
    std::printf("  %3s %16s %6s %6s %-14s %11s %11s %12s %12s %7s\n", "run", "grid", "iters", "thesis", "", "E_p",
      "Err_P", "stored", "most", "uniform");
    const auto& runs = result.Records.Runs;
    for (size_t r = 0; r < runs.size(); ++r)
    {
      const auto& run = runs[r];
      std::string dims;
      for (int a = 0; a < D; ++a)
      {
        dims += (a ? "x" : "") + std::to_string(run.Grid.Dims[static_cast<size_t>(a)]);
      }
      const double uniform = static_cast<double>(run.Grid.nodeCount());
      const bool tiled = r > 0 && r - 1 < result.Storage.size();
      const double stored = tiled ? static_cast<double>(result.Storage[r - 1].StoredNodes) : uniform;
      const double most =
        tiled ? static_cast<double>(result.Storage[r - 1].PeakTiles) * sltk::TiledField<D>::Nodes : uniform;
      const double thesis = r < thesisIterations.size() ? thesisIterations[r] : std::nan("");
      std::printf("  %3zu %16s %6d %6s %-14s %11.4e %11.4e %12.0f %12.0f %6.1f%%\n", r + 1, dims.c_str(),
        run.Iterations, formatValue(thesis, "%6.0f").c_str(), verdictWithinHalf(run.Iterations, thesis).c_str(),
        run.Energy, run.CloudError, stored, most, 100.0 * stored / uniform);
    }
    if (exact)
    {
      const auto value = [&result](const std::array<sltk::Index, D>& i) { return result.Field.value(i); };
      std::printf("  L1 of phi against the exact signed distance over its band |d| < gamma: %.4e\n",
        l1Errors<D>(result.Field.grid(), value, exact, result.Field.gamma(), result.Box).second);
    }
    if (result.Field.grid().nodeCount() <= MaxSeamNodes)
    {
      const SeamJumps seams = leastSquaresSeams<D>(result.Field);
      std::printf("  the least squares Q1 (5.5) drawn cell by cell: jumps of %.3g cells on average, %.3g at most, at "
                  "the middle of the %lld edges the front crosses (our contour: none)\n",
        seams.Mean, seams.Largest, static_cast<long long>(seams.Edges));
    }
    if (!runs.empty() && !std::isnan(thesisEnergy))
    {
      std::printf("  final E_2 %.4e against the thesis's %.3e (%s); Err_P %.4e against %.3e (%s)\n", runs.back().Energy,
        thesisEnergy, errorRatio(runs.back().Energy, thesisEnergy).c_str(), runs.back().CloudError, thesisCloudError,
        errorRatio(runs.back().CloudError, thesisCloudError).c_str());
    }
    if (args.PerIteration)
    {
      std::printf("  %3s %5s %11s %11s %12s %12s %12s\n", "run", "iter", "E_p", "Err_P", "stored", "leaves", "uniform");
      for (const sltk::IterationRecord& it : result.Records.History)
      {
        std::printf("  %3d %5d %11.4e %11.4e %12lld %12lld %12lld\n", it.Run, it.Iteration, it.Energy, it.CloudError,
          static_cast<long long>(it.StoredNodes), static_cast<long long>(it.Leaves),
          static_cast<long long>(it.UniformNodes));
      }
    }
  }
}

} // namespace

int main(int argc, char** argv)
{
  CLI::App app("The thesis's chapter 5 tests (5.3) on the tiled band: iterations, E_2, Err_P, stored nodes");
  takeLastByDefault(app);
  Arguments args;
  std::string cases, interps;
  app.add_option("--case", cases, "circle,square,heart,cubespheres (default all)");
  app.add_option("--interp", interps,
    "q1,weno3,cweno,cwenoz, or lsq-q1: the thesis's chapter 5 least squares (5.5) (default q1,weno3,lsq-q1)");
  app.add_option("--threads", args.Threads, "threads (0: all hardware threads)")->capture_default_str();
  app.add_option("--kp", args.OutsideFactor, "K_P: the initial sphere's margin beyond the farthest point, in h_P")
    ->capture_default_str();
  app.add_flag("--per-iteration", args.PerIteration,
    "every iteration's E_p, Err_P, stored nodes and octree leaves (Fig. 5.7, 5.14)");
  app.add_option("--tables", args.Tables, "thesis_tables.json")->capture_default_str();
  if (const auto code = parseCommandLine(app, argc, argv))
  {
    return *code;
  }
  if (!cases.empty())
  {
    args.Cases = splitList(cases);
  }
  if (!interps.empty())
  {
    args.Interps = splitList(interps);
  }
  const ThesisTables tables(args.Tables);
  const auto iterations = [&](const char* key) { return tables.numbers({ "ch5_amr", key }); };
  const double NaN = std::nan("");
  const auto firstNumber = [&](const std::vector<std::string>& keys)
  {
    const std::vector<double> values = tables.numbers(keys);
    return values.empty() ? NaN : values[0];
  };
  sltk::ThreadPool pool(args.Threads);
  sltk::Context ctx;
  ctx.Executor = &pool;
  for (const std::string& name : args.Cases)
  {
    if (name == "circle")
    {
      runCase<2>(
        name, sltk::circleCloud(64), [](const std::array<double, 2>& x) { return sltk::circleSdf(x); },
        iterations("circle_iterations"), firstNumber({ "ch5_amr", "circle_final", "E2" }),
        firstNumber({ "ch5_amr", "circle_final", "err_cloud" }), args, ctx);
    }
    else if (name == "square")
    {
      runCase<2>(name, sltk::rotatedSquareCloud(6), sltk::rotatedSquareSdf, iterations("square_iterations"), NaN, NaN,
        args, ctx);
    }
    else if (name == "heart")
    {
      runCase<2>(name, sltk::heartCloud(24), nullptr, iterations("heart_iterations"), NaN, NaN, args, ctx);
    }
    else if (name == "cubespheres")
    {
      sltk::CubeSpheres shape;
      runCase<3>(
        name, shape.cloud(2346), [shape](const std::array<double, 3>& x) { return shape.sdf(x); },
        iterations("cube_spheres_iterations"), NaN, NaN, args, ctx);
    }
    else
    {
      std::fprintf(stderr, "unknown case %s (circle, square, heart, cubespheres)\n", name.c_str());
      return 2;
    }
  }
  return 0;
}
