// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKReconstructionOutput.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFlyingEdges2D.h"
#include "vtkFlyingEdges3D.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

#include <utility>

namespace sltk
{
namespace vtkbridge
{

namespace
{
template <int D>
vtkSmartPointer<vtkDoubleArray> nodeValues(const GridField<D>& field, const char* name)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  const Index n = field.spec().nodeCount();
  array->SetNumberOfTuples(n);
  double* out = array->GetPointer(0);
  for (Index k = 0; k < n; ++k) // x fastest in both layouts
  {
    out[k] = field(field.nodeIndex(k));
  }
  return array;
}
} // namespace

template <int D>
void toImage(const ReconstructionResult<D>& result, double z, vtkImageData* image)
{
  const GridSpec<D>& g = result.SignedDistance.spec();
  int dims[3] = { 1, 1, 1 };
  double origin[3] = { 0.0, 0.0, z };
  double spacing[3] = { 1.0, 1.0, 1.0 };
  for (int a = 0; a < D; ++a)
  {
    dims[a] = static_cast<int>(g.Dims[a]);
    origin[a] = g.Origin[a];
    spacing[a] = g.Spacing[a];
  }
  if (D == 2)
  {
    spacing[2] = g.Spacing[0];
  }
  image->SetDimensions(dims);
  image->SetOrigin(origin);
  image->SetSpacing(spacing);
  image->GetPointData()->SetScalars(nodeValues(result.SignedDistance, "SignedDistance"));
  image->GetPointData()->AddArray(nodeValues(result.Distance, "DistanceToCloud"));
}

template <int D>
void runSummary(const ReconstructionResult<D>& result, vtkImageData* image)
{
  vtkNew<vtkDoubleArray> spacing;
  spacing->SetName("CloudSpacing");
  spacing->InsertNextValue(result.CloudSpacing);
  vtkNew<vtkIntArray> grids, iterations;
  grids->SetName("RunGridDimensions");
  grids->SetNumberOfComponents(3);
  iterations->SetName("RunIterations");
  vtkNew<vtkDoubleArray> energy, cloudError, seconds;
  energy->SetName("RunEnergy");
  cloudError->SetName("RunCloudError");
  seconds->SetName("RunSeconds");
  for (const RunRecord<D>& run : result.Runs)
  {
    int dims[3] = { 1, 1, 1 };
    for (int a = 0; a < D; ++a)
    {
      dims[a] = static_cast<int>(run.Grid.Dims[a]);
    }
    grids->InsertNextTypedTuple(dims);
    iterations->InsertNextValue(run.Iterations);
    energy->InsertNextValue(run.Energy);
    cloudError->InsertNextValue(run.CloudError);
    seconds->InsertNextValue(run.Seconds);
  }
  vtkFieldData* fd = image->GetFieldData();
  // The pre-processing (CloudCleaning.h): counts as doubles (exact below 2^53).
  const std::pair<const char*, double> cleaning[4] = {
    { "InputPoints", static_cast<double>(result.Cleaning.InputPoints) },
    { "OutliersRemoved", static_cast<double>(result.Cleaning.OutliersRemoved) },
    { "ThinningCell", result.Cleaning.ThinningCell },
    { "ReconstructedPoints", static_cast<double>(result.Cleaning.OutputPoints) },
  };
  for (const auto& entry : cleaning)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(entry.first);
    a->InsertNextValue(entry.second);
    fd->AddArray(a);
  }
  fd->AddArray(spacing);
  fd->AddArray(grids);
  fd->AddArray(iterations);
  fd->AddArray(energy);
  fd->AddArray(cloudError);
  fd->AddArray(seconds);
}

void zeroLevelSet(vtkImageData* image, vtkPolyData* surface)
{
  const bool flat = image->GetDimensions()[2] == 1;
  if (flat)
  {
    vtkNew<vtkFlyingEdges2D> contour;
    contour->SetInputData(image);
    contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "SignedDistance");
    contour->SetValue(0, 0.0);
    contour->Update();
    surface->ShallowCopy(contour->GetOutput());
    return;
  }
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "SignedDistance");
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOn();
  contour->Update();
  surface->ShallowCopy(contour->GetOutput());
}

void historyTable(const std::vector<IterationRecord>& history, vtkTable* table)
{
  vtkNew<vtkIntArray> run, iteration;
  vtkNew<vtkDoubleArray> energy, change, cloudError, seconds;
  vtkNew<vtkIdTypeArray> band;
  run->SetName("Run");
  iteration->SetName("Iteration");
  energy->SetName("Energy");
  change->SetName("Change");
  cloudError->SetName("CloudError");
  band->SetName("BandSize");
  seconds->SetName("Seconds");
  for (const IterationRecord& r : history)
  {
    run->InsertNextValue(r.Run);
    iteration->InsertNextValue(r.Iteration);
    energy->InsertNextValue(r.Energy);
    change->InsertNextValue(r.Change);
    cloudError->InsertNextValue(r.CloudError);
    band->InsertNextValue(static_cast<vtkIdType>(r.BandSize));
    seconds->InsertNextValue(r.Seconds);
  }
  table->AddColumn(run);
  table->AddColumn(iteration);
  table->AddColumn(energy);
  table->AddColumn(change);
  table->AddColumn(cloudError);
  table->AddColumn(band);
  table->AddColumn(seconds);
}

template void toImage(const ReconstructionResult<2>&, double, vtkImageData*);
template void toImage(const ReconstructionResult<3>&, double, vtkImageData*);
template void runSummary(const ReconstructionResult<2>&, vtkImageData*);
template void runSummary(const ReconstructionResult<3>&, vtkImageData*);

} // namespace vtkbridge
} // namespace sltk
