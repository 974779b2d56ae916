// SPDX-License-Identifier: GPL-2.0-or-later
/// \file BenchP4estCellCentred.cxx
/// The thesis's chapter 5 tests (5.3: the circle of 64 points, the square of
/// 24, the heart of 24, Cube&Spheres of 2346) with the thesis's own
/// cell-centred scheme on a p4est quadtree or p8est octree
/// (sltk/p4est/CellCentredReconstruction.h), side by side with the tiled
/// band that the library's octree output uses, with the thesis's least
/// squares Q1 as its interpolation (sltkBenchChapter5 compares the tiled
/// band's interpolators). Parameters as
/// sltkBenchChapter5: run 1's finest cell Delta_P / 2^L0 (5.10)-(5.11), one
/// level more per run, dt = Delta x_min (5.12), a circle K_P = 2 spacings
/// beyond the farthest point as initial data, Table 4.1's p and eta, the
/// stopping rule (4.33) alone, no cleaning.
///
/// Per case it prints, for both schemes, each run's iterations against the
/// thesis's (issue 14: within +-50%), E_2 and Err_P, the leaves of the tree
/// against the uniform grid of the same finest cell (Fig. 5.7), the L1 error
/// of phi against the exact signed distance over |d| < gamma where the shape
/// is known, and for the cell-centred scheme the jumps of its zero level set
/// between neighbouring leaves (5.3.1, "noticeably disconnected").
///
/// Under `mpiexec -n N` both schemes run on N ranks (the cell-centred
/// scheme's leaves are gathered for the L1 and the seams); rank 0 prints.
///
/// Usage: sltkBenchP4estCellCentred [--case circle,square,heart,cubespheres] [--threads N] [--kp K_P] [--log]
///                                   [--per-iteration] [--tables thesis_tables.json] [--no-tiled]
///        sltkBenchP4estCellCentred --cloud bunny.xyz --cdx 2 --kp 10 [--runs R] (a scanned cloud: Err_P, seams)

#include "common/BenchCli.h"
#include "common/Chapter5.h"
#include "common/PrintLogger.h"
#include "common/ReadXyz.h"
#include "common/ThesisTables.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/exec/Context.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/mpi/MpiCommunicator.h"
#include "sltk/octree/TiledReconstruction.h"
#include "sltk/p4est/CellCentredReconstruction.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
using namespace sltkbench;
template <int D>
using Exact = std::function<double(const std::array<double, D>&)>;

struct Arguments
{
  std::vector<std::string> Cases{ "circle", "square", "heart", "cubespheres" };
  int Threads = 0;
  double OutsideFactor = 2.0;  ///< K_P: the initial circle's margin beyond the farthest point, in h_P
  std::string Cloud;           ///< --cloud: an .xyz cloud instead of the thesis's cases
  double CellSizeFactor = 0.0; ///< --cdx: run 1's cell C_dx h_P (4.36) instead of (5.10)-(5.11)
  int Runs = 3;
  bool PerIteration = false;
  bool Log = false;
  bool NoTiled = false; ///< --no-tiled: the cell-centred scheme alone
  std::string Tables = DefaultThesisTablesPath;
};

/// The L1 error of phi against the exact signed distance over the band
/// |d| < gamma, as sltkBenchChapter5 measures it on nodes (SdfErrors.h
/// l1Errors: the integral, in the user's units): each leaf's |phi - d| at
/// its centre times its volume.
template <int D>
double leafL1(const sltk::p4est::CellCentredResult<D>& r, const Exact<D>& exact, double gamma)
{
  const sltk::UnitBox<D>& box = r.Box;
  double band = 0.0;
  for (const auto& leaf : r.Leaves)
  {
    std::array<double, D> user;
    for (int a = 0; a < D; ++a)
    {
      user[a] = box.Centre[a] + box.Scale * leaf.Centre[a];
    }
    const double e = exact(user);
    if (std::fabs(e) < gamma * box.Scale)
    {
      band += std::fabs(box.Scale * leaf.Phi - e) * std::pow(box.Scale * leaf.Size, D);
    }
  }
  return band;
}

