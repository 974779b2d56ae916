// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCWENOHJBSolver.h"

#include "sltk/hjb/InitialData.h"

#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

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

bool vtkCWENOHJBSolver::ValidateGrid()
{
  static const char axis[3] = { 'x', 'y', 'z' };
  for (int a = 0; a < 3; ++a)
  {
    const bool used = this->Dimensions[a] > 1;
    if (this->Dimensions[a] < 1 || (used && this->Dimensions[a] < 3))
    {
      vtkErrorMacro("Dimensions along " << axis[a] << " is " << this->Dimensions[a]
                                        << ": use 1 for an unused axis or at least 3 nodes.");
      return false;
    }
    if (used && !(this->Bounds[2 * a + 1] > this->Bounds[2 * a]))
    {
      vtkErrorMacro("Bounds along " << axis[a] << " are [" << this->Bounds[2 * a] << ", "
                                    << this->Bounds[2 * a + 1] << "]: the maximum must exceed the minimum.");
      return false;
    }
  }
  if (this->Preset == Test1Rotation && (this->Dimensions[0] < 3 || this->Dimensions[1] < 3 || this->Dimensions[2] != 1))
  {
    vtkErrorMacro("Preset Test1Rotation is a 2D problem: set Dimensions to (N, N, 1).");
    return false;
  }
  const double nodes = double(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  if (nodes > 2e9)
  {
    vtkErrorMacro("The grid has " << nodes << " nodes, more than SLTK handles on one machine (2e9): "
                                  << "reduce Dimensions.");
    return false;
  }
  return true;
}

int vtkCWENOHJBSolver::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->ValidateGrid())
  {
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  double origin[3], spacing[3];
  for (int a = 0; a < 3; ++a)
  {
    extent[2 * a] = 0;
    extent[2 * a + 1] = this->Dimensions[a] - 1;
    origin[a] = this->Bounds[2 * a];
    spacing[a] = this->Dimensions[a] > 1
      ? (this->Bounds[2 * a + 1] - this->Bounds[2 * a]) / (this->Dimensions[a] - 1)
      : 1.0;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_DOUBLE, 1);
  return 1;
}

int vtkCWENOHJBSolver::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->ValidateGrid())
  {
    return 0;
  }
  if (this->FinalTime > 0.0)
  {
    vtkErrorMacro("FinalTime = " << this->FinalTime
                                 << ": time stepping of the HJB scheme (3.7) is not implemented in this "
                                    "SLTK version; set FinalTime to 0 for the initial datum.");
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  double origin[3], spacing[3];
  outInfo->Get(vtkDataObject::ORIGIN(), origin);
  outInfo->Get(vtkDataObject::SPACING(), spacing);
  output->SetExtent(extent);
  output->SetOrigin(origin);
  output->SetSpacing(spacing);

  vtkNew<vtkDoubleArray> value;
  value->SetName("ValueFunction");
  value->SetNumberOfTuples(output->GetNumberOfPoints());
  vtkIdType id = 0;
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      for (int i = extent[0]; i <= extent[1]; ++i, ++id)
      {
        value->SetValue(id, sltk::rotatingBump(origin[0] + i * spacing[0], origin[1] + j * spacing[1]));
      }
    }
  }
  output->GetPointData()->SetScalars(value);
  return 1;
}

void vtkCWENOHJBSolver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Preset: " << this->Preset << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "Bounds:";
  for (double b : this->Bounds)
  {
    os << " " << b;
  }
  os << "\n";
  os << indent << "FinalTime: " << this->FinalTime << "\n";
  os << indent << "CourantNumber: " << this->CourantNumber << "\n";
  os << indent << "RungeKuttaOrder: " << this->RungeKuttaOrder << "\n";
  os << indent << "Interpolator: " << this->Interpolator << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
