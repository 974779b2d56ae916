// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKReconstructionOutput.h"

#include "SLTKMergePoints.h"

#include "vtkAbstractArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFlyingEdges2D.h"
#include "vtkFlyingEdges3D.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace sltk
{
namespace vtkbridge
{

namespace
{
/// The field's node values (without ghosts) of window rows [firstRow, firstRow
/// + rows) of the last axis as a VTK array; the field is freed afterwards, so a
/// result and its image never hold two copies of both fields.
template <int D>
vtkSmartPointer<vtkDoubleArray> moveNodeValues(GridField<D>& field, Index firstRow, Index rows, const char* name)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  const Index rowNodes = field.spec().nodeCount() / field.spec().Dims[D - 1];
  const Index n = rows * rowNodes;
  array->SetNumberOfTuples(n);
  double* out = array->GetPointer(0);
  const Index lineNodes = field.spec().Dims[0];
  // x fastest in both layouts: one x line at a time, the lines on VTK's threads
  // (a copy of every node: 206 MB for the bunny's finest grid)
  vtkSMPTools::For(0, n / lineNodes,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (Index k = begin * lineNodes; k < end * lineNodes; k += lineNodes)
      {
        const double* line = field.pointer(field.nodeIndex(k + firstRow * rowNodes));
        std::copy(line, line + lineNodes, out + k);
      }
    });
  field = GridField<D>();
  return array;
}
} // namespace

template <int D>
void toImage(ReconstructionResult<D>& result, double z, int ghostLevels, vtkImageData* image)
{
  // This rank's block: its owned rows and the next rank's first row (image
  // pieces share their boundary points, so the contour pieces join); on one
  // rank the whole grid. Ghost levels add rows of the window beyond the block
  // on each side another rank owns (at most the window's ghost rows, which
  // hold the owners' values after every run).
  const GridSpec<D>& g = result.WholeGrid;
  const SlabPlan& slab = result.Slab;
  const Index rows = g.Dims[D - 1];
  const Index endRow = std::min(slab.End + 1, rows);
  const Index levels = std::max(0, ghostLevels);
  const Index below = std::min(levels, slab.Begin - slab.First);
  const Index above = endRow < rows ? std::min(levels, slab.Stop - endRow) : 0;
  int extent[6] = { 0, 0, 0, 0, 0, 0 };
  double origin[3] = { 0.0, 0.0, z };
  double spacing[3] = { 1.0, 1.0, 1.0 };
  for (int a = 0; a < D; ++a)
  {
    extent[2 * a + 1] = static_cast<int>(g.Dims[a] - 1);
    origin[a] = g.Origin[a];
    spacing[a] = g.Spacing[a];
  }
  extent[2 * (D - 1)] = static_cast<int>(slab.Begin);
  extent[2 * (D - 1) + 1] = static_cast<int>(endRow - 1);
  int owned[6];
  std::copy(extent, extent + 6, owned);
  extent[2 * (D - 1)] -= static_cast<int>(below);
  extent[2 * (D - 1) + 1] += static_cast<int>(above);
  if (D == 2)
  {
    spacing[2] = g.Spacing[0];
  }
  image->SetExtent(extent);
  image->SetOrigin(origin);
  image->SetSpacing(spacing);
  const Index first = slab.Begin - below - slab.First, count = endRow - slab.Begin + below + above;
  image->GetPointData()->SetScalars(moveNodeValues(result.SignedDistance, first, count, "SignedDistance"));
  image->GetPointData()->AddArray(moveNodeValues(result.Distance, first, count, "DistanceToCloud"));
  if (below + above > 0)
  {
    image->GenerateGhostArray(owned); // vtkGhostType: DUPLICATEPOINT / DUPLICATECELL beyond the block
  }
}

namespace
{
/// A one-component array `name` of field data, a value per run.
template <class Array, class Value>
void addPerRun(vtkFieldData* fd, const char* name, const std::vector<RunSummary>& runs, Value value)
{
  vtkNew<Array> a;
  a->SetName(name);
  for (const RunSummary& run : runs)
  {
    a->InsertNextValue(value(run));
  }
  fd->AddArray(a);
}

/// MissedPlaces: one tuple per place where the last run misses points (MissedPlaces.h),
/// largest first: its points, the cloud's points there, its centre and bounds in the user's
/// coordinates (11 components).
void missedPlacesSummary(const ReconstructionSummary& summary, vtkFieldData* fd)
{
  vtkNew<vtkDoubleArray> places;
  places->SetName("MissedPlaces");
  places->SetNumberOfComponents(11);
  const char* names[11] = { "Points", "Nearby", "CentreX", "CentreY", "CentreZ", "LowerX", "LowerY", "LowerZ", "UpperX",
    "UpperY", "UpperZ" };
  for (int c = 0; c < 11; ++c)
  {
    places->SetComponentName(c, names[c]);
  }
  for (const MissedPlace<3>& place : summary.MissedPlaces)
  {
    double tuple[11] = { static_cast<double>(place.Points), static_cast<double>(place.Nearby) };
    std::copy(place.Centre.begin(), place.Centre.end(), tuple + 2);
    std::copy(place.Lower.begin(), place.Lower.end(), tuple + 5);
    std::copy(place.Upper.begin(), place.Upper.end(), tuple + 8);
    places->InsertNextTuple(tuple);
  }
  fd->AddArray(places);
}
} // namespace

