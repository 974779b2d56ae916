// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOctreeSDF.h"

#include "SLTKBridge.h"
#include "SLTKCommunicator.h"
#include "SLTKGuard.h"
#ifdef SLTK_HAS_OCTREE
#include "SLTKOctreeOutput.h"
#include "sltk/octree/CloudForest.h"
#endif

#include "sltk/exec/ThreadPool.h"

#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <sstream>

vtkStandardNewMacro(vtkOctreeSDF);

namespace
{
/// The properties' documented ranges (the plugin XML's domains): a value
/// outside is refused with its name and range, never clamped.
sltk::Status checkRanges(vtkOctreeSDF* self)
{
  SLTK_RETURN_IF_ERROR(sltk::vtkbridge::checkPropertyRanges({
    { "MinimumLevel", double(self->GetMinimumLevel()), 0, 18 },
    { "MaximumLevel", double(self->GetMaximumLevel()), 0, 18 },
    { "NumberOfThreads", double(self->GetNumberOfThreads()), 0, 1024 },
    { "MemoryBudget", double(self->GetMemoryBudget()), 0, 16777216 },
  }));
  if (self->GetMinimumLevel() > self->GetMaximumLevel())
  {
    std::ostringstream m;
    m << "MinimumLevel (" << self->GetMinimumLevel() << ") exceeds MaximumLevel (" << self->GetMaximumLevel()
      << "): lower MinimumLevel or raise MaximumLevel";
    return sltk::Status::invalidArgument(m.str());
  }
  return sltk::Status::ok();
}

[[maybe_unused]] void addValue(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}
} // namespace

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
    return sltk::vtkbridge::guardedRequest(this, [&] { return this->RequestData(request, inputVector, outputVector); });
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkOctreeSDF::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkHyperTreeGrid* output = vtkHyperTreeGrid::GetData(outputVector, 0);
  if (output)
  {
    output->Initialize();
  }
  // Every rank reaches the agreement below, whatever failed locally, so that
  // an error on one rank ends every rank with it (Documentation/Octree.md).
  std::unique_ptr<sltk::Communicator> comm;
  sltk::Status status = sltk::vtkbridge::makeCommunicator(nullptr, comm);
  if (!status.isOk())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  status = checkRanges(this);
  sltk::PointCloud<3> points; // this rank's piece; may be empty
  if (status.isOk())
  {
    status = sltk::vtkbridge::toCloud(vtkPointSet::GetData(inputVector[0], 0), points);
  }
#ifdef SLTK_HAS_OCTREE
  status = comm->agree(status);
  if (!status.isOk())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  sltk::ThreadPool pool(this->NumberOfThreads);
  sltk::vtkbridge::VTKLogger logger;
  sltk::Context ctx;
  ctx.Executor = &pool;
  ctx.Log = &logger;
  sltk::octree::CloudForestOptions options;
  options.MinimumLevel = this->MinimumLevel;
  options.MaximumLevel = this->MaximumLevel;
  options.MemoryBudget = static_cast<std::uint64_t>(this->MemoryBudget) << 20;
  std::unique_ptr<sltk::octree::CloudForest> forest;
  status = sltk::octree::CloudForest::build(*comm, points, options, ctx, forest);
  if (!status.isOk())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  sltk::vtkbridge::forestToHyperTreeGrid(*forest, output);
  vtkFieldData* fd = output->GetFieldData();
  addValue(fd, "GlobalLeaves", static_cast<double>(forest->stats().GlobalLeaves));
  addValue(fd, "UniformCells", forest->stats().UniformCells);
  addValue(fd, "CloudSpacing", forest->cloudSpacing() * forest->unitBox().Scale);
  return 1;
#else
  status = comm->agree(status.isOk()
      ? sltk::Status::notImplemented("vtkOctreeSDF needs the p4est octree backend: this SLTK was built without it "
                                     "(SLTK_ENABLE_OCTREE=OFF or p4est not found; install libp4est-dev)")
      : status);
  vtkErrorMacro(<< status.message());
  return 0;
#endif
}

void vtkOctreeSDF::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumLevel: " << this->MinimumLevel << "\n";
  os << indent << "MaximumLevel: " << this->MaximumLevel << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << "\n";
}
