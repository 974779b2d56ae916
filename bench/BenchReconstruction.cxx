// SPDX-License-Identifier: BSD-3-Clause
/// \file BenchReconstruction.cxx
/// Algorithm 1 (thesis 4.3-4.5) on the data sets of 4.5.3-4.5.5, printed per
/// run next to the thesis's Tables 4.2-4.7 (read from thesis_tables.json).
///
/// Synthetic cases (exact signed distance known, clouds built in [-1, 1]^d as
/// in 4.5, so that the library's unit-box scale is 1):
///  - circle:      64 points at angles 2 pi k / 64 on the unit circle (4.5.3), 5 runs (Table 4.2);
///  - square:      24 points on the square |x| + |y| = 1 (rotated 45 degrees), its 4 corners
///                 and 5 equispaced points inside each side (h_P = sqrt(2) / 6), 5 runs (Table 4.3);
///  - sphere:      icosahedron subdivided 4 times, vertices projected on the unit sphere,
///                 10 * 4^4 + 2 = 2562 points, 3 runs (Table 4.4);
///  - cubespheres: cube of edge 0.8, a sphere of radius 0.25 centred at the middle of an edge and
///                 two of radius 0.15 at the two vertices of the opposite edge (4.5.4), rotated,
///                 sampled quasi-uniformly with 2346 points, rescaled to [-1, 1]^3, 3 runs (Table 4.5).
///
/// L1 error (4.5.1; the text gives no formula): the library's phi is cut at
/// +-gamma = +-4 dx (1.49)/(1.51), so the main column is
///   L1 = dx^d * sum over all nodes of |phi_j - cut(phi*(x_j))|, cut(s) = max(-gamma, min(gamma, s)),
/// and the second column restricts the sum to the band |phi*| < gamma
/// (no cut needed there). The per-run phi is obtained by calling reconstruct
/// with Runs = 1..R (the grids of run r do not depend on R: GridPlan.cxx).
///
/// E_2 of the exact shape (4.1) is printed for circle, square and sphere (fine
/// quadrature of the exact curve/surface, brute-force d_P): the thesis quotes
/// about 7.10e-2 for the circle (4.5.3), the limit our runs should approach.
///
/// Real scans (4.5.5; --scans): energies and Err_P converted to the unit box
/// of 4.5 (scale s = half the largest bounding-box extent: Err_P / s,
/// E_2 / s^((d+1)/2), the library's own conversion in Reconstruction.cxx).
///
/// This is a benchmark: it prints tables, never pass/fail. Each comparison
/// prints ours/thesis and a factor-1.5 verdict: "within" (1/1.5 <= ratio <= 1.5),
/// "better"/"worse" for errors, "lower"/"higher" for energies.
///
/// Usage: sltkBenchReconstruction [--case NAME[,NAME...]] [--interp q1,weno3,cweno,cwenoz]
///          [--threads N] [--tables PATH] [--data DIR] [--scans] [--cdx C] [--kp K] [--runs R]
///          [--noise SIGMA] [--tolerance T] [--final-only] [--padding P] [--log]
///   default cases: circle,square,sphere,cubespheres; also noisycircle, noisysphere (10% noise, larger
///   final eta; --noise sets sigma, default 0.1 = 10% of the radius);
///   --scans: bunny,teapot,fandisk,knot,knotellipse,frog
///   --tolerance: threshold of the stopping rule (4.33), default 1e-4
///   --final-only: synthetic cases run once with R runs (L1 of the last run only; half the work for R = 3)
///   default interpolators: q1,weno3,cweno in 2D, q1,weno3 in 3D and for the scans
///   --log prints the library's per-run phase times (the context's logger)
///   --padding: cells of padding per side of the synthetic cases (library default 10; the thesis's square grids are
///   padding 8)
///
/// The clouds, exact distances and quadratures are Core's (sltk/cloud/SyntheticClouds.h); the
/// tables are printed by reconstruction/Synthetic.cxx and reconstruction/Scans.cxx.

#include "common/BenchCli.h"
#include "common/PrintLogger.h"
#include "common/ThesisTables.h"
#include "reconstruction/Options.h"
#include "reconstruction/Report.h"
#include "reconstruction/Scans.h"
#include "reconstruction/Synthetic.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/exec/Context.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/recon/Reconstruction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace sltkbench;

const double NaN = std::nan("");

/// The exact signed distances of the unit circle and sphere.
double unitCircleSdf(const std::array<double, 2>& x)
{
  return sltk::circleSdf(x);
}

double unitSphereSdf(const std::array<double, 3>& x)
{
  return sltk::sphereSdf(x);
}

/// Table 4.1 for runs 1 and 2, then eta = `finalEta` from run 3 on (the noisy
/// tests raise eta in the last run only: Fig. 4.8, Fig. 4.11).
std::vector<sltk::RunParameters> scheduleWithFinalEta(double finalEta)
{
  return { sltk::table41(1), sltk::table41(2), { 2.0, finalEta } };
}