void runSummary(const ReconstructionSummary& summary, vtkDataObject* image)
{
  vtkFieldData* fd = image->GetFieldData();
  const std::pair<const char*, const std::vector<std::string>*> notes[3] = {
    { "AutomaticChoices", &summary.Choices },
    { "Recoveries", &summary.Recoveries },
    { "Warnings", &summary.Warnings },
  };
  for (const auto& entry : notes)
  {
    vtkNew<vtkStringArray> a;
    a->SetName(entry.first);
    for (const std::string& note : *entry.second)
    {
      a->InsertNextValue(note);
    }
    fd->AddArray(a);
  }
  // The pre-processing (CloudCleaning.h): counts as doubles (exact below 2^53),
  // and the parameters used (chosen when automatic: AutomaticParameters.h).
  const std::pair<const char*, double> scalars[13] = {
    { "InputPoints", static_cast<double>(summary.Cleaning.InputPoints) },
    { "OutliersRemoved", static_cast<double>(summary.Cleaning.OutliersRemoved) },
    { "ThinningCell", summary.Cleaning.ThinningCell },
    { "ReconstructedPoints", static_cast<double>(summary.Cleaning.OutputPoints) },
    { "CellSizeFactor", summary.CellSizeFactor },
    { "OutsideThresholdFactor", summary.OutsideThresholdFactor },
    { "CloudSpacing", summary.CloudSpacing },
    { "FitsCloud", summary.FitsCloud ? 1.0 : 0.0 },
    { "SeparateGroups", summary.SeparateGroups ? 1.0 : 0.0 },      // a few groups far apart: their own runs
    { "Interpolator", static_cast<double>(summary.Interpolator) }, // the filter's InterpolatorType code
    { "CloudNoise", summary.CloudNoise },                          // < 0: not measured (given)
    { "Pieces", static_cast<double>(summary.Pieces) },             // InsideComponents.h
    { "CloudComponents", static_cast<double>(summary.CloudComponents) },
  };
  for (const auto& entry : scalars)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(entry.first);
    a->InsertNextValue(entry.second);
    fd->AddArray(a);
  }
  missedPlacesSummary(summary, fd);
  vtkNew<vtkIntArray> grids;
  grids->SetName("RunGridDimensions");
  grids->SetNumberOfComponents(3);
  for (const RunSummary& run : summary.Runs)
  {
    const int dims[3] = { static_cast<int>(run.GridDimensions[0]), static_cast<int>(run.GridDimensions[1]),
      static_cast<int>(run.GridDimensions[2]) };
    grids->InsertNextTypedTuple(dims);
  }
  fd->AddArray(grids);
  const auto& runs = summary.Runs;
  addPerRun<vtkIntArray>(fd, "RunIterations", runs, [](const RunSummary& r) { return r.Iterations; });
  addPerRun<vtkDoubleArray>(fd, "RunEnergy", runs, [](const RunSummary& r) { return r.Energy; });
  addPerRun<vtkDoubleArray>(fd, "RunCloudError", runs, [](const RunSummary& r) { return r.CloudError; });
  addPerRun<vtkDoubleArray>(fd, "RunFarPoints", runs, [](const RunSummary& r) { return r.FarPoints; });
  addPerRun<vtkDoubleArray>(fd, "RunMisfitPoints", runs, [](const RunSummary& r) { return r.MisfitPoints; });
  addPerRun<vtkDoubleArray>(fd, "RunSeconds", runs, [](const RunSummary& r) { return r.Seconds; });
  addPerRun<vtkIntArray>(fd, "RunGhostRows", runs, [](const RunSummary& r) { return static_cast<int>(r.GhostRows); });
  // Counts as doubles (exact below 2^53).
  addPerRun<vtkDoubleArray>(fd, "RunFarFeet", runs, [](const RunSummary& r) { return double(r.FarFeet); });
  addPerRun<vtkDoubleArray>(fd, "RunMergedNodes", runs, [](const RunSummary& r) { return double(r.MergedNodes); });
  addPerRun<vtkDoubleArray>(fd, "RunPointsHeld", runs, [](const RunSummary& r) { return double(r.PointsHeld); });
  if (!summary.OctreeStorage)
  {
    return;
  }
  addPerRun<vtkDoubleArray>(fd, "RunStoredNodes", runs, [](const RunSummary& r) { return double(r.StoredNodes); });
  addPerRun<vtkDoubleArray>(fd, "RunUniformNodes", runs, [](const RunSummary& r) { return double(r.UniformNodes); });
  addPerRun<vtkDoubleArray>(fd, "RunLeaves", runs, [](const RunSummary& r) { return double(r.Leaves); });
  addPerRun<vtkDoubleArray>(
    fd, "RunLargestRankLeaves", runs, [](const RunSummary& r) { return double(r.LargestRankLeaves); });
}

