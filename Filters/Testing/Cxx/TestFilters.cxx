// SPDX-License-Identifier: BSD-3-Clause
// Pipeline-level checks of the three SLTK filters in plain C++ VTK.
#include "vtkCWENOHJBSolver.h"
#include "vtkOctreeSDF.h"
#include "vtkSLLevelSetReconstruct.h"

#include "sltk/recon/ReconstructionOptions.h"
#include "sltk/recon/ReconstructionSummary.h"

#include "vtkBitArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFeatureEdges.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridContour.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"
#include "vtkXMLHyperTreeGridReader.h"
#include "vtkXMLHyperTreeGridWriter.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
int failures = 0;

void check(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << "\n";
  failures += ok ? 0 : 1;
}

vtkSmartPointer<vtkPolyData> cloud(int n, double scale)
{
  vtkNew<vtkPoints> points;
  for (int k = 0; k < n; ++k)
  {
    const double z = -1.0 + 2.0 * (k + 0.5) / n;
    const double r = std::sqrt(1.0 - z * z);
    points->InsertNextPoint(scale * r * std::cos(2.4 * k), scale * r * std::sin(2.4 * k), scale * z);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  return poly;
}

/// The first value of field array `name` of `data`, or of its tuple `k` (NaN when absent).
double fieldValue(vtkDataObject* data, const char* name, vtkIdType k = 0)
{
  vtkDataArray* a = data ? data->GetFieldData()->GetArray(name) : nullptr;
  return a && k < a->GetNumberOfTuples() ? a->GetTuple1(k) : std::nan("");
}

/// The properties read and write Core's options in place (C++: SetOptions, GetOptions)
/// with vtkSetMacro's semantics, in the property's units; a value Core's types cannot
/// hold is kept as given and refused when the filter runs.
void checkOptionProperties()
{
  vtkNew<vtkSLLevelSetReconstruct> recon;
  const sltk::ReconstructionOptions defaults;
  check(recon->GetNumberOfRuns() == defaults.Runs && recon->GetPadding() == defaults.Padding &&
      recon->GetTolerance() == defaults.Tolerance && recon->GetFinalEta() == defaults.FinalEta &&
      !defaults.Interpolator && recon->GetInterpolator() == vtkSLLevelSetReconstruct::AUTOMATIC &&
      recon->GetMemoryBudget() == 0 && recon->GetAutomaticCleaning() == defaults.Cleaning.Automatic &&
      recon->GetOutlierDeviations() == defaults.Cleaning.Outliers.Deviations,
    "the properties' defaults are Core's");
  const vtkMTimeType before = recon->GetMTime();
  recon->SetPadding(recon->GetPadding());
  recon->SetInterpolator(recon->GetInterpolator());
  check(recon->GetMTime() == before, "setting a property to its value leaves the filter unmodified");
  recon->SetPadding(12);
  recon->SetThinningFactor(1.5);
  check(recon->GetMTime() > before && recon->GetOptions().Padding == 12 &&
      recon->GetOptions().Cleaning.ThinningFactor == 1.5,
    "a property writes Core's options in place");
  recon->SetMemoryBudget(64);
  check(recon->GetOptions().MemoryBudget == (std::uint64_t(64) << 20) && recon->GetMemoryBudget() == 64,
    "MemoryBudget is in MB, Core's in bytes");
  recon->AddRunParameterValue(1.0);
  check(recon->GetNumberOfRunParameterValues() == 1 && recon->GetOptions().Schedule.empty(),
    "a lone RunParameters value waits for its pair");
  recon->AddRunParameterValue(0.0);
  check(recon->GetOptions().Schedule.size() == 1 && recon->GetRunEta(0) == 0.0, "a pair is one (p, eta) of Core's");
  sltk::ReconstructionOptions options;
  options.CellSizeFactor = 1.5;
  options.Guess = sltk::InitialGuess::BoundingSphere;
  options.Cleaning.Automatic = false;
  options.MinIterations = 5; // no property: C++ only
  recon->SetOptions(options);
  check(recon->GetCellSizeFactor() == 1.5 && recon->GetInitialGuess() == vtkSLLevelSetReconstruct::BOUNDING_SPHERE &&
      !recon->GetAutomaticCleaning() && recon->GetNumberOfRunParameters() == 0 &&
      recon->GetOptions().MinIterations == 5,
    "SetOptions replaces every option; the properties read them");

  recon->SetOptions(sltk::ReconstructionOptions{});
  recon->SetNumberOfRuns(1);
  recon->SetInputData(cloud(300, 1.0));
  check(recon->GetExecutive()->Update() == 1 && recon->GetLastSummary(), "a run leaves its summary");
  const struct
  {
    const char* Name;
    void (vtkSLLevelSetReconstruct::*Set)(int);
    int (vtkSLLevelSetReconstruct::*Get)();
    int Bad, Good;
  } unheld[3] = {
    { "Interpolator", &vtkSLLevelSetReconstruct::SetInterpolator, &vtkSLLevelSetReconstruct::GetInterpolator, -2,
      1 }, // -1: AUTOMATIC
    { "InitialGuess", &vtkSLLevelSetReconstruct::SetInitialGuess, &vtkSLLevelSetReconstruct::GetInitialGuess, 300, 0 },
    { "MemoryBudget", &vtkSLLevelSetReconstruct::SetMemoryBudget, &vtkSLLevelSetReconstruct::GetMemoryBudget, -5, 0 },
  };
  for (const auto& property : unheld)
  {
    (recon->*property.Set)(property.Bad);
    check((recon->*property.Get)() == property.Bad && recon->GetExecutive()->Update() == 0 && !recon->GetLastSummary(),
      std::string(property.Name) + " outside Core's type is kept as given and refused, with no summary");
    (recon->*property.Set)(property.Good);
  }
  check(recon->GetExecutive()->Update() == 1, "the corrected properties run again");
}

/// The typed summary (C++: GetLastSummary) holds the values of port 0's field data.
void checkSummary(vtkSLLevelSetReconstruct* recon, const std::string& what)
{
  vtkDataObject* grid = recon->GetOutputDataObject(0);
  const sltk::ReconstructionSummary* s = recon->GetLastSummary();
  bool same = s && !s->Runs.empty() && s->CloudSpacing == fieldValue(grid, "CloudSpacing") &&
    s->CellSizeFactor == fieldValue(grid, "CellSizeFactor") &&
    static_cast<double>(s->Cleaning.OutputPoints) == fieldValue(grid, "ReconstructedPoints") &&
    static_cast<double>(s->Traffic.PointToPointBytes) == fieldValue(grid, "RankBytesSent") &&
    static_cast<double>(s->Traffic.CollectiveBytes) == fieldValue(grid, "RankCollectiveBytes") &&
    static_cast<double>(s->PlanTraffic.Collectives) == fieldValue(grid, "PlanRankCollectives");
  for (size_t r = 0; same && r < s->Runs.size(); ++r)
  {
    const auto k = static_cast<vtkIdType>(r);
    const sltk::RunSummary& run = s->Runs[r];
    same = run.Iterations == fieldValue(grid, "RunIterations", k) &&
      run.CloudError == fieldValue(grid, "RunCloudError", k) && run.Seconds == fieldValue(grid, "RunSeconds", k) &&
      static_cast<double>(run.Traffic.Collectives) == fieldValue(grid, "RunRankCollectives", k) &&
      (!s->OctreeStorage || static_cast<double>(run.StoredNodes) == fieldValue(grid, "RunStoredNodes", k));
  }
  check(same, what + ": the typed summary holds port 0's field data");
  // Where the last run misses points: a tuple of 11 per place (Points, Nearby, Centre, Lower, Upper).
  vtkDataArray* places = grid ? grid->GetFieldData()->GetArray("MissedPlaces") : nullptr;
  bool placesSame = s && places && places->GetNumberOfComponents() == 11 &&
    places->GetNumberOfTuples() == static_cast<vtkIdType>(s->MissedPlaces.size());
  for (size_t k = 0; placesSame && k < s->MissedPlaces.size(); ++k)
  {
    const sltk::MissedPlace<3>& place = s->MissedPlaces[k];
    const double* tuple = places->GetTuple(static_cast<vtkIdType>(k));
    placesSame = tuple[0] == static_cast<double>(place.Points) && tuple[1] == static_cast<double>(place.Nearby) &&
      std::equal(place.Centre.begin(), place.Centre.end(), tuple + 2) &&
      std::equal(place.Lower.begin(), place.Lower.end(), tuple + 5) &&
      std::equal(place.Upper.begin(), place.Upper.end(), tuple + 8);
  }
  check(placesSame, what + ": the field data's MissedPlaces are the typed summary's");
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string outDir = argc > 1 ? argv[1] : ".";     // files written and read back
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // expected errors stay quiet

  // HJB solver: whole extent, spacing, a sub-extent request, T = 0 and a real solve.
  {
    vtkNew<vtkCWENOHJBSolver> solver;
    solver->SetNumberOfNodes(41);
    solver->SetFinalTime(0.0);
    solver->UpdateInformation();
    int whole[6];
    solver->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    check(whole[1] == 40 && whole[3] == 40 && whole[5] == 0, "HJB Test 1 whole extent is 0..40 x 0..40");
    check(
      solver->GetOutputInformation(0)->Get(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT()) == 1, "HJB advertises sub-extents");
    int sub[6] = { 0, 40, 10, 19, 0, 0 };
    solver->UpdateExtent(sub);
    vtkImageData* image = solver->GetOutput();
    int got[6];
    image->GetExtent(got);
    check(got[2] == 10 && got[3] == 19, "HJB produces exactly the requested sub-extent");
    check(std::fabs(image->GetSpacing()[1] - 1.0 / 40) < 1e-15, "HJB spacing is 1/(N-1) on [0,1]");
    auto* values = vtkDoubleArray::SafeDownCast(image->GetPointData()->GetArray("ValueFunction"));
    bool exact = values != nullptr;
    for (vtkIdType id = 0; exact && id < image->GetNumberOfPoints(); ++id)
    {
      double x[3];
      image->GetPoint(id, x);
      const double r = std::hypot(x[0] - 0.3, x[1] - 0.7) / 0.15;
      const double s = r - 1.0;
      const double expected = r < 1.0 ? 0.15 * (1.0 + r * r * r * (-1.0 + 3.0 * s * (1.0 - 2.0 * s))) : 0.0;
      exact = std::fabs(values->GetValue(id) - expected) < 1e-14;
    }
    check(exact, "HJB T=0 output equals the Test 1 initial datum");

    // One full revolution at N = 41: the thesis's Table 3.1 gives L1 4.84e-4 for CWENOZ.
    solver->SetFinalTime(-1.0);
    solver->SetNumberOfThreads(2);
    solver->UpdateWholeExtent();
    image = solver->GetOutput();
    auto* l1 = image->GetFieldData()->GetArray("L1Error");
    check(l1 && std::fabs(l1->GetTuple1(0) / 4.84e-4 - 1.0) < 0.05, "HJB Test 1 N=41 CWENOZ L1 within 5% of Table 3.1");
    std::ostringstream os;
    solver->Print(os);
    check(os.str().find("NumberOfNodes: 41") != std::string::npos, "HJB PrintSelf lists properties");

    // Test 5 has a reachable-set field.
    solver->SetPreset(vtkCWENOHJBSolver::TEST5_ZERMELO);
    solver->SetNumberOfNodes(26);
    solver->SetFinalTime(0.5);
    solver->UpdateWholeExtent();
    check(solver->GetOutput()->GetPointData()->GetArray("ReachTime") != nullptr, "HJB Test 5 outputs ReachTime");
    solver->SetNumberOfNodes(1000000);
    check(solver->GetNumberOfNodes() == 1000000, "NumberOfNodes is kept as given, not clamped");
    check(solver->GetExecutive()->Update() == 0, "NumberOfNodes out of range is refused when the filter runs");
  }

  // Reconstruction: bad inputs fail cleanly; a sphere cloud gives a signed distance and a surface.
  {
    vtkNew<vtkSLLevelSetReconstruct> recon;
    check(recon->GetNumberOfOutputPorts() == 3, "reconstruction has 3 outputs");
    vtkNew<vtkPolyData> empty;
    recon->SetInputData(empty);
    check(recon->GetExecutive()->Update() == 0, "reconstruction refuses an empty point set");
    recon->SetInputData(cloud(800, 1.0));
    recon->SetNumberOfRuns(2);
    recon->SetInterpolator(vtkSLLevelSetReconstruct::WENO3);
    check(recon->GetExecutive()->Update() == 1, "reconstruction of an 800-point sphere succeeds");
    checkSummary(recon, "uniform grids");
    auto* image = vtkImageData::SafeDownCast(recon->GetOutputDataObject(0));
    auto* sdf = image ? image->GetPointData()->GetArray("SignedDistance") : nullptr;
    check(sdf != nullptr && image->GetPointData()->GetArray("DistanceToCloud") != nullptr,
      "output 0 carries SignedDistance and DistanceToCloud");
    if (sdf)
    {
      const vtkIdType centre = image->FindPoint(0.0, 0.0, 0.0);
      const vtkIdType outside = image->FindPoint(1.4, 0.0, 0.0);
      check(sdf->GetTuple1(centre) < 0.0, "the signed distance is negative inside");
      check(sdf->GetTuple1(outside) > 0.0, "and positive outside");
    }
    auto* surface = vtkPolyData::SafeDownCast(recon->GetOutputDataObject(1));
    double bounds[6] = { 0, 0, 0, 0, 0, 0 };
    if (surface && surface->GetNumberOfPoints() > 0)
    {
      surface->GetBounds(bounds);
    }
    check(surface && surface->GetNumberOfPolys() > 100 && std::fabs(bounds[1] - 1.0) < 0.05 &&
        std::fabs(bounds[4] + 1.0) < 0.05,
      "output 1 is a closed surface through the unit sphere");
    auto* table = vtkTable::SafeDownCast(recon->GetOutputDataObject(2));
    check(table && table->GetNumberOfRows() >= 2 && table->GetColumnByName("CloudError") != nullptr,
      "output 2 is the convergence history");

    // OctreeStorage: runs >= 2 in tiles around the front; the same iterations, the same
    // surface up to round-off (phi agrees to ~1e-14 cells, TestTiledReconstruction), watertight.
    const vtkIdType uniformPoints = surface ? surface->GetNumberOfPoints() : 0;
    const vtkIdType uniformRows = table ? table->GetNumberOfRows() : 0;
    const double uniformCloudError =
      table && uniformRows > 0 ? table->GetValueByName(uniformRows - 1, "CloudError").ToDouble() : 0.0;
    check(table && !table->GetColumnByName("StoredNodes"), "the uniform history has no StoredNodes column");
    recon->OctreeStorageOn();
    check(recon->GetExecutive()->Update() == 1, "OctreeStorage: the sphere is reconstructed");
    auto* tiled = vtkPolyData::SafeDownCast(recon->GetOutputDataObject(1));
    vtkNew<vtkFeatureEdges> open;
    open->SetInputData(tiled);
    open->BoundaryEdgesOn();
    open->NonManifoldEdgesOn();
    open->FeatureEdgesOff();
    open->ManifoldEdgesOff();
    open->Update();
    check(tiled && tiled->GetNumberOfPolys() > 100 && open->GetOutput()->GetNumberOfCells() == 0,
      "OctreeStorage: the surface contoured tile by tile has no boundary or non-manifold edge");
    check(tiled && std::abs(tiled->GetNumberOfPoints() - uniformPoints) <= uniformPoints / 1000,
      "OctreeStorage: the surface has the uniform one's points (" + std::to_string(tiled->GetNumberOfPoints()) +
        " vs " + std::to_string(uniformPoints) + ")");
    auto* tiledTable = vtkTable::SafeDownCast(recon->GetOutputDataObject(2));
    check(tiledTable && tiledTable->GetNumberOfRows() == uniformRows, "OctreeStorage: the same iterations");
    auto* tree = vtkHyperTreeGrid::SafeDownCast(recon->GetOutputDataObject(0));
    check(tree != nullptr, "OctreeStorage: port 0 is a hyper tree grid");
    auto* stored = tree ? tree->GetFieldData()->GetArray("RunStoredNodes") : nullptr;
    auto* all = tree ? tree->GetFieldData()->GetArray("RunUniformNodes") : nullptr;
    check(stored && all && stored->GetNumberOfTuples() == 2 && stored->GetTuple1(0) == all->GetTuple1(0) &&
        stored->GetTuple1(1) > 0 && stored->GetTuple1(1) < all->GetTuple1(1),
      "OctreeStorage: stored and uniform node counts per run (run 1 uniform)");
    {
      // Every iteration's stored nodes (thesis Fig. 5.7): run 1 its whole grid, run 2 its tiles.
      auto* storedColumn =
        tiledTable ? vtkDataArray::SafeDownCast(tiledTable->GetColumnByName("StoredNodes")) : nullptr;
      auto* runColumn = tiledTable ? vtkDataArray::SafeDownCast(tiledTable->GetColumnByName("Run")) : nullptr;
      double first = -1.0, lastStored = -1.0;
      for (vtkIdType r = 0; storedColumn && runColumn && r < tiledTable->GetNumberOfRows(); ++r)
      {
        (runColumn->GetTuple1(r) == 1 ? first : lastStored) = storedColumn->GetTuple1(r);
      }
      check(storedColumn && all && first == all->GetTuple1(0) && lastStored > 0.0 && lastStored < all->GetTuple1(1),
        "OctreeStorage: the history's StoredNodes per iteration (run 1 " + std::to_string(first) +
          ", its grid; the last " + std::to_string(lastStored) + ", fewer than run 2's grid)");
    }
    if (tree)
    {
      // One leaf per stored node in the grid (level 3) but for the flat cells (one leaf each), one
      // per slot without a tile (level 0); its dual grid contours to the tile-by-tile surface.
      auto* level = tree->GetCellData()->GetArray("Level");
      auto* phi = tree->GetCellData()->GetArray("SignedDistance");
      auto* dist = tree->GetCellData()->GetArray("DistanceToCloud");
      vtkIdType finest = 0;
      for (vtkIdType c = 0; level && c < level->GetNumberOfTuples(); ++c)
      {
        finest += level->GetTuple1(c) == 3 && !(tree->HasMask() && tree->GetMask()->GetValue(c)) ? 1 : 0;
      }
      check(level && phi && dist && finest > 0 && finest <= stored->GetTuple1(1) && dist->GetRange()[0] >= 0.0 &&
          std::isfinite(dist->GetRange()[1]),
        "OctreeStorage: the tree's leaves hold the stored nodes' values (" + std::to_string(finest) + " of " +
          std::to_string(static_cast<long long>(stored->GetTuple1(1))) + " stored nodes)");
      vtkNew<vtkHyperTreeGridContour> contour;
      contour->SetInputData(tree);
      contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "SignedDistance");
      contour->SetValue(0, 0.0);
      vtkNew<vtkCleanPolyData> merged;
      merged->SetInputConnection(contour->GetOutputPort());
      vtkNew<vtkFeatureEdges> treeOpen;
      treeOpen->SetInputConnection(merged->GetOutputPort());
      treeOpen->BoundaryEdgesOn();
      treeOpen->NonManifoldEdgesOn();
      treeOpen->FeatureEdgesOff();
      treeOpen->ManifoldEdgesOff();
      treeOpen->Update();
      check(merged->GetOutput()->GetNumberOfPoints() == tiled->GetNumberOfPoints() &&
          treeOpen->GetOutput()->GetNumberOfCells() == 0,
        "OctreeStorage: the tree's contour is the tiled surface (" +
          std::to_string(merged->GetOutput()->GetNumberOfPoints()) + " vs " +
          std::to_string(tiled->GetNumberOfPoints()) + " points), watertight");
      const std::string htg = outDir + "/adaptive.htg";
      vtkNew<vtkXMLHyperTreeGridWriter> writer;
      writer->SetInputData(tree);
      writer->SetFileName(htg.c_str());
      writer->SetDataModeToBinary();
      vtkNew<vtkXMLHyperTreeGridReader> reader;
      reader->SetFileName(htg.c_str());
      check(
        writer->Write() == 1 && (reader->Update(), reader->GetOutput()->GetNumberOfCells() == tree->GetNumberOfCells()),
        "OctreeStorage: the tree written as .htg reads back");
    }
    recon->GenerateHyperTreeGridOff(); // the surface alone: no trees, the run summary kept
    check(recon->GetExecutive()->Update() == 1, "OctreeStorage without the grid: reconstructed");
    auto* bare = vtkHyperTreeGrid::SafeDownCast(recon->GetOutputDataObject(0));
    auto* bareSurface = vtkPolyData::SafeDownCast(recon->GetOutputDataObject(1));
    check(bare && bare->GetNumberOfCells() == 0 && bare->GetFieldData()->GetArray("RunStoredNodes") && bareSurface &&
        bareSurface->GetNumberOfPoints() == tiled->GetNumberOfPoints(),
      "GenerateHyperTreeGrid off: no trees, the run summary and the same surface");
    recon->GenerateHyperTreeGridOn();
    recon->OctreeStorageOff();
    // LEAST_SQUARES_Q1: the thesis's chapter 5 interpolation (5.5) at the feet; its own result, watertight.
    recon->SetInterpolator(vtkSLLevelSetReconstruct::LEAST_SQUARES_Q1);
    check(recon->GetExecutive()->Update() == 1, "LEAST_SQUARES_Q1: the sphere is reconstructed");
    {
      auto* lsqTable = vtkTable::SafeDownCast(recon->GetOutputDataObject(2));
      const vtkIdType rows = lsqTable ? lsqTable->GetNumberOfRows() : 0;
      const double lsqCloudError = rows > 0 ? lsqTable->GetValueByName(rows - 1, "CloudError").ToDouble() : 0.0;
      vtkNew<vtkFeatureEdges> lsqOpen;
      lsqOpen->SetInputData(recon->GetOutputDataObject(1));
      lsqOpen->BoundaryEdgesOn();
      lsqOpen->NonManifoldEdgesOn();
      lsqOpen->FeatureEdgesOff();
      lsqOpen->ManifoldEdgesOff();
      lsqOpen->Update();
      check(lsqCloudError > 0.0 && lsqCloudError < 0.05 && lsqCloudError != uniformCloudError &&
          lsqOpen->GetOutput()->GetNumberOfCells() == 0,
        "LEAST_SQUARES_Q1: Err_P " + std::to_string(lsqCloudError) + " (WENO3 " + std::to_string(uniformCloudError) +
          "), no boundary or non-manifold edge");
    }
    recon->SetInterpolator(vtkSLLevelSetReconstruct::WENO3);
    recon->SetNumberOfRuns(99);
    check(recon->GetNumberOfRuns() == 99 && recon->GetExecutive()->Update() == 0,
      "NumberOfRuns outside 1-6 is refused, not clamped");
    recon->SetNumberOfRuns(3);

    // A planar cloud (a circle at z = 0.5) is reconstructed in 2D.
    vtkNew<vtkPoints> ring;
    for (int k = 0; k < 64; ++k)
    {
      ring->InsertNextPoint(std::cos(2 * M_PI * k / 64), std::sin(2 * M_PI * k / 64), 0.5);
    }
    vtkNew<vtkPolyData> circle;
    circle->SetPoints(ring);
    recon->SetInputData(circle);
    recon->SetNumberOfRuns(3);
    check(recon->GetExecutive()->Update() == 1, "a 64-point circle is reconstructed");
    image = vtkImageData::SafeDownCast(recon->GetOutputDataObject(0));
    check(image->GetDimensions()[2] == 1 && image->GetOrigin()[2] == 0.5, "in 2D: one z layer at the cloud's height");
    surface = vtkPolyData::SafeDownCast(recon->GetOutputDataObject(1));
    check(surface->GetNumberOfLines() > 50, "the 2D output 1 is a closed contour");

    // Per-run (p, eta): Table 4.1 with eta 0 from run 3 on, once through FinalEta and once
    // through a schedule whose last row repeats, gives bitwise the same signed distance;
    // a schedule with eta = 0 in every run gives another one; a bad row is refused.
    const auto signedDistance = [&recon]()
    {
      std::vector<double> values;
      auto* out = vtkImageData::SafeDownCast(recon->GetOutputDataObject(0));
      auto* array = out ? out->GetPointData()->GetArray("SignedDistance") : nullptr;
      for (vtkIdType k = 0; array && k < array->GetNumberOfTuples(); ++k)
      {
        values.push_back(array->GetTuple1(k));
      }
      return values;
    };
    recon->SetNumberOfRuns(4);
    recon->SetFinalEta(0.0);
    recon->Update();
    const std::vector<double> viaFinalEta = signedDistance();
    recon->SetFinalEta(1.0);
    recon->AddRunParameters(1.0, 0.05);
    recon->AddRunParameters(2.0, 0.05);
    recon->AddRunParameters(2.0, 0.0);
    check(recon->GetNumberOfRunParameters() == 3 && recon->GetRunEta(2) == 0.0 && recon->GetRunP(5) == 0.0,
      "the run schedule holds three (p, eta) rows");
    check(recon->GetExecutive()->Update() == 1, "a reconstruction with a run schedule succeeds");
    const std::vector<double> viaSchedule = signedDistance();
    check(!viaFinalEta.empty() && viaSchedule == viaFinalEta,
      "the schedule's last row holds for run 4, as FinalEta does (bitwise the same result)");
    recon->RemoveAllRunParameters();
    recon->AddRunParameters(1.0, 0.0);
    recon->AddRunParameters(2.0, 0.0);
    recon->Update();
    check(signedDistance() != viaSchedule, "eta = 0 in runs 1-2 changes the result");
    recon->AddRunParameters(0.5, 1.0);
    check(recon->GetExecutive()->Update() == 0, "a schedule row with p < 1 is refused");
    recon->RemoveAllRunParameters();
    check(recon->GetNumberOfRunParameters() == 0, "RemoveAllRunParameters empties the schedule");
    recon->SetInterpolator(7);
    check(recon->GetInterpolator() == 7 && recon->GetExecutive()->Update() == 0,
      "an Interpolator outside the registry is refused, not clamped");
    vtkNew<vtkCWENOHJBSolver> badHjb;
    badHjb->SetInterpolator(-1);
    badHjb->UpdateWholeExtent();
    check(badHjb->GetExecutive()->Update() == 0, "the HJB solver refuses an Interpolator outside the registry");
    badHjb->SetInterpolator(vtkSLLevelSetReconstruct::LEAST_SQUARES_Q1);
    check(badHjb->GetExecutive()->Update() == 0, "the HJB solver refuses the reconstruction's own interpolator");
  }

  // Octree: always the octree (TestOctreeSDF.cxx checks its outputs).
  {
    vtkNew<vtkOctreeSDF> octree;
    octree->SetInputDataObject(cloud(100, 2.0));
    octree->OctreeStorageOff();
    check(octree->GetExecutive()->Update() == 0, "vtkOctreeSDF refuses OctreeStorage off");
    octree->OctreeStorageOn();
    // The deprecated names forward to OctreeStorage and GenerateHyperTreeGrid for one release.
    octree->SetAdaptiveStorage(false);
    octree->GenerateAdaptiveGridOff();
    check(!octree->GetOctreeStorage() && !octree->GetGenerateHyperTreeGrid() && !octree->GetAdaptiveStorage() &&
        !octree->GetGenerateAdaptiveGrid(),
      "the deprecated AdaptiveStorage and GenerateAdaptiveGrid methods forward to the new properties");
    octree->AdaptiveStorageOn();
    octree->SetGenerateAdaptiveGrid(true);
    check(octree->GetOctreeStorage() && octree->GetGenerateHyperTreeGrid(),
      "the deprecated On and Set methods forward to the new properties");
    octree->SetMaximumLevel(40);
    check(octree->GetExecutive()->Update() == 0 && octree->GetMaximumLevel() == 40,
      "vtkOctreeSDF refuses MaximumLevel 40, not clamped");
    octree->SetMaximumLevel(0);
    octree->SetNumberOfRuns(9);
    check(octree->GetExecutive()->Update() == 0 && octree->GetOutput() != nullptr,
      "vtkOctreeSDF refuses NumberOfRuns 9; its port 0 is a vtkHyperTreeGrid");
    octree->SetNumberOfRuns(2);
    check(octree->GetExecutive()->Update() == 1, "vtkOctreeSDF reconstructs with 2 runs");
    checkSummary(octree, "octree");
  }
  checkOptionProperties();

  std::cout << (failures == 0 ? "all filter checks passed\n" : "filter checks FAILED\n");
  return failures == 0 ? 0 : 1;
}