/// The scans of 4.5.4-4.5.5 (--scans): file, thesis table, title, C_dx, K_P, initial guess,
/// iteration limit and the note printed with the table.
const std::vector<ScanCase>& scanCases()
{
  constexpr auto marking = sltk::InitialGuess::OutsideMarking;
  constexpr auto ellipsoid = sltk::InitialGuess::BoundingEllipsoid;
  // The notes of the clouds that are not the thesis's.
  constexpr const char* teapot = "(3644-point mesh vertices; thesis cloud unknown) ";
  constexpr const char* fandisk =
    "(substitute for the 4102-point mechanical part: final Err_P Q1 7.59e-03, WENO 3.74e-03) ";
  constexpr const char* knot = "(CGAL knot1, 3200 points; thesis 10000-point knot: 61/23/10 iterations) ";
  constexpr const char* knotEllipse = "(ellipsoid guess; thesis: 120/24/14 iterations) ";
  constexpr const char* frog = "(5429 points, not the thesis's 2512-point frog) ";
  static const std::vector<ScanCase> cases = {
    // 4.5.5 / Table 4.7: C_dx = 2, K_P = 10 (holes in the bottom).
    { "bunny", "bunny/bunny.xyz", "table_4_7_bunny_35947pts", "Bunny", 2.0, 10.0, marking, 100, "" },
    // teapot.obj is an open surface (1036 boundary edges): with K_P = 2 the outside marking
    // leaks inside and the WENO run 3 loses its front; K_P = 10 as for the thesis's scans with holes.
    { "teapot", "teapot/teapot.xyz", "", "Teapot", 1.0, 10.0, marking, 100, teapot },
    // 4.5.4 "mechanical part": the thesis's 4102-point cloud is not available; fandisk is a substitute.
    { "fandisk", "fandisk/fandisk.xyz", "", "Mechanical part", 1.0, 2.0, marking, 100, fandisk },
    // 4.5.4: C_dx = 2, K_P = 10, usual initial data (thesis: 61, 23, 10 iterations, 10000 points).
    { "knot", "knot/knot1.xyz", "", "Knot", 2.0, 10.0, marking, 100, knot },
    // 4.5.4: ellipsoid initial guess, at most 200 iterations (thesis: 120, 24, 14 iterations).
    { "knotellipse", "knot/knot1.xyz", "", "Knot (ellipse)", 2.0, 10.0, ellipsoid, 200, knotEllipse },
    // 4.5.5 / Table 4.6: K_P = 10 (the thesis's frog has 2512 points; ours 5429, another scan).
    { "frog", "frog/frog.xyz", "table_4_6_frog_2512pts", "Frog", 1.0, 10.0, marking, 100, frog },
  };
  return cases;
}

/// The scan named `name`, or null when it is not one.
const ScanCase* findScan(const std::string& name)
{
  const auto& cases = scanCases();
  const auto it = std::find_if(cases.begin(), cases.end(), [&](const ScanCase& c) { return c.Name == name; });
  return it == cases.end() ? nullptr : &*it;
}

} // namespace