namespace
{
/// The rows of `image` that hold no ghost point (vtkGhostType, toImage()), as a
/// view of the same memory when there are ghost rows: the last axis' rows are
/// contiguous runs of the arrays.
vtkSmartPointer<vtkImageData> withoutGhostRows(vtkImageData* image)
{
  auto* ghosts =
    vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  auto* values = vtkDoubleArray::SafeDownCast(image->GetPointData()->GetArray("SignedDistance"));
  if (!ghosts || !values)
  {
    return image;
  }
  int extent[6];
  image->GetExtent(extent);
  const int axis = extent[4] == extent[5] ? 1 : 2; // the slabs' axis: y of a planar image, else z
  const int* dims = image->GetDimensions();
  const vtkIdType rowNodes = axis == 1 ? dims[0] : vtkIdType(dims[0]) * dims[1];
  int first = extent[2 * axis], last = extent[2 * axis + 1];
  const auto ghostRow = [&](int row)
  { return ghosts->GetValue((row - extent[2 * axis]) * rowNodes) & vtkDataSetAttributes::DUPLICATEPOINT; };
  while (first < last && ghostRow(first))
  {
    ++first;
  }
  while (last > first && ghostRow(last))
  {
    --last;
  }
  auto view = vtkSmartPointer<vtkImageData>::New();
  int owned[6];
  std::copy(extent, extent + 6, owned);
  owned[2 * axis] = first;
  owned[2 * axis + 1] = last;
  view->SetExtent(owned);
  view->SetOrigin(image->GetOrigin());
  view->SetSpacing(image->GetSpacing());
  vtkNew<vtkDoubleArray> rows;
  rows->SetName("SignedDistance");
  rows->SetArray(values->GetPointer((first - extent[2 * axis]) * rowNodes), view->GetNumberOfPoints(), 1);
  view->GetPointData()->SetScalars(rows);
  return view;
}
} // namespace

void zeroLevelSet(vtkImageData* image, vtkPolyData* surface)
{
  // Flying edges puts a vertex on every edge that meets a node where phi is
  // exactly 0, all at that node, with zero-area triangles between them: the
  // coincident vertices are merged and the degenerate cells dropped (as rank
  // 0 does when it joins the ranks' pieces), so a surface has the same
  // vertices on any rank count. Ghost rows are not contoured (their cells are
  // the next rank's).
  const vtkSmartPointer<vtkImageData> block = withoutGhostRows(image);
  vtkSmartPointer<vtkPolyData> contoured;
  if (block->GetDimensions()[2] == 1)
  {
    vtkNew<vtkFlyingEdges2D> contour;
    contour->SetInputData(block);
    contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "SignedDistance");
    contour->SetValue(0, 0.0);
    contour->Update();
    contoured = contour->GetOutput();
  }
  else
  {
    vtkNew<vtkFlyingEdges3D> contour;
    contour->SetInputData(block);
    contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "SignedDistance");
    contour->SetValue(0, 0.0);
    contour->ComputeNormalsOn();
    contour->Update();
    contoured = contour->GetOutput();
  }
  mergeCoincidentPoints(contoured, surface);
}

void transferCloudAttributes(vtkPointSet* cloud, vtkPolyData* surface)
{
  const vtkIdType vertices = surface->GetNumberOfPoints();
  if (vertices == 0 || cloud->GetNumberOfPoints() == 0)
  {
    return;
  }
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  std::vector<vtkIdType> nearest(static_cast<size_t>(vertices));
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("DistanceToCloud");
  distance->SetNumberOfTuples(vertices);
  vtkSMPTools::For(0, vertices,
    [&](vtkIdType begin, vtkIdType end)
    {
      double x[3], q[3];
      for (vtkIdType k = begin; k < end; ++k)
      {
        surface->GetPoint(k, x);
        const vtkIdType id = locator->FindClosestPoint(x);
        cloud->GetPoint(id, q);
        nearest[static_cast<size_t>(k)] = id;
        distance->SetValue(k, std::sqrt(vtkMath::Distance2BetweenPoints(x, q)));
      }
    });
  vtkPointData* out = surface->GetPointData();
  vtkPointData* in = cloud->GetPointData();
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* from = in->GetAbstractArray(a);
    if (!from || !from->GetName())
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> to = vtk::TakeSmartPointer(from->NewInstance());
    const std::string name = from->GetName();
    to->SetName((out->HasArray(name.c_str()) ? "Cloud" + name : name).c_str());
    to->SetNumberOfComponents(from->GetNumberOfComponents());
    to->SetNumberOfTuples(vertices);
    for (vtkIdType k = 0; k < vertices; ++k)
    {
      to->SetTuple(k, nearest[static_cast<size_t>(k)], from);
    }
    out->AddArray(to);
  }
  out->AddArray(distance);
}

