// SPDX-License-Identifier: BSD-3-Clause
// `sltk reconstruct CLOUD`: vtkSLLevelSetReconstruct from a terminal.
#include "CliOptions.h"
#include "Commands.h"
#include "ErrorCollector.h"
#include "FileNames.h"
#include "GatherSurface.h"
#include "MpiSession.h"
#include "OutputPaths.h"
#include "ProgressBar.h"
#include "ReadCloudShares.h"
#include "RenderPng.h"
#include "SLTKCommunicator.h"
#include "SurfaceDistance.h"
#include "SurfacePieces.h"
#include "TreeImage.h"
#include "WriteAtomically.h"
#include "WritePieces.h"
#include "WriteSurface.h"

#include "sltk/exec/CountingCommunicator.h"
#include "sltk/exec/Memory.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/interp/InterpolatorKind.h"
#include "sltk/recon/ReconstructionPlan.h"
#include "sltk/recon/ReconstructionSummary.h"

#include <vtkDelimitedTextWriter.h>
#include <vtkHyperTreeGrid.h>
#include <vtkImageData.h>
#include <vtkLogger.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkOctreeSDF.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSLLevelSetReconstruct.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTrivialProducer.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <vector>

namespace sltkcli
{

namespace
{
const char* reconstructDescription = R"(reconstruct a watertight surface (signed distance + surface)

Reconstructs a watertight surface from an unorganised point cloud with the
semi-Lagrangian level-set method (Preda 2024, Algorithm 1 with the multi-run
schedule of Table 4.1). Clouds with no z extent are reconstructed in 2D.
)";

/// The most points a rank's run read over the runs (RunFigures::PointsHeld).
template <class Runs>
long long runPointsHeld(const Runs& runs)
{
  long long most = 0;
  for (const auto& run : runs)
  {
    most = std::max(most, static_cast<long long>(run.PointsHeld));
  }
  return most;
}

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

/// "" or the problem of a --schedule.
std::string scheduleProblem(const std::string& text)
{
  std::vector<sltk::RunParameters> schedule;
  if (!parseSchedule(text, schedule))
  {
    return "expects p:eta pairs separated by commas, e.g. 1:0,2:0,2:1, got '" + text + "'";
  }
  const sltk::Status valid = sltk::validateSchedule(schedule);
  return valid.isOk() ? std::string() : valid.message();
}

/// `sltk reconstruct`'s command line.
struct Reconstruct
{
  CLI::App* Parser = nullptr;
  std::string Cloud, Output, Surface, Png, Csv, Json, Reference;
  sltk::ReconstructionOptions Options; ///< the flags' options, the filter's (SetOptions)
  int Threads = 0;
  bool Quiet = false;
  bool Verbose = false;
  bool given(const char* name) const { return this->Parser->count(name) > 0; }
  bool octree() const { return this->Options.OctreeStorage; } ///< --octree: runs 2..R stored as tiles
  std::string problemBeforeWork(bool pieces, vtkPolyData* reference, int& code) const;
  vtkSmartPointer<vtkSLLevelSetReconstruct> makeFilter(vtkPointSet* cloud) const;
  sltk::Status writeRankPieces(vtkDataObject* grid) const;
  /// `finest`: the last run's grid (nodes per axis), the image --octree writes as .vti.
  sltk::Status writeFiles(vtkDataObject* grid, const std::array<long long, 3>& finest, vtkPolyData* surface,
    vtkPointSet* cloud, vtkTable* history) const;
  int run() const;
};

/// The cloud, the automatic choices, the recoveries and the cleaning.
void printCloud(const sltk::ReconstructionSummary& summary, const std::string& path, vtkIdType points)
{
  std::printf(
    "cloud      %s (%lld points, h_P = %.6g)\n", path.c_str(), static_cast<long long>(points), summary.CloudSpacing);
  for (const std::string& choice : summary.Choices)
  {
    std::printf("automatic  %s\n", choice.c_str());
  }
  for (const std::string& recovery : summary.Recoveries)
  {
    std::printf("recovered  %s\n", recovery.c_str());
  }
  const sltk::CloudCleaningReport& cleaning = summary.Cleaning;
  if (cleaning.OutliersRemoved > 0 || cleaning.ThinningCell > 0.0)
  {
    std::printf("cleaning   %lld outliers removed, thinning cell %.4g: %lld points reconstructed\n",
      static_cast<long long>(cleaning.OutliersRemoved), cleaning.ThinningCell,
      static_cast<long long>(cleaning.OutputPoints));
  }
}

/// The surface's (or the curve's) size and topology, printed and returned.
SurfaceTopology printSurface(vtkPolyData* surface, bool planar)
{
  const SurfaceTopology topology = surfaceTopology(surface);
  if (planar)
  {
    std::printf("\ncurve      %lld points, %lld segments, %lld closed curve(s)\n",
      static_cast<long long>(surface->GetNumberOfPoints()), static_cast<long long>(surface->GetNumberOfCells()),
      topology.Pieces);
  }
  else
  {
    std::printf("\nsurface    %lld points, %lld cells, %lld piece(s), Euler characteristic %lld\n",
      static_cast<long long>(surface->GetNumberOfPoints()), static_cast<long long>(surface->GetNumberOfCells()),
      topology.Pieces, topology.Euler);
  }
  return topology;
}

/// The time, the peak memory and, under mpirun, the busiest rank's traffic.
void printTotals(double seconds, double peakMb, int ranks, const sltk::CommTraffic& traffic, bool octree)
{
  std::printf(ranks > 1 ? "total      %.2f s, peak memory %.0f MB (the largest rank's), %d ranks\n"
                        : "total      %.2f s, peak memory %.0f MB\n",
    seconds, peakMb, ranks);
  if (ranks > 1)
  {
    std::printf("traffic    %.1f MB sent by the busiest rank (%s), %.1f MB in %lld collective calls\n",
      static_cast<double>(traffic.PointToPointBytes) / 1e6,
      octree ? "ghost rows of run 1, then ghost tiles" : "ghost rows",
      static_cast<double>(traffic.CollectiveBytes) / 1e6, static_cast<long long>(traffic.Collectives));
  }
}

/// Warnings about the result: a surface that did not reach the cloud, and
/// Core's (points left far from it: features thinner than run 1's cell, with
/// advice that was not what just ran).
void warnAboutResult(const sltk::ReconstructionSummary& summary)
{
  const double hP = summary.CloudSpacing;
  const double finalError = summary.Runs.empty() ? 0.0 : summary.Runs.back().CloudError;
  if (finalError > 2.0 * hP && !summary.SeparateGroups) // else Core's warnings advise the groups' own runs
  {
    std::fprintf(stderr,
      "sltk: warning: the surface ends %.1f h_P from the cloud on average: it did not reach the points; try a "
      "larger --kp (scans with holes), a smaller --cdx or --initial sphere\n",
      finalError / hP);
  }
  for (const std::string& warning : summary.Warnings) // Core's: what did not fit, and what may help (not what just ran)
  {
    std::fprintf(stderr, "sltk: warning: %s\n", warning.c_str());
  }
}

/// --json's missed_places: where the last run misses points (MissedPlaces.h), in the user's coordinates.
nlohmann::ordered_json missedPlacesJson(const std::vector<sltk::MissedPlace<3>>& places)
{
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const sltk::MissedPlace<3>& place : places)
  {
    list.push_back(
      { { "points", static_cast<long long>(place.Points) }, { "nearby", static_cast<long long>(place.Nearby) },
        { "centre", place.Centre }, { "lower", place.Lower }, { "upper", place.Upper } });
  }
  return list;
}