int main(int argc, char** argv)
{
  ReconstructionBenchOptions args;
  std::vector<std::string> cases;
  std::string interps;
  CLI::App app("SLTK reconstruction benchmark (thesis Algorithm 1, Tables 4.2-4.9); see the header of "
               "bench/BenchReconstruction.cxx",
    "sltkBenchReconstruction");
  takeLastByDefault(app);
  app
    .add_option("--case", cases,
      "cases, comma-separated or repeated; synthetic: circle square sphere cubespheres (default), noisycircle "
      "noisysphere; scans (--scans): bunny teapot fandisk knot knotellipse frog")
    ->delimiter(',')
    ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--interp", interps, "q1,weno3,cweno,cwenoz (default q1,weno3,cweno in 2D, q1,weno3 in 3D)");
  app.add_option("--threads", args.Threads, "executor size (at least 1)");
  app.add_option("--tables", args.Tables, "thesis_tables.json")->capture_default_str();
  app.add_option("--data", args.Data, "directory of the scans")->capture_default_str();
  app.add_flag("--scans", args.Scans, "the real scans of 4.5.5 instead of the synthetic cases");
  app.add_option("--cdx", args.Cdx, "C_dx (default 1; scans: per case)");
  app.add_option("--kp", args.Kp, "K_P (default 2; scans: per case)");
  app.add_option("--runs", args.Runs, "runs R (default per case)");
  app.add_option("--noise", args.Noise, "sigma of the noisy cases")->capture_default_str();
  app.add_option("--tolerance", args.Tolerance, "threshold of the stopping rule (4.33) (default 1e-4)");
  app.add_flag("--final-only", args.FinalOnly, "synthetic cases: one R-run call, L1 of the last run only");
  app.add_option("--padding", args.Padding, "cells of padding per side of the synthetic cases (default 10)");
  app.add_flag("--log", args.Log, "print the library's per-run phase times");
  if (const auto exit = parseCommandLine(app, argc, argv))
  {
    return *exit;
  }
  args.Threads = std::max(1, args.Threads);
  for (const std::string& c : cases)
  {
    if (!c.empty())
    {
      args.Cases.push_back(c);
    }
  }
  args.Interps = splitList(interps);
  if (args.Cases.empty())
  {
    args.Cases = args.Scans ? std::vector<std::string>{ "bunny", "teapot", "fandisk", "knot", "knotellipse", "frog" }
                            : std::vector<std::string>{ "circle", "square", "sphere", "cubespheres" };
  }
  const ThesisTables thesis(args.Tables);
  std::printf("SLTK reconstruction benchmark (thesis Algorithm 1, Tables 4.2-4.9); threads %d; thesis tables: %s\n",
    args.Threads, thesis.loaded() ? args.Tables.c_str() : "not found (comparison columns left empty)");
  sltk::ThreadPool pool(args.Threads);
  sltk::Context ctx;
  ctx.Executor = args.Threads > 1 ? &pool : nullptr;
  PrintLogger logger; // --log: the per-run phase times (distance, initial data, energy, SL step, reinit, metrics)
  if (args.Log)
  {
    ctx.Log = &logger;
  }
  const std::vector<std::string> interps2 =
    args.Interps.empty() ? std::vector<std::string>{ "q1", "weno3", "cweno" } : args.Interps;
  const std::vector<std::string> interps3 =
    args.Interps.empty() ? std::vector<std::string>{ "q1", "weno3" } : args.Interps;
  for (const std::string& name : args.Cases)
  {
    if (name == "circle")
    {
      // Table 4.2: five runs (grids 42 ... 344), Table 4.1 schedule.
      // 4.5.3: "64 points uniformly chosen on a circle of radius 1" (h_P = 2 sin(pi/64) = 0.0981).
      const auto cloud = sltk::circleCloud(64);
      runSynthetic<2>({ name, "table_4_2_circle_64pts", "Table 4.2 circle", cloud, unitCircleSdf, 5,
                        sltk::shapeEnergy<2>(cloud, sltk::circleQuadrature(64000)) },
        interps2, args, thesis, ctx);
    }
    else if (name == "square")
    {
      // Table 4.3: five runs (grids 30 ... 153).
      const auto cloud = sltk::rotatedSquareCloud(6);
      runSynthetic<2>({ name, "table_4_3_square_24pts", "Table 4.3 square rotated 45 degrees", cloud,
                        sltk::rotatedSquareSdf, 5, sltk::shapeEnergy<2>(cloud, sltk::rotatedSquareQuadrature(16000)) },
        interps2, args, thesis, ctx);
    }
    else if (name == "noisycircle")
    {
      // Fig. 4.8: 10% noise, WENO, eta raised in the final run; eta = 5 gave the best L1 error,
      // eta = 35 degenerates. Errors against the exact circle's SDF.
      for (const double eta : { 1.0, 5.0, 10.0, 35.0 })
      {
        runSynthetic<2>({ name, "", "Fig. 4.8 circle, 10% noise, final eta = " + fmt(eta),
                          sltk::withGaussianNoise(sltk::circleCloud(64), args.Noise, 2024), unitCircleSdf, 3, NaN },
          interps2, args, thesis, ctx, scheduleWithFinalEta(eta));
      }
    }
    else if (name == "noisysphere")
    {
      // Fig. 4.11 second row: 10% noise, eta = 10 in the last run (and eta = 1 for comparison).
      for (const double eta : { 1.0, 10.0 })
      {
        runSynthetic<3>({ name, "", "Fig. 4.11 sphere, 10% noise, final eta = " + fmt(eta),
                          sltk::withGaussianNoise(sltk::icosphereCloud(4), args.Noise, 2024), unitSphereSdf, 3, NaN },
          interps3, args, thesis, ctx, scheduleWithFinalEta(eta));
      }
    }
    else if (name == "sphere")
    {
      // Table 4.4: the usual three runs on the 2562-point icosphere.
      runSynthetic<3>(
        { name, "table_4_4_sphere_2562pts", "Table 4.4 sphere (icosphere, 4 subdivisions)", sltk::icosphereCloud(4),
          unitSphereSdf, 3, sltk::shapeEnergy<3>(sltk::icosphereCloud(4), sltk::sphereQuadrature(40000)) },
        interps3, args, thesis, ctx);
    }
    else if (name == "cubespheres")
    {
      sltk::CubeSpheres shape;
      sltk::PointCloud<3> cloud = shape.cloud(2346); // 4.5.4: 2346 points
      runSynthetic<3>({ name, "table_4_5_cube_spheres_2346pts", "Table 4.5 Cube&Spheres", std::move(cloud),
                        [shape](const std::array<double, 3>& x) { return shape.sdf(x); }, 3, NaN },
        interps3, args, thesis, ctx);
    }
    else if (const ScanCase* scan = findScan(name))
    {
      runScan(*scan, interps3, args, thesis, ctx);
    }
    else
    {
      std::printf("unknown case %s (see --help)\n", name.c_str());
      return 2;
    }
  }
  return 0;
}
