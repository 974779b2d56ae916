// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCWENOHJBSolver.h"

#include "SLTKBridge.h"

#include "sltk/hjb/PresetRun.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>

vtkStandardNewMacro(vtkCWENOHJBSolver);

vtkCWENOHJBSolver::vtkCWENOHJBSolver()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

int vtkCWENOHJBSolver::FillInputPortInformation(int, vtkInformation*)
{
  return 1;
}

int vtkCWENOHJBSolver::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  sltk::PresetGrid grid;
  const sltk::Status status =
    sltk::presetGrid(static_cast<sltk::HjbPreset>(this->Preset), this->NumberOfNodes, grid);
  if (!status.isOk())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  for (int a = 0; a < 3; ++a)
  {
    extent[2 * a] = 0;
    extent[2 * a + 1] = static_cast<int>(grid.Dims[a]) - 1;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), grid.Origin.data(), 3);
  outInfo->Set(vtkDataObject::SPACING(), grid.Spacing.data(), 3);
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_DOUBLE, 1);
  return 1;
}

namespace
{
/// The block `extent` of a whole-grid node array (x fastest).
vtkSmartPointer<vtkDoubleArray> block(
  const std::vector<double>& values, const sltk::PresetGrid& grid, const int extent[6], const char* name)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfTuples(static_cast<vtkIdType>(extent[1] - extent[0] + 1) * (extent[3] - extent[2] + 1) *
    (extent[5] - extent[4] + 1));
  vtkIdType id = 0;
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      for (int i = extent[0]; i <= extent[1]; ++i, ++id)
      {
        const double v = values[static_cast<size_t>(i + grid.Dims[0] * (j + grid.Dims[1] * k))];
        array->SetValue(id, std::isinf(v) ? -1.0 : v); // never reached: -1 in ReachTime
      }
    }
  }
  return array;
}

void addScalar(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}
} // namespace

int vtkCWENOHJBSolver::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  sltk::PresetRunOptions options;
  options.Preset = static_cast<sltk::HjbPreset>(this->Preset);
  options.Nodes = this->NumberOfNodes;
  options.FinalTime = this->FinalTime;
  options.CourantNumber = this->CourantNumber;
  options.Interpolator = static_cast<sltk::InterpolatorKind>(this->Interpolator);
  sltk::ThreadPool pool(this->NumberOfThreads);
  sltk::vtkbridge::AlgorithmInterrupter progress(this);
  sltk::Context ctx;
  ctx.Executor = &pool;
  ctx.Progress = &progress;
  sltk::PresetRunResult result;
  const sltk::Status status = sltk::runPreset(options, ctx, result);
  if (!status.isOk())
  {
    vtkErrorMacro("HJB solve failed: " << status.message());
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  output->SetExtent(extent);
  output->SetOrigin(result.Grid.Origin.data());
  output->SetSpacing(result.Grid.Spacing.data());
  output->GetPointData()->SetScalars(block(result.Value, result.Grid, extent, "ValueFunction"));
  if (!result.ReachTime.empty())
  {
    output->GetPointData()->AddArray(block(result.ReachTime, result.Grid, extent, "ReachTime"));
  }
  vtkFieldData* fd = output->GetFieldData();
  addScalar(fd, "FinalTime", result.FinalTime);
  addScalar(fd, "Steps", static_cast<double>(result.Steps));
  addScalar(fd, "EvaluationsPerNode", result.EvaluationsPerNode);
  if (!std::isnan(result.L1Error))
  {
    addScalar(fd, "L1Error", result.L1Error);
    addScalar(fd, "LinfError", result.LinfError);
  }
  return 1;
}

void vtkCWENOHJBSolver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Preset: " << this->Preset << "\n";
  os << indent << "NumberOfNodes: " << this->NumberOfNodes << "\n";
  os << indent << "FinalTime: " << this->FinalTime << "\n";
  os << indent << "CourantNumber: " << this->CourantNumber << "\n";
  os << indent << "Interpolator: " << this->Interpolator << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
