// SPDX-License-Identifier: BSD-3-Clause
// `sltk reconstruct CLOUD`: vtkSLLevelSetReconstruct from a terminal.
#include "Commands.h"
#include "ErrorCollector.h"
#include "Json.h"
#include "ProgressBar.h"
#include "ReadPointCloud.h"
#include "RenderPng.h"
#include "SurfaceDistance.h"
#include "SurfacePieces.h"
#include "WriteAtomically.h"
#include "WriteSurface.h"

#include "sltk/exec/Memory.h"
#include "sltk/interp/InterpolatorKind.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <vtkDataArray.h>
#include <vtkDelimitedTextWriter.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSLLevelSetReconstruct.h>
#include <vtkTable.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <vector>

namespace sltkcli
{

namespace
{
const char* reconstructUsage = R"(usage: sltk reconstruct CLOUD [options]

Reconstructs a watertight surface from an unorganised point cloud with the
semi-Lagrangian level-set method (Preda 2024, Algorithm 1 with the multi-run
schedule of Table 4.1). Clouds with no z extent are reconstructed in 2D.

options:
  -o, --output FILE.vti   signed distance (and distance to the cloud) on the grid
  --surface FILE          zero level set: .vtp, .ply, .stl (3D) or .vtp (2D)
  --png FILE              a picture of the surface and the cloud (renders through X: xvfb-run -a without a display)
  --csv FILE              convergence history (run, iteration, energy, change, cloud error, band, time)
  --json FILE             summary: points, points_reconstructed, outliers_removed, seconds, peak_memory_mb,
                          surface_pieces, euler_characteristic, runs [grid, iterations, energy, err_cloud]
  --interpolator NAME     q1 | weno3 | cweno | cwenoz (default weno3)
  --cdx C                 C_dx of (4.36): first-run cell size in units of h_P (default 1)
  --kp K                  K_P: initial surface at K h_P from the cloud (default 2; 10 for scans with holes)
  --runs R                runs, each halving the cell size (default 3)
  --max-iterations N      iteration cap per run (default 100)
  --initial NAME          outside | sphere | ellipsoid (default outside)
  --eta E                 eta of runs >= 3 (Table 4.1: 1); larger smooths noisy scans (thesis Fig. 4.8)
  --schedule P:E,P:E,...  p and eta of each run (4.9); the last pair holds for later runs (default Table 4.1:
                          1:0.05,2:0.05,2:1); the thesis's teapot keeps details with 1:0,2:0,2:1
  --detect-tunnels        follow grad phi through long narrow holes instead of plugging them (4.5.6)
  --remove-outliers       drop points whose mean distance to 8 neighbours is above mean + S sigma
  --outlier-sigma S       the S of --remove-outliers (default 3)
  --thin F                average the points in voxels of F x the density spacing (merged, overlapping
                          scans: h_P (4.36) is then taken on the thinned cloud); 0 = off (default)
  --threads T             threads (default: all)
  --reference MESH        add Chamfer and Hausdorff distances to a reference surface (.off .ply .obj .stl .vtp)
                          to the summary: Chamfer = (mean d(result->ref) + mean d(ref->result)) / 2
  --quiet                 no progress bar
  --verbose               the solver's log (cleaning counts, grids, per-run phase times) on stderr
)";

/// "P:E,P:E,..." -> one (p, eta) per run; false when malformed.
bool parseSchedule(const std::string& text, std::vector<sltk::RunParameters>& schedule)
{
  std::stringstream in(text);
  std::string pair;
  while (std::getline(in, pair, ','))
  {
    const size_t colon = pair.find(':');
    if (colon == std::string::npos)
    {
      return false;
    }
    try
    {
      size_t usedP = 0;
      size_t usedEta = 0;
      const std::string p = pair.substr(0, colon);
      const std::string eta = pair.substr(colon + 1);
      schedule.push_back({ std::stod(p, &usedP), std::stod(eta, &usedEta) });
      if (usedP != p.size() || usedEta != eta.size())
      {
        return false;
      }
    }
    catch (const std::exception&)
    {
      return false;
    }
  }
  return !schedule.empty();
}

} // namespace

