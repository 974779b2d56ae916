// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSLLevelSetReconstruct.h"

#include "SLTKBridge.h"

#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"

vtkStandardNewMacro(vtkSLLevelSetReconstruct);

vtkSLLevelSetReconstruct::vtkSLLevelSetReconstruct()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
}

int vtkSLLevelSetReconstruct::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkSLLevelSetReconstruct::FillOutputPortInformation(int port, vtkInformation* info)
{
  static const char* types[3] = { "vtkImageData", "vtkPolyData", "vtkTable" };
  info->Set(vtkDataObject::DATA_TYPE_NAME(), types[port]);
  return 1;
}

int vtkSLLevelSetReconstruct::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // The grid follows from the data (h_P, bounding box), which the pipeline
  // has not produced yet: the image is made whole in RequestData and the
  // filter answers piece requests, like unstructured producers do.
  for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    outInfo->Remove(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
    outInfo->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  }
  return 1;
}

int vtkSLLevelSetReconstruct::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  sltk::PointCloud<3> cloud;
  const sltk::Status status = sltk::vtkbridge::toValidCloud(input, cloud);
  if (!status.isOk())
  {
    vtkErrorMacro("Input point set rejected: " << status.message());
    return 0;
  }
  vtkErrorMacro("The input (" << cloud.size()
                              << " points) is valid, but the level-set reconstruction "
                                 "(thesis Algorithm 1) is not implemented in this SLTK version; "
                                 "no output was produced.");
  return 0;
}

void vtkSLLevelSetReconstruct::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* names[4] = { "Q1", "WENO3", "CWENO", "CWENOZ" };
  os << indent << "Interpolator: " << names[this->Interpolator] << "\n";
  os << indent << "NumberOfRuns: " << this->NumberOfRuns << "\n";
  os << indent << "CellSizeFactor: " << this->CellSizeFactor << "\n";
  os << indent << "OutsideThresholdFactor: " << this->OutsideThresholdFactor << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