/// The cell-centred zero level set's gaps: between neighbouring leaves of
/// opposite signs, the jump of the two polynomials at the middle of the
/// centres, in cells of the finest level (mean, largest).
template <int D>
std::pair<double, double> cellSeams(const sltk::p4est::CellCentredResult<D>& r, double dx)
{
  // The finest leaves by their integer position; each one's neighbours along +x, +y (+z).
  using Key = std::array<long, D>;
  std::map<Key, size_t> finest;
  for (size_t i = 0; i < r.Leaves.size(); ++i)
  {
    if (r.Leaves[i].Size < 1.5 * dx)
    {
      Key at;
      for (int a = 0; a < D; ++a)
      {
        at[a] = std::lround((r.Leaves[i].Centre[a] - r.DomainOrigin[a]) / dx - 0.5);
      }
      finest[at] = i;
    }
  }
  double sum = 0.0, largest = 0.0;
  long count = 0;
  for (const auto& [at, i] : finest)
  {
    for (int axis = 0; axis < D; ++axis)
    {
      Key next = at;
      ++next[axis];
      const auto other = finest.find(next);
      if (other == finest.end())
      {
        continue;
      }
      const auto& a = r.Leaves[i];
      const auto& b = r.Leaves[other->second];
      if ((a.Phi < 0.0) == (b.Phi < 0.0))
      {
        continue;
      }
      std::array<double, D> mid;
      for (int c = 0; c < D; ++c)
      {
        mid[c] = 0.5 * (a.Centre[c] + b.Centre[c]);
      }
      const double jump = std::fabs(a.Polynomial.eval(mid) - b.Polynomial.eval(mid)) / dx;
      sum += jump;
      largest = std::max(largest, jump);
      ++count;
    }
  }
  return { count ? sum / count : 0.0, largest };
}

template <int D>
void printCellCentred(const sltk::p4est::CellCentredResult<D>& r, const std::vector<double>& thesis, bool perIteration)
{
  std::printf("  %3s %5s %6s %6s %-14s %11s %11s %10s %12s %7s\n", "run", "level", "iters", "thesis", "", "E_2",
    "Err_P", "leaves", "uniform", "");
  size_t h = 0;
  for (size_t k = 0; k < r.Runs.size(); ++k)
  {
    const auto& run = r.Runs[k];
    long long leaves = 0, uniform = 0;
    for (; h < r.History.size() && r.History[h].Run == run.Run; ++h)
    {
      leaves = r.History[h].Leaves;
      uniform = r.History[h].UniformCells;
    }
    const double t = k < thesis.size() ? thesis[k] : std::nan("");
    std::printf("  %3d %5d %6d %6s %-14s %11.4e %11.4e %10lld %12lld %6.1f%%\n", run.Run, run.Level, run.Iterations,
      formatValue(t, "%6.0f").c_str(), verdictWithinHalf(run.Iterations, t).c_str(), run.Energy, run.CloudError, leaves,
      uniform, uniform ? 100.0 * leaves / uniform : 0.0);
  }
  if (perIteration)
  {
    std::printf("  %3s %5s %11s %11s %10s %10s %12s\n", "run", "iter", "E_2", "Err_P", "leaves", "finest", "uniform");
    for (const auto& it : r.History)
    {
      std::printf("  %3d %5d %11.4e %11.4e %10lld %10lld %12lld\n", it.Run, it.Iteration, it.Energy, it.CloudError,
        static_cast<long long>(it.Leaves), static_cast<long long>(it.FinestLeaves),
        static_cast<long long>(it.UniformCells));
    }
  }
}