int commandReconstruct(const Args& rawArgs)
{
  Args args = rawArgs;
  for (auto& a : args)
  {
    a = a == "-o" ? "--output" : a;
  }
  Options opt(args,
    { "output", "surface", "csv", "json", "interpolator", "cdx", "kp", "runs", "max-iterations", "initial", "threads",
      "reference", "png", "eta", "outlier-sigma", "thin", "schedule" },
    { "help", "quiet", "remove-outliers", "verbose", "detect-tunnels" });
  if (opt.has("help"))
  {
    std::cout << reconstructUsage;
    return 0;
  }
  const double cdx = opt.number("cdx", 1.0);
  const double kp = opt.number("kp", 2.0);
  const double runs = opt.number("runs", 3);
  const double iterations = opt.number("max-iterations", 100);
  const double threads = opt.number("threads", 0);
  const double eta = opt.number("eta", 1.0);
  const double sigma = opt.number("outlier-sigma", 3.0);
  const double thin = opt.number("thin", 0.0);
  if (!opt.ok())
  {
    return fail(opt.error(), 2);
  }
  if (opt.positional().size() != 1)
  {
    return fail("give exactly one point cloud file (see sltk reconstruct --help)", 2);
  }
  sltk::InterpolatorKind interpolator = sltk::InterpolatorKind::Weno3;
  if (opt.has("interpolator") && !sltk::parseInterpolator(opt.value("interpolator"), interpolator))
  {
    return fail("unknown interpolator '" + opt.value("interpolator") + "': use " + sltk::interpolatorNameList(), 2);
  }
  sltk::InitialGuess guess = sltk::InitialGuess::OutsideMarking;
  if (!parseInitialGuess(opt.value("initial", "outside"), guess))
  {
    return fail("unknown initial guess '" + opt.value("initial") + "': use outside, sphere or ellipsoid", 2);
  }
  if (!(cdx >= 0.05 && cdx <= 100) || !(kp >= 0.1 && kp <= 100) || runs < 1 || runs > 6 || iterations < 1 ||
    threads < 0)
  {
    return fail("out of range: --cdx 0.05..100, --kp 0.1..100, --runs 1..6, --max-iterations >= 1, --threads >= 0", 2);
  }
  if (!(eta >= 0 && eta <= 100) || !(sigma >= 0.5 && sigma <= 100) || !(thin >= 0 && thin <= 100))
  {
    return fail("out of range: --eta 0..100, --outlier-sigma 0.5..100, --thin 0..100", 2);
  }
  std::vector<sltk::RunParameters> schedule;
  if (opt.has("schedule"))
  {
    if (!parseSchedule(opt.value("schedule"), schedule))
    {
      const std::string text = opt.value("schedule");
      return fail("malformed --schedule '" + text + "': give p:eta pairs separated by commas, e.g. 1:0,2:0,2:1", 2);
    }
    const sltk::Status valid = sltk::validateSchedule(schedule);
    if (!valid.isOk())
    {
      return fail("--schedule: " + valid.message(), 2);
    }
    if (opt.has("eta"))
    {
      return fail("give either --eta or --schedule (a schedule sets eta of every run)", 2);
    }
  }
  if (opt.has("outlier-sigma") && !opt.has("remove-outliers"))
  {
    return fail("--outlier-sigma needs --remove-outliers", 2);
  }
  if (opt.has("surface"))
  {
    const std::string problem = surfaceFormatProblem(opt.value("surface"));
    if (!problem.empty())
    {
      return fail(problem, 2);
    }
  }

  if (opt.has("png"))
  {
    const std::string problem = pngProblem(opt.value("png"));
    if (!problem.empty())
    {
      return fail(problem, 2);
    }
  }

  vtkNew<vtkPolyData> reference;
  if (opt.has("reference"))
  {
    const sltk::Status read = readMesh(opt.value("reference"), reference);
    if (!read.isOk())
    {
      return fail(read.message());
    }
  }

  const auto start = std::chrono::steady_clock::now();
  const std::string path = opt.positional()[0];
  vtkSmartPointer<vtkPointSet> cloud;
  sltk::Status status = readPointCloud(path, cloud);
  if (!status.isOk())
  {
    return fail(status.message());
  }
  if (opt.has("verbose"))
  {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_INFO);
  }
  vtkNew<vtkSLLevelSetReconstruct> filter;
  vtkNew<ErrorCollector> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<ProgressBar> bar;
  if (!opt.has("quiet"))
  {
    filter->AddObserver(vtkCommand::ProgressEvent, bar);
  }
  filter->SetInputData(cloud);
  filter->SetInterpolator(static_cast<int>(interpolator));
  filter->SetCellSizeFactor(cdx);
  filter->SetOutsideThresholdFactor(kp);
  filter->SetNumberOfRuns(static_cast<int>(runs));
  filter->SetMaximumNumberOfIterations(static_cast<int>(iterations));
  filter->SetInitialGuess(static_cast<int>(guess));
  filter->SetNumberOfThreads(static_cast<int>(threads));
  filter->SetFinalEta(eta);
  for (const sltk::RunParameters& run : schedule)
  {
    filter->AddRunParameters(run.P, run.Eta);
  }
  filter->SetRemoveOutliers(opt.has("remove-outliers"));
  filter->SetOutlierDeviations(sigma);
  filter->SetThinningFactor(thin);
  filter->SetDetectTunnels(opt.has("detect-tunnels"));
  filter->Update();
  bar->finish();
  if (!errors->Message.empty())
  {
    return fail(
      path + ": " + withMergedScanHint(errors->Message, static_cast<size_t>(cloud->GetNumberOfPoints()), thin > 0));
  }
  auto* image = vtkImageData::SafeDownCast(filter->GetOutputDataObject(0));
  auto* surface = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(1));
  auto* history = vtkTable::SafeDownCast(filter->GetOutputDataObject(2));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double peakMb = static_cast<double>(sltk::peakResidentBytes()) / 1e6;

  // Summary table.
  vtkFieldData* fd = image->GetFieldData();
  auto* grids = fd->GetArray("RunGridDimensions");
  auto* its = fd->GetArray("RunIterations");
  auto* energy = fd->GetArray("RunEnergy");
  auto* cloudError = fd->GetArray("RunCloudError");
  auto* runSeconds = fd->GetArray("RunSeconds");
  std::printf("cloud      %s (%lld points, h_P = %.6g)\n", path.c_str(),
    static_cast<long long>(cloud->GetNumberOfPoints()), fd->GetArray("CloudSpacing")->GetTuple1(0));
  const auto fieldValue = [fd](const char* name) { return fd->GetArray(name)->GetTuple1(0); };
  const long long reconstructed = static_cast<long long>(fieldValue("ReconstructedPoints"));
  const long long outliers = static_cast<long long>(fieldValue("OutliersRemoved"));
  if (opt.has("remove-outliers") || thin > 0.0)
  {
    std::printf("cleaning   %lld outliers removed, thinning cell %.4g: %lld points reconstructed\n", outliers,
      fieldValue("ThinningCell"), reconstructed);
  }
  std::printf("\n run            grid   iterations      energy E_2     Err_P        time\n");
  std::vector<JsonObject> runRecords;
  for (vtkIdType r = 0; r < grids->GetNumberOfTuples(); ++r)
  {
    const double* g = grids->GetTuple3(r);
    std::printf("%4lld  %5.0f x %4.0f x %4.0f  %6.0f  %14.6g  %10.4g  %8.2f s\n", static_cast<long long>(r + 1), g[0],
      g[1], g[2], its->GetTuple1(r), energy->GetTuple1(r), cloudError->GetTuple1(r), runSeconds->GetTuple1(r));
    runRecords.push_back(JsonObject()
                           .add("run", static_cast<long long>(r + 1))
                           .add("grid",
                             std::vector<long long>{ static_cast<long long>(g[0]), static_cast<long long>(g[1]),
                               static_cast<long long>(g[2]) })
                           .add("iterations", static_cast<long long>(its->GetTuple1(r)))
                           .add("energy", energy->GetTuple1(r))
                           .add("err_cloud", cloudError->GetTuple1(r))
                           .add("seconds", runSeconds->GetTuple1(r)));
  }
  const double hP = fd->GetArray("CloudSpacing")->GetTuple1(0);
  const double finalError =
    cloudError->GetNumberOfTuples() ? cloudError->GetTuple1(cloudError->GetNumberOfTuples() - 1) : 0.0;
  if (finalError > 2.0 * hP)
  {
    std::fprintf(stderr,
      "sltk: warning: the surface ends %.1f h_P from the cloud on average: it did not reach the points; try a "
      "larger --kp (scans with holes), a smaller --cdx or --initial sphere\n",
      finalError / hP);
  }
  const SurfaceTopology topology = surfaceTopology(surface);
  std::printf("\nsurface    %lld points, %lld cells, %lld piece(s), Euler characteristic %lld\n",
    static_cast<long long>(surface->GetNumberOfPoints()), static_cast<long long>(surface->GetNumberOfCells()),
    topology.Pieces, topology.Euler);
  std::printf("total      %.2f s, peak memory %.0f MB\n", seconds, peakMb);
  SurfaceDistances distances;
  if (opt.has("reference"))
  {
    status = surfaceDistances(surface, reference, distances);
    if (!status.isOk())
    {
      return fail(status.message());
    }
    std::printf("reference  Chamfer %.4g, Hausdorff %.4g (mean to reference %.4g, from reference %.4g)\n",
      distances.Chamfer, distances.Hausdorff, distances.MeanToReference, distances.MeanFromReference);
  }

  if (opt.has("output"))
  {
    status = writeImage(opt.value("output"), image);
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  if (opt.has("surface"))
  {
    status = writeSurface(opt.value("surface"), surface);
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  if (opt.has("png"))
  {
    status = renderPng(opt.value("png"), surface, cloud);
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  if (opt.has("csv"))
  {
    status = writeAtomically(opt.value("csv"),
      [&](const std::string& temporary)
      {
        vtkNew<vtkDelimitedTextWriter> writer;
        writer->SetInputData(history);
        writer->SetFileName(temporary.c_str());
        writer->SetFieldDelimiter(",");
        writer->SetUseStringDelimiter(false);
        return writer->Write() == 1;
      });
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  if (opt.has("json"))
  {
    JsonObject summary;
    summary.add("cloud", path)
      .add("points", static_cast<long long>(cloud->GetNumberOfPoints()))
      .add("outliers_removed", outliers)
      .add("thinning_cell", fieldValue("ThinningCell"))
      .add("points_reconstructed", reconstructed)
      .add("h_P", fd->GetArray("CloudSpacing")->GetTuple1(0))
      .add("seconds", seconds)
      .add("peak_memory_mb", peakMb)
      .add("surface_points", static_cast<long long>(surface->GetNumberOfPoints()))
      .add("surface_pieces", topology.Pieces)
      .add("euler_characteristic", topology.Euler)
      .add("runs", runRecords);
    if (opt.has("reference"))
    {
      summary.add("reference", opt.value("reference"))
        .add("chamfer", distances.Chamfer)
        .add("hausdorff", distances.Hausdorff);
    }
    status = writeTextFile(opt.value("json"), summary.str() + "\n");
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  return 0;
}

} // namespace sltkcli