/// The busiest rank's traffic (each count its largest over the ranks): the whole
/// reconstruction's first, then each run's (RunFigures::Traffic), then the plan's. One collective call.
std::vector<sltk::CommTraffic> busiestRankTraffic(const sltk::ReconstructionSummary& summary)
{
  std::vector<sltk::CommTraffic> phases = { summary.Traffic };
  for (const sltk::RunSummary& run : summary.Runs)
  {
    phases.push_back(run.Traffic);
  }
  phases.push_back(summary.PlanTraffic);    // last: the plan's
  std::unique_ptr<sltk::Communicator> comm; // the read made the same one: it cannot fail here
  return sltk::vtkbridge::makeCommunicator(nullptr, comm).isOk() ? sltk::busiestRanks(std::move(phases), *comm)
                                                                 : phases;
}

nlohmann::ordered_json trafficJson(const sltk::CommTraffic& t)
{
  return { { "bytes_sent_max", static_cast<long long>(t.PointToPointBytes) },
    { "collective_bytes_max", static_cast<long long>(t.CollectiveBytes) },
    { "collectives_max", static_cast<long long>(t.Collectives) } };
}

/// The runs' table on standard output and their records for --json; `runTraffic`: busiestRankTraffic().
nlohmann::ordered_json printRuns(
  const sltk::ReconstructionSummary& summary, int ranks, const std::vector<sltk::CommTraffic>& runTraffic)
{
  std::printf("\n run            grid   iterations      energy E_2     Err_P        time\n");
  nlohmann::ordered_json runRecords = nlohmann::ordered_json::array();
  long long number = 0;
  for (const sltk::RunSummary& run : summary.Runs)
  {
    const auto& g = run.GridDimensions;
    std::printf("%4lld  %5lld x %4lld x %4lld  %6d  %14.6g  %10.4g  %8.2f s\n", ++number, static_cast<long long>(g[0]),
      static_cast<long long>(g[1]), static_cast<long long>(g[2]), run.Iterations, run.Energy, run.CloudError,
      run.Seconds);
    runRecords.push_back({ { "run", number },
      { "grid", { static_cast<long long>(g[0]), static_cast<long long>(g[1]), static_cast<long long>(g[2]) } },
      { "iterations", static_cast<long long>(run.Iterations) }, { "energy", run.Energy },
      { "err_cloud", run.CloudError }, { "far_points", run.FarPoints }, { "misfit_points", run.MisfitPoints },
      { "merged_nodes", static_cast<long long>(run.MergedNodes) },
      { "points_held", static_cast<long long>(run.PointsHeld) }, { "seconds", run.Seconds } });
    if (ranks > 1)
    {
      const sltk::CommTraffic& t = runTraffic[static_cast<size_t>(number)]; // [0]: the whole reconstruction's
      runRecords.back()["ghost_rows"] = static_cast<long long>(run.GhostRows);
      runRecords.back()["far_feet"] = static_cast<long long>(run.FarFeet);
      runRecords.back()["bytes_sent_max"] = static_cast<long long>(t.PointToPointBytes);
      runRecords.back()["collective_bytes_max"] = static_cast<long long>(t.CollectiveBytes);
      runRecords.back()["collectives_max"] = static_cast<long long>(t.Collectives);
      std::printf("      traffic of the busiest rank: %.1f MB point to point, %.1f MB in %lld collective calls\n",
        static_cast<double>(t.PointToPointBytes) / 1e6, static_cast<double>(t.CollectiveBytes) / 1e6,
        static_cast<long long>(t.Collectives));
    }
    if (summary.OctreeStorage)
    {
      const double stored = static_cast<double>(run.StoredNodes), all = static_cast<double>(run.UniformNodes);
      std::printf("      stored %.0f of %.0f nodes (%.1f%%), %.0f octree leaves\n", stored, all, 100.0 * stored / all,
        static_cast<double>(run.Leaves));
      runRecords.back()["stored_nodes"] = static_cast<long long>(run.StoredNodes);
      runRecords.back()["uniform_nodes"] = static_cast<long long>(run.UniformNodes);
      runRecords.back()["leaves"] = static_cast<long long>(run.Leaves);
    }
  }
  return runRecords;
}