void historyTable(const std::vector<IterationRecord>& history, vtkTable* table)
{
  vtkNew<vtkIntArray> run, iteration;
  vtkNew<vtkDoubleArray> energy, change, cloudError, seconds;
  vtkNew<vtkIdTypeArray> band, stored, leaves, largestRank, uniform;
  run->SetName("Run");
  iteration->SetName("Iteration");
  energy->SetName("Energy");
  change->SetName("Change");
  cloudError->SetName("CloudError");
  band->SetName("BandSize");
  stored->SetName("StoredNodes");
  leaves->SetName("Leaves");
  largestRank->SetName("LargestRankLeaves");
  uniform->SetName("UniformNodes");
  seconds->SetName("Seconds");
  // Tiled storage (OctreeStorage) records the nodes held after each iteration.
  const bool tiled =
    std::any_of(history.begin(), history.end(), [](const IterationRecord& r) { return r.StoredNodes > 0; });
  for (const IterationRecord& r : history)
  {
    run->InsertNextValue(r.Run);
    iteration->InsertNextValue(r.Iteration);
    energy->InsertNextValue(r.Energy);
    change->InsertNextValue(r.Change);
    cloudError->InsertNextValue(r.CloudError);
    band->InsertNextValue(static_cast<vtkIdType>(r.BandSize));
    stored->InsertNextValue(static_cast<vtkIdType>(r.StoredNodes));
    leaves->InsertNextValue(static_cast<vtkIdType>(r.Leaves));
    largestRank->InsertNextValue(static_cast<vtkIdType>(r.LargestRankLeaves));
    uniform->InsertNextValue(static_cast<vtkIdType>(r.UniformNodes));
    seconds->InsertNextValue(r.Seconds);
  }
  table->AddColumn(run);
  table->AddColumn(iteration);
  table->AddColumn(energy);
  table->AddColumn(change);
  table->AddColumn(cloudError);
  table->AddColumn(band);
  if (tiled)
  {
    table->AddColumn(stored);
    table->AddColumn(leaves);
    table->AddColumn(largestRank);
    table->AddColumn(uniform);
  }
  table->AddColumn(seconds);
}

void communicationSummary(const ReconstructionSummary& summary, vtkDataObject* image)
{
  vtkNew<vtkDoubleArray> ranks;
  ranks->SetName("Ranks");
  ranks->InsertNextValue(static_cast<double>(summary.Ranks));
  image->GetFieldData()->AddArray(ranks);
  // The whole reconstruction's counts (Rank*), each run's share (Run*, one value a run)
  // and the plan's on the shares (Plan*, apart from the reconstruction's).
  using Field = std::int64_t CommTraffic::*;
  const std::pair<const char*, Field> counts[3] = { { "RankBytesSent", &CommTraffic::PointToPointBytes },
    { "RankCollectiveBytes", &CommTraffic::CollectiveBytes }, { "RankCollectives", &CommTraffic::Collectives } };
  for (const auto& count : counts)
  {
    vtkNew<vtkDoubleArray> whole, perRun, plan;
    whole->SetName(count.first);
    whole->InsertNextValue(static_cast<double>(summary.Traffic.*count.second));
    perRun->SetName((std::string("Run") + count.first).c_str());
    for (const RunSummary& run : summary.Runs)
    {
      perRun->InsertNextValue(static_cast<double>(run.Traffic.*count.second));
    }
    plan->SetName((std::string("Plan") + count.first).c_str());
    plan->InsertNextValue(static_cast<double>(summary.PlanTraffic.*count.second));
    image->GetFieldData()->AddArray(whole);
    image->GetFieldData()->AddArray(perRun);
    image->GetFieldData()->AddArray(plan);
  }
}

template void toImage(ReconstructionResult<2>&, double, int, vtkImageData*);
template void toImage(ReconstructionResult<3>&, double, int, vtkImageData*);

} // namespace vtkbridge
} // namespace sltk