template <int D>
void runCase(const std::string& name, const sltk::PointCloud<D>& cloud, const Exact<D>& exact,
  const std::vector<double>& thesis, const Arguments& args, const sltk::Context& ctx, const sltk::Communicator& comm)
{
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.Runs = args.Runs;
  options.Guess = sltk::InitialGuess::BoundingSphere;
  options.OutsideThresholdFactor = args.OutsideFactor;
  options.OctreeStorage = true;
  options.Interpolator = sltk::InterpolatorKind::LeastSquaresQ1; // the tiled band with the thesis's interpolation (5.5)
  sltk::ReconstructionPlan<D> plan;
  sltk::Status status = sltk::planReconstruction(cloud, options, ctx, plan);
  Chapter5Grid level;
  if (status.isOk())
  {
    level = chapter5Grid(2.0, plan.CloudSpacing); // Delta_P = 2 in the unit box (4.5)
    if (args.CellSizeFactor > 0.0)
    {
      level.CellSizeFactor = args.CellSizeFactor;
      level.Level = static_cast<int>(std::ceil(std::log2(2.0 / (args.CellSizeFactor * plan.CloudSpacing))));
    }
    options.CellSizeFactor = level.CellSizeFactor;
    status = sltk::planReconstruction(cloud, options, ctx, plan);
  }
  if (!status.isOk())
  {
    std::printf("\n%s: planning failed: %s\n", name.c_str(), status.toString().c_str());
    return;
  }
  const double firstCell = level.CellSizeFactor * plan.CloudSpacing;
  std::printf("\n%s (%zu points): L0 = %d (Delta x_min of run 1 = %.5f = %.3g h_P)\n", name.c_str(),
    cloud.Points.size(), level.Level, firstCell, level.CellSizeFactor);

  sltk::p4est::CellCentredOptions cc;
  cc.FirstCellSize = firstCell;
  sltk::p4est::CellCentredResult<D> cell;
  auto start = std::chrono::steady_clock::now();
  status = sltk::p4est::reconstructCellCentred(plan, cc, ctx, cell, comm);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(" the thesis's cell-centred scheme on a p4est %s (edge %.0f), %d rank%s, %.2f s\n",
    D == 2 ? "quadtree" : "octree", cell.DomainEdge, comm.size(), comm.size() > 1 ? "s" : "", seconds);
  cell.Leaves = comm.allGatherV(cell.Leaves); // every rank's, in Morton order
  if (!status.isOk())
  {
    std::printf("  failed: %s\n", status.toString().c_str());
  }
  else
  {
    printCellCentred(cell, thesis, args.PerIteration);
    const double dx = cell.Runs.back().CellSize;
    if (exact)
    {
      std::printf("  L1 of phi against the exact signed distance over |d| < gamma: %.4e\n",
        leafL1<D>(cell, exact, options.GammaFactor * dx));
    }
    const auto seams = cellSeams<D>(cell, dx);
    std::printf("  zero level set drawn leaf by leaf: jumps of %.3g cells on average, %.3g at most, between finest "
                "neighbours of opposite signs\n",
      seams.first, seams.second);
  }

  if (args.NoTiled)
  {
    return;
  }
  sltk::TiledReconstructionResult<D> tiled;
  start = std::chrono::steady_clock::now();
  status = sltk::reconstructTiled(plan, ctx, tiled, comm);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(" the tiled band (node values, LSQ Q1 interpolation), %.2f s\n", seconds);
  if (!status.isOk())
  {
    std::printf("  failed: %s\n", status.toString().c_str());
    return;
  }
  for (size_t r = 0; r < tiled.Records.Runs.size(); ++r)
  {
    const auto& run = tiled.Records.Runs[r];
    const double t = r < thesis.size() ? thesis[r] : std::nan("");
    std::printf("  %3zu %5s %6d %6s %-14s %11.4e %11.4e\n", r + 1, "", run.Iterations, formatValue(t, "%6.0f").c_str(),
      verdictWithinHalf(run.Iterations, t).c_str(), run.Energy, run.CloudError);
  }
}

} // namespace