/// The problems found before any work: "" or the message, with its exit code
/// in `code`. The display (--png) and the reference mesh are checked and read
/// on rank 0 only, which alone uses them.
std::string Reconstruct::problemBeforeWork(bool pieces, vtkPolyData* reference, int& code) const
{
  const int ranks = MpiSession::size();
  code = 2;
  if (this->given("--eta") && this->given("--schedule"))
  {
    return "give either --eta or --schedule (a schedule sets eta of every run)";
  }
  const std::string paths =
    outputPathsProblem({ { "input cloud", this->Cloud }, { "--reference mesh", this->Reference } },
      { { "-o", this->Output, { "vti", "pvti", "htg", "phtg" } }, { "--surface", this->Surface, {} },
        { "--png", this->Png, { "png" } }, { "--csv", this->Csv, { "csv", "txt" } },
        { "--json", this->Json, { "json" } } });
  if (!paths.empty())
  {
    return paths;
  }
  const std::string extension = this->given("--output") ? extensionOf(this->Output) : "";
  const bool treeOutput = extension == "htg" || extension == "phtg";
  if (this->octree() && extension == "pvti")
  {
    return "--octree's ranks hold trees, not blocks of the grid: write -o as .phtg under mpirun (each rank its own "
           "trees), or as .vti on one rank (the uniform grid written from the trees piece by piece)";
  }
  if (!this->octree() && treeOutput)
  {
    return "-o FILE." + extension +
      " is --octree's output (a hyper tree grid): add --octree, or write the uniform grid as .vti "
      "(.pvti under mpirun)";
  }
  if (ranks > 1 && this->given("--output") && !pieces)
  {
    return this->octree()
      ? "under mpirun every rank holds only its own trees: write -o as .phtg (one piece per rank, FILE.phtg, "
        "FILE.vtm and FILE/FILE_<rank>.htg)"
      : "under mpirun every rank holds only its block of the grid: write -o as .pvti (one piece per rank, "
        "FILE.pvti and FILE/FILE_<rank>.vti)";
  }
  const std::string folder = pieces ? pieceFolderProblem(this->Output) : "";
  if (!folder.empty())
  {
    return folder;
  }
  if (MpiSession::rank() > 0)
  {
    return "";
  }
  if (this->given("--png"))
  {
    const std::string problem = pngProblem(this->Png);
    if (!problem.empty())
    {
      return problem;
    }
  }
  if (this->given("--reference"))
  {
    const sltk::Status read = readMesh(this->Reference, reference);
    code = 1;
    return read.isOk() ? "" : read.message();
  }
  return "";
}

