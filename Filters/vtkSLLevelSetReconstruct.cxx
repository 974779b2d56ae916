// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSLLevelSetReconstruct.h"

#include "SLTKBridge.h"
#include "SLTKReconstructionOutput.h"

#include "sltk/recon/Reconstruction.h"

#include "vtkDataObject.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"

#include <algorithm>

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

namespace
{
sltk::ReconstructionOptions optionsOf(vtkSLLevelSetReconstruct* self)
{
  sltk::ReconstructionOptions o;
  o.Runs = self->GetNumberOfRuns();
  o.CellSizeFactor = self->GetCellSizeFactor();
  o.OutsideThresholdFactor = self->GetOutsideThresholdFactor();
  o.Padding = self->GetPadding();
  o.MaxIterations = self->GetMaximumNumberOfIterations();
  o.Tolerance = self->GetTolerance();
  o.Interpolator = static_cast<sltk::InterpolatorKind>(self->GetInterpolator());
  o.Guess = static_cast<sltk::InitialGuess>(self->GetInitialGuess());
  for (int k = 0; k < self->GetNumberOfRunParameters(); ++k)
  {
    o.Schedule.push_back({ self->GetRunP(k), self->GetRunEta(k) });
  }
  if (o.Schedule.empty() && self->GetFinalEta() != sltk::table41(3).Eta)
  {
    // Table 4.1 with eta of runs >= 3 replaced (noisy data: Fig. 4.8, 4.11).
    o.Schedule = { sltk::table41(1), sltk::table41(2), { sltk::table41(3).P, self->GetFinalEta() } };
  }
  o.Cleaning.RemoveOutliers = self->GetRemoveOutliers();
  o.Cleaning.Outliers.Deviations = self->GetOutlierDeviations();
  o.Cleaning.ThinningFactor = self->GetThinningFactor();
  o.DetectTunnels = self->GetDetectTunnels();
  return o;
}

/// One execution makes all three outputs, and piece 0 holds the whole result:
/// every ghost level a consumer may ask for is there. Say so in the data
/// information, and drop the piece keys that the internal contour filter left on
/// the surface (ShallowCopy), so that the executive stamps the requested piece on
/// every output. Otherwise, under MPI, ParaView's request of port 1 with one
/// ghost level executes the whole reconstruction a second time.
void markOutputsComplete(vtkInformationVector* outputs)
{
  constexpr int everyGhostLevel = 32; // ParaView asks for 1, some filters 2-3
  for (int port = 0; port < outputs->GetNumberOfInformationObjects(); ++port)
  {
    vtkDataObject* data = outputs->GetInformationObject(port)->Get(vtkDataObject::DATA_OBJECT());
    if (data)
    {
      data->GetInformation()->Remove(vtkDataObject::DATA_PIECE_NUMBER());
      data->GetInformation()->Remove(vtkDataObject::DATA_NUMBER_OF_PIECES());
      data->GetInformation()->Set(vtkDataObject::DATA_NUMBER_OF_GHOST_LEVELS(), everyGhostLevel);
    }
  }
}

/// The cloud in its plane when it has no z extent (2D reconstruction).
bool flatten(const sltk::PointCloud<3>& cloud, sltk::PointCloud<2>& flat, double& z)
{
  const auto box = sltk::boundingBox(cloud);
  if (box.extent(2) != 0.0)
  {
    return false;
  }
  z = box.Min[2];
  flat.Points.resize(cloud.Points.size());
  for (size_t k = 0; k < cloud.Points.size(); ++k)
  {
    flat.Points[k] = { cloud.Points[k][0], cloud.Points[k][1] };
  }
  return true;
}
} // namespace

