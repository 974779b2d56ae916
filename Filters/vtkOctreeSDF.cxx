// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOctreeSDF.h"

#include "SLTKBridge.h"

#include "vtkDemandDrivenPipeline.h"
#include "vtkHyperTreeGrid.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkStreamingDemandDrivenPipeline.h"

vtkStandardNewMacro(vtkOctreeSDF);

vtkOctreeSDF::vtkOctreeSDF()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkOctreeSDF::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkOctreeSDF::FillOutputPortInformation(int, vtkInformation* info)
{
  // The executive creates this type; the input type is never passed through.
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkHyperTreeGrid");
  return 1;
}

vtkHyperTreeGrid* vtkOctreeSDF::GetOutput()
{
  return vtkHyperTreeGrid::SafeDownCast(this->GetOutputDataObject(0));
}

vtkTypeBool vtkOctreeSDF::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
    return 1;
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkOctreeSDF::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  if (this->MinimumLevel > this->MaximumLevel)
  {
    vtkErrorMacro("MinimumLevel (" << this->MinimumLevel << ") exceeds MaximumLevel (" << this->MaximumLevel
                                   << "): lower MinimumLevel or raise MaximumLevel.");
    return 0;
  }
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  sltk::PointCloud<3> cloud;
  const sltk::Status status = sltk::vtkbridge::toValidCloud(input, cloud);
  if (!status.isOk())
  {
    vtkErrorMacro("Input point set rejected: " << status.message());
    return 0;
  }
  vtkErrorMacro("The input (" << cloud.size()
                              << " points) is valid, but the octree level-set solver (thesis ch. 5) "
                                 "is not implemented in this SLTK version; no output was produced.");
  return 0;
}

void vtkOctreeSDF::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumLevel: " << this->MinimumLevel << "\n";
  os << indent << "MaximumLevel: " << this->MaximumLevel << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