/// VTK's threaded filters (flying edges, the surface's nearest cloud points) on as
/// many threads as Core's pool (sltk::threadsPerRank): the Debian build's default
/// backend is Sequential, which left both phases on one core. STDThread, unless the
/// user chose a backend by VTK_SMP_BACKEND_IN_USE; the surfaces are the same bytes.
void useVtkThreads(int requested)
{
  if (!std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  vtkSMPTools::Initialize(sltk::threadsPerRank(requested, controller ? controller->GetNumberOfProcesses() : 1));
}

/// The filter of the options: the octree's (vtkSLLevelSetReconstruct with
/// OctreeStorage always on) for --octree.
vtkSmartPointer<vtkSLLevelSetReconstruct> Reconstruct::makeFilter(vtkPointSet* cloud) const
{
  const vtkSmartPointer<vtkSLLevelSetReconstruct> filter = this->octree()
    ? vtkSmartPointer<vtkSLLevelSetReconstruct>(vtkSmartPointer<vtkOctreeSDF>::New())
    : vtkSmartPointer<vtkSLLevelSetReconstruct>::New();
  filter->SetInputData(cloud);
  filter->SetOptions(this->Options);                         // every flag of the plan is a field of Core's options
  filter->SetNumberOfThreads(this->Threads);                 // the filter shares the cores among the ranks
  useVtkThreads(this->Threads);                              // and VTK's own filters the same threads
  filter->SetGenerateHyperTreeGrid(this->given("--output")); // the trees only for -o FILE.htg
  return filter;
}

/// Under mpirun, -o as pieces: each rank's own trees (--octree) or its block of
/// the image at its place in the whole extent (the blocks are the solver's slabs).
sltk::Status Reconstruct::writeRankPieces(vtkDataObject* grid) const
{
  if (this->octree())
  {
    vtkNew<vtkTrivialProducer> producer; // each rank's own trees (the tiles it owns)
    producer->SetOutput(grid);
    return writeHyperTreeGridPieces(this->Output, producer, vtkMultiProcessController::GetGlobalController());
  }
  vtkNew<vtkImageData> block;
  block->ShallowCopy(grid);
  int extent[6];
  block->GetExtent(extent);
  for (int k = 0; k < 6; ++k)
  {
    extent[k] = static_cast<int>(k % 2 ? MpiSession::maxOverRanks(extent[k]) : -MpiSession::maxOverRanks(-extent[k]));
  }
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(block);
  producer->SetWholeExtent(extent);
  return writeImagePieces(this->Output, producer, vtkMultiProcessController::GetGlobalController());
}

/// The files rank 0 writes besides the summary: -o (unless written in pieces,
/// `grid` null then), --surface, --png and --csv.
sltk::Status Reconstruct::writeFiles(vtkDataObject* grid, const std::array<long long, 3>& finest, vtkPolyData* surface,
  vtkPointSet* cloud, vtkTable* history) const
{
  if (grid && this->given("--output"))
  {
    auto* trees = vtkHyperTreeGrid::SafeDownCast(grid);
    SLTK_RETURN_IF_ERROR(!this->octree()     ? writeImage(this->Output, vtkImageData::SafeDownCast(grid))
        : extensionOf(this->Output) == "vti" ? writeTreeImage(this->Output, trees, finest)
                                             : writeHyperTreeGrid(this->Output, trees));
  }
  if (this->given("--surface"))
  {
    SLTK_RETURN_IF_ERROR(writeSurface(this->Surface, surface));
  }
  if (this->given("--png"))
  {
    SLTK_RETURN_IF_ERROR(renderPng(this->Png, surface, cloud));
  }
  if (!this->given("--csv"))
  {
    return sltk::Status::ok();
  }
  return writeAtomically(this->Csv,
    [&](const std::string& temporary)
    {
      vtkNew<vtkDelimitedTextWriter> writer;
      writer->SetInputData(history);
      writer->SetFileName(temporary.c_str());
      writer->SetFieldDelimiter(",");
      writer->SetUseStringDelimiter(false);
      return writer->Write() == 1;
    });
}

int Reconstruct::run() const
{
  const int rank = MpiSession::rank(), ranks = MpiSession::size();
  const bool pieces =
    this->given("--output") && (extensionOf(this->Output) == "pvti" || extensionOf(this->Output) == "phtg");
  vtkNew<vtkPolyData> reference;
  int code = 0;
  const std::string problem = this->problemBeforeWork(pieces, reference, code);
  // Every rank stops together (a rank that stopped alone would leave the others waiting).
  const double worst = MpiSession::maxOverRanks(problem.empty() ? 0.0 : static_cast<double>(code));
  if (worst > 0.0)
  {
    return fail(
      problem.empty() ? "another rank stopped before the reconstruction (run on one rank to see why)" : problem,
      static_cast<int>(worst));
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string& path = this->Cloud;
  vtkSmartPointer<vtkPointSet> cloud;
  CloudReadCounts counts;
  // Each rank its share, planned where it is, or the whole cloud for --png to draw (ReadCloudShares.h).
  sltk::Status status = readCloudOnRanks(path, this->given("--png"), cloud, counts);
  const double readSeconds =
    MpiSession::maxOverRanks(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (MpiSession::maxOverRanks(status.isOk() ? 0.0 : 1.0) > 0.0) // every rank stops, none waits in the filter
  {
    return fail(status.isOk() ? path + ": another rank could not read the cloud" : status.message());
  }
  if (this->Verbose)
  {
    std::fprintf(stderr,
      "read       %lld points in %.3f s (parsed in %.3f s): at most %lld parsed and %lld held by a rank; "
      "%.1f MB in %lld collective calls by the busiest rank\n",
      counts.Total, readSeconds, counts.ParseSeconds, counts.ReadMax, counts.HeldMax,
      static_cast<double>(counts.Traffic.CollectiveBytes) / 1e6, static_cast<long long>(counts.Traffic.Collectives));
  }
  const double* bounds = counts.Bounds.data();                    // over every rank's share
  const bool planar = counts.Total > 0 && bounds[4] == bounds[5]; // reconstructed in 2D
  if (planar && this->given("--surface") && extensionOf(this->Surface) != "vtp")
  {
    return fail(path + " has no z extent, so its reconstruction is a curve, which " + extensionOf(this->Surface) +
        " cannot hold: write --surface as .vtp",
      2);
  }
  const std::string imprecise = this->given("--surface") ? surfacePrecisionProblem(this->Surface, bounds) : "";
  if (!imprecise.empty())
  {
    return fail(this->Surface + ": " + imprecise, 2);
  }
  if (this->Verbose)
  {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_INFO);
  }
  const vtkSmartPointer<vtkSLLevelSetReconstruct> filter = this->makeFilter(cloud);
  filter->SetCloudPiecesAreShares(counts.Shares);
  vtkNew<ErrorCollector> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<ProgressBar> bar;
  if (!this->Quiet)
  {
    filter->AddObserver(vtkCommand::ProgressEvent, bar);
  }
  if (ranks > 1)
  {
    filter->UpdatePiece(rank, ranks, 0); // each rank its slab (a collective update)
  }
  else
  {
    filter->Update();
  }
  bar->finish();
  if (!errors->Message.empty())
  {
    return fail(path + ": " +
      withMergedScanHint(
        errors->Message, static_cast<size_t>(counts.Total), this->Options.Cleaning.ThinningFactor > 0));
  }
  vtkDataObject* grid = filter->GetOutputDataObject(0); // the image, or --octree's hyper tree grid
  auto* history = vtkTable::SafeDownCast(filter->GetOutputDataObject(2));
  const double seconds =
    MpiSession::maxOverRanks(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  status = pieces ? this->writeRankPieces(grid) : sltk::Status::ok();
  if (!status.isOk())
  {
    return fail(status.message());
  }
  const double peakMb = MpiSession::maxOverRanks(static_cast<double>(sltk::peakResidentBytes()) / 1e6);
  // The filter's typed summary of this rank (its field data hold the same for ParaView users).
  const sltk::ReconstructionSummary& result = *filter->GetLastSummary();
  const std::vector<sltk::CommTraffic> traffic = busiestRankTraffic(result);
  // Rank 0 joins the ranks' pieces of the surface and writes the one set of outputs.
  const vtkSmartPointer<vtkPolyData> joined = gatherSurface(
    vtkPolyData::SafeDownCast(filter->GetOutputDataObject(1)), vtkMultiProcessController::GetGlobalController());
  if (rank > 0)
  {
    return 0;
  }
  vtkPolyData* surface = joined;

  // Summary table.
  printCloud(result, path, counts.Total);
  const nlohmann::ordered_json runRecords = printRuns(result, ranks, traffic);
  warnAboutResult(result);
  const bool fits = result.FitsCloud; // Core's verdict (StoppingRule.h FitShare)
  const SurfaceTopology topology = printSurface(surface, planar);
  printTotals(seconds, peakMb, ranks, traffic[0], this->octree());
  SurfaceDistances distances;
  if (this->given("--reference"))
  {
    status = surfaceDistances(surface, reference, distances);
    if (!status.isOk())
    {
      return fail(status.message());
    }
    std::printf("reference  Chamfer %.4g, Hausdorff %.4g (mean to reference %.4g, from reference %.4g)\n",
      distances.Chamfer, distances.Hausdorff, distances.MeanToReference, distances.MeanFromReference);
  }

  std::array<long long, 3> finest{ 1, 1, 1 };
  for (int a = 0; a < 3 && !result.Runs.empty(); ++a)
  {
    finest[a] = static_cast<long long>(result.Runs.back().GridDimensions[a]);
  }
  status = this->writeFiles(pieces ? nullptr : grid, finest, surface, cloud, history);
  if (!status.isOk())
  {
    return fail(status.message());
  }
  if (this->given("--json"))
  {
    nlohmann::ordered_json summary = { { "cloud", path }, { "points", counts.Total }, { "points_total", counts.Total },
      { "points_read_max", counts.ReadMax },
      { "points_held_max", std::max<long long>(counts.HeldMax, result.PlanPointsHeldMax) },
      { "run_points_held_max", runPointsHeld(result.Runs) }, { "read_seconds", readSeconds },
      { "parse_seconds", counts.ParseSeconds },
      { "outliers_removed", static_cast<long long>(result.Cleaning.OutliersRemoved) },
      { "thinning_cell", result.Cleaning.ThinningCell },
      { "points_reconstructed", static_cast<long long>(result.Cleaning.OutputPoints) }, { "h_P", result.CloudSpacing },
      { "cdx", result.CellSizeFactor }, { "kp", result.OutsideThresholdFactor },
      { "interpolator", sltk::interpolatorInfo(result.Interpolator).Name },
      { "noise", result.CloudNoise >= 0.0 ? nlohmann::ordered_json(result.CloudNoise) : nlohmann::ordered_json() },
      { "automatic_choices", result.Choices }, { "recoveries", result.Recoveries }, { "warnings", result.Warnings },
      { "fits_cloud", fits }, { "separate_groups", result.SeparateGroups },
      { "pieces", static_cast<long long>(result.Pieces) },
      { "cloud_components", static_cast<long long>(result.CloudComponents) }, { "seconds", seconds },
      { "peak_memory_mb", peakMb }, { "ranks", ranks },
      { "bytes_sent_max", static_cast<double>(traffic[0].PointToPointBytes) },
      { "collective_bytes_max", static_cast<double>(traffic[0].CollectiveBytes) },
      { "collectives", static_cast<double>(traffic[0].Collectives) }, { "read_traffic", trafficJson(counts.Traffic) },
      { "plan_traffic", trafficJson(traffic.back()) },
      { "surface_points", static_cast<long long>(surface->GetNumberOfPoints()) }, { "surface_pieces", topology.Pieces },
      { "euler_characteristic", planar ? nlohmann::ordered_json() : nlohmann::ordered_json(topology.Euler) },
      { "runs", runRecords }, { "missed_places", missedPlacesJson(result.MissedPlaces) } };
    if (this->given("--reference"))
    {
      summary["reference"] = this->Reference;
      summary["chamfer"] = distances.Chamfer;
      summary["hausdorff"] = distances.Hausdorff;
    }
    status = writeJsonFile(this->Json, summary);
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  if (!fits)
  {
    std::fprintf(
      stderr, "sltk: the result does not fit the cloud (the warning above): its files are written; exit status 3\n");
    return 3;
  }
  return 0;
}
} // namespace

Command addReconstructCommand(CLI::App& sltk)
{
  auto command = std::make_shared<Reconstruct>();
  CLI::App* app = addCloudCommand(sltk, "reconstruct", reconstructDescription, command->Cloud);
  command->Parser = app;
  sltk::ReconstructionOptions& o = command->Options;
  app
    ->add_option("-o,--output", command->Output,
      "signed distance (and distance to the cloud) on the grid; under\nmpirun, .pvti: every rank writes its own "
      "block (FILE/FILE_<rank>.vti);\n--octree: a hyper tree grid, .htg (.phtg under mpirun: each rank\nits own "
      "trees, FILE/FILE_<rank>.htg, also listed by FILE.vtm, which\nParaView 5.11 opens), or on one rank the "
      "uniform grid as .vti,\nwritten from the trees piece by piece (never held whole)")
    ->option_text("FILE.vti|.pvti|.htg|.phtg");
  app
    ->add_option("--surface", command->Surface,
      "zero level set: .vtp, .ply, .stl (3D) or .vtp (2D); a cloud far from the origin for\n                          "
      "its size (survey coordinates) gets double vertices in .vtp and .ply, not .stl")
    ->check(CLI::Validator(surfaceFormatProblem, ""))
    ->option_text("FILE");
  app
    ->add_option("--png", command->Png,
      "a picture of the surface and the cloud (renders through X:\nxvfb-run -a without a display)")
    ->option_text("FILE");
  app
    ->add_option("--csv", command->Csv,
      "convergence history (run, iteration, energy, change, cloud error,\nband, with --octree the nodes stored, the "
      "octree's leaves, the most\non a rank and the uniform grid's nodes, time)")
    ->option_text("FILE");
  app
    ->add_option("--json", command->Json,
      "summary: points, points_total, points_read_max and points_held_max (the\n"
      "most points a rank parsed from the file, and held: its share, the plan's\n"
      "owners, the cleaned cloud gathered), run_points_held_max\n"
      "(the most a rank's runs read: its rows' and those within reach), read_seconds\n"
      "(parse_seconds of it: the shares' parse),\n"
      "points_reconstructed, outliers_removed, cdx, kp,\n"
      "automatic_choices, recoveries, warnings, fits_cloud, separate_groups (a few groups\nfar apart that need "
      "their own runs), pieces (components of the\ninside), cloud_components "
      "(the cloud's, points within 4 local spacings linked),\nseconds, peak_memory_mb, ranks, surface_pieces, "
      "euler_characteristic, runs [grid, iterations, energy, err_cloud,\nfar_points, misfit_points, "
      "merged_nodes,\npoints_held; "
      "--octree: "
      "stored_nodes, "
      "uniform_nodes, leaves], missed_places [points, nearby (the cloud's\npoints there), centre, lower, upper: "
      "where the last run misses\npoints, largest first]")
    ->option_text("FILE");
  addReconstructionInterpolatorOption(app, o.Interpolator);
  addPlanOptions(app, o);
  app->get_option("--cdx")->check(withinRange("CellSizeFactor"));
  app->get_option("--kp")->check(withinRange("OutsideThresholdFactor"));
  app->get_option("--runs")->check(withinRange("NumberOfRuns"));
  app->get_option("--outlier-sigma")->check(withinRange("OutlierDeviations"))->needs("--remove-outliers");
  app->get_option("--thin")->check(withinRange("ThinningFactor"));
  addNumber(app, "--max-iterations", o.MaxIterations, "iteration cap per run (default 100)")
    ->check(withinRange("MaximumNumberOfIterations"))
    ->option_text("N");
  addNumber(app, "--tolerance", o.Tolerance,
    "a run stops when the mean energy of the last iterations changes by less\nthan this, relatively (4.33; "
    "default 1e-4)")
    ->check(withinRange("Tolerance"))
    ->option_text("TOL");
  addNumber(app, "--eta", o.FinalEta, "eta of runs >= 3 (Table 4.1: 1); larger smooths noisy scans\n(thesis Fig. 4.8)")
    ->check(withinRange("FinalEta"))
    ->option_text("E");
  app
    ->add_option_function<std::string>(
      "--schedule", [&o](const std::string& text) { parseSchedule(text, o.Schedule); },
      "p and eta of each run (4.9); the last pair holds for later runs\n(default Table 4.1: 1:0.05,2:0.05,2:1); "
      "the thesis's teapot\nkeeps details with 1:0,2:0,2:1")
    ->check(CLI::Validator(scheduleProblem, ""))
    ->option_text("P:E,P:E,...");
  app->add_flag(
    "--detect-tunnels", o.DetectTunnels, "follow grad phi through long narrow holes instead of plugging them\n(4.5.6)");
  addThreadsOption(app, command->Threads);
  app
    ->add_option("--reference", command->Reference,
      "add Chamfer and Hausdorff distances to a reference surface\n(.off .ply .obj .stl .vtp) to the summary: "
      "Chamfer =\n(mean d(result->ref) + mean d(ref->result)) / 2")
    ->option_text("MESH");
  app->add_flag("--octree", o.OctreeStorage,
    "memory that follows the surface: runs 2..R store only 8^3-node tiles\n(8^2 in 2D) around the front (the octree's "
    "finest "
    "levels; the same surface);\n-o FILE.htg: the grid as a hyper tree grid");
  app->add_flag("--quiet", command->Quiet, "no progress bar");
  app->add_flag(
    "--verbose", command->Verbose, "the solver's log (cleaning counts, grids, per-run phase times) on stderr");
  return { app, [command] { return command->run(); } };
}

} // namespace sltkcli