int vtkSLLevelSetReconstruct::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The model needs the whole cloud (h_P (4.36), the bounding box and the
  // distance function see every point), whatever piece is asked of us.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

int vtkSLLevelSetReconstruct::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  vtkImageData* image = vtkImageData::GetData(outputVector, 0);
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);
  vtkTable* history = vtkTable::GetData(outputVector, 2);

  sltk::PointCloud<3> cloud;
  sltk::PointCloud<2> flat;
  double z = 0.0;
  sltk::Status status = sltk::vtkbridge::toCloud(input, cloud);
  // Under MPI each rank is asked for one piece and has read the whole cloud
  // (RequestUpdateExtent): piece 0 reconstructs, the other pieces stay empty
  // (distributed runs are not built yet).
  const int port = request->Has(vtkExecutive::FROM_OUTPUT_PORT())
    ? std::max(0, request->Get(vtkExecutive::FROM_OUTPUT_PORT()))
    : 0;
  vtkInformation* outInfo = outputVector->GetInformationObject(port);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    markOutputsComplete(outputVector);
    return 1;
  }
  const bool planar = status.isOk() && !cloud.Points.empty() && flatten(cloud, flat, z);
  if (status.isOk())
  {
    status = planar ? sltk::validateCloud(flat) : sltk::validateCloud(cloud);
  }
  if (!status.isOk())
  {
    vtkErrorMacro("Input point set rejected: " << status.message());
    return 0;
  }

  sltk::ThreadPool pool(this->NumberOfThreads);
  sltk::vtkbridge::AlgorithmInterrupter progress(this);
  sltk::vtkbridge::VTKLogger logger;
  sltk::Context ctx;
  ctx.Executor = &pool;
  ctx.Progress = &progress;
  ctx.Log = &logger;
  const sltk::ReconstructionOptions options = optionsOf(this);
  sltk::ReconstructionResult<2> result2;
  sltk::ReconstructionResult<3> result3;
  status = planar ? sltk::reconstruct(flat, options, ctx, result2) : sltk::reconstruct(cloud, options, ctx, result3);
  if (!status.isOk())
  {
    vtkErrorMacro("Reconstruction failed: " << status.message());
    return 0;
  }
  if (planar)
  {
    sltk::vtkbridge::toImage(result2, z, image);
    sltk::vtkbridge::runSummary(result2, image);
    sltk::vtkbridge::historyTable(result2.History, history);
  }
  else
  {
    sltk::vtkbridge::toImage(result3, 0.0, image);
    sltk::vtkbridge::runSummary(result3, image);
    sltk::vtkbridge::historyTable(result3.History, history);
  }
  sltk::vtkbridge::zeroLevelSet(image, surface);
  markOutputsComplete(outputVector);
  return 1;
}

void vtkSLLevelSetReconstruct::AddRunParameters(double p, double eta)
{
  this->RunSchedule.push_back(p);
  this->RunSchedule.push_back(eta);
  this->Modified();
}

void vtkSLLevelSetReconstruct::RemoveAllRunParameters()
{
  if (!this->RunSchedule.empty())
  {
    this->RunSchedule.clear();
    this->Modified();
  }
}

int vtkSLLevelSetReconstruct::GetNumberOfRunParameters() const
{
  return static_cast<int>(this->RunSchedule.size() / 2);
}

double vtkSLLevelSetReconstruct::GetRunP(int index) const
{
  return index >= 0 && index < this->GetNumberOfRunParameters() ? this->RunSchedule[2 * static_cast<size_t>(index)]
                                                                : 0.0;
}

double vtkSLLevelSetReconstruct::GetRunEta(int index) const
{
  return index >= 0 && index < this->GetNumberOfRunParameters() ? this->RunSchedule[2 * static_cast<size_t>(index) + 1]
                                                                : 0.0;
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
  os << indent << "InitialGuess: " << this->InitialGuess << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "FinalEta: " << this->FinalEta << "\n";
  os << indent << "RunParameters (p, eta):";
  for (int k = 0; k < this->GetNumberOfRunParameters(); ++k)
  {
    os << " (" << this->GetRunP(k) << ", " << this->GetRunEta(k) << ")";
  }
  os << (this->RunSchedule.empty() ? " none (Table 4.1)\n" : "\n");
  os << indent << "RemoveOutliers: " << this->RemoveOutliers << "\n";
  os << indent << "DetectTunnels: " << this->DetectTunnels << "\n";
  os << indent << "OutlierDeviations: " << this->OutlierDeviations << "\n";
  os << indent << "ThinningFactor: " << this->ThinningFactor << "\n";
}