int main(int argc, char** argv)
{
  CLI::App app("The thesis's chapter 5 tests with its cell-centred scheme on a p4est tree");
  takeLastByDefault(app);
  Arguments args;
  std::string cases;
  app.add_option("--case", cases, "circle,square,heart,cubespheres (default all)");
  app.add_option("--threads", args.Threads, "threads (0: all hardware threads)")->capture_default_str();
  app.add_flag("--per-iteration", args.PerIteration, "every iteration's E_2, Err_P and leaves (Fig. 5.7)");
  app.add_option("--cloud", args.Cloud, "an .xyz cloud (3D) instead of the thesis's cases, e.g. the bunny");
  app.add_option("--cdx", args.CellSizeFactor, "run 1's cell as C_dx h_P (4.36) instead of (5.10)-(5.11)");
  app.add_option("--runs", args.Runs, "runs (the thesis's tests: 3)")->capture_default_str();
  app.add_option("--kp", args.OutsideFactor, "K_P: the initial circle's margin beyond the farthest point, in h_P")
    ->capture_default_str();
  app.add_flag("--log", args.Log, "the cell-centred scheme's progress, iteration by iteration");
  app.add_option("--tables", args.Tables, "thesis_tables.json")->capture_default_str();
  app.add_flag("--no-tiled", args.NoTiled, "the cell-centred scheme alone (no tiled band beside it)");
  if (const auto code = parseCommandLine(app, argc, argv))
  {
    return *code;
  }
  if (!cases.empty())
  {
    args.Cases = splitList(cases);
  }
  std::unique_ptr<sltk::mpi::MpiCommunicator> comm;
  sltk::Status mpi = sltk::mpi::ensureMpiInitialised();
  if (mpi.isOk())
  {
    mpi = sltk::mpi::MpiCommunicator::world(comm);
  }
  if (!mpi.isOk())
  {
    std::fprintf(stderr, "%s\n", mpi.toString().c_str());
    return 1;
  }
  if (comm->rank() != 0 && !std::freopen("/dev/null", "w", stdout)) // rank 0 prints
  {
    return 1;
  }
  const ThesisTables tables(args.Tables);
  const auto iterations = [&](const char* key) { return tables.numbers({ "ch5_amr", key }); };
  sltk::ThreadPool pool(args.Threads);
  sltk::Context ctx;
  ctx.Executor = &pool;
  PrintLogger logger(sltk::LogLevel::Debug);
  if (args.Log)
  {
    ctx.Log = &logger;
  }
  if (!args.Cloud.empty())
  {
    sltk::PointCloud<3> cloud;
    const bool read = readXyz(args.Cloud, cloud); // every rank reads it
    if (!comm->agree(read ? sltk::Status::ok() : sltk::Status::ioError("cannot read a cloud from " + args.Cloud))
           .isOk())
    {
      std::fprintf(stderr, "cannot read a cloud from %s (x y z per line)\n", args.Cloud.c_str());
      return 2;
    }
    runCase<3>(args.Cloud, cloud, nullptr, {}, args, ctx, *comm);
    return 0;
  }
  for (const std::string& name : args.Cases)
  {
    if (name == "circle")
    {
      runCase<2>(
        name, sltk::circleCloud(64), [](const std::array<double, 2>& x) { return sltk::circleSdf(x); },
        iterations("circle_iterations"), args, ctx, *comm);
    }
    else if (name == "square")
    {
      runCase<2>(
        name, sltk::rotatedSquareCloud(6), sltk::rotatedSquareSdf, iterations("square_iterations"), args, ctx, *comm);
    }
    else if (name == "heart")
    {
      runCase<2>(name, sltk::heartCloud(24), nullptr, iterations("heart_iterations"), args, ctx, *comm);
    }
    else if (name == "cubespheres")
    {
      sltk::CubeSpheres shape;
      runCase<3>(
        name, shape.cloud(2346), [shape](const std::array<double, 3>& x) { return shape.sdf(x); },
        iterations("cube_spheres_iterations"), args, ctx, *comm);
    }
    else
    {
      std::fprintf(stderr, "unknown case %s (circle, square, heart, cubespheres)\n", name.c_str());
      return 2;
    }
  }
  return 0;
}
