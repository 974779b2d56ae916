// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSLLevelSetReconstruct.h"

#include "SLTKBridge.h"
#include "SLTKCloudPieces.h"
#include "SLTKCommunicator.h"
#include "SLTKGuard.h"
#include "SLTKReconstructionOutput.h"
#include "SLTKTiledGrid.h"
#include "SLTKTiledSurface.h"
#include "SLTKUserFrame.h"

#include "sltk/cloud/CloudPieces.h"
#include "sltk/cloud/LocalFrame.h"
#include "sltk/exec/CountingCommunicator.h"
#include "sltk/exec/Memory.h"
#include "sltk/octree/TiledReconstruction.h"
#include "sltk/recon/OptionRanges.h"
#include "sltk/recon/Reconstruction.h"

#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLogger.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"

#include <algorithm>
#include <memory>
#include <set>
#include <sstream>

vtkStandardNewMacro(vtkSLLevelSetReconstruct);
vtkCxxSetObjectMacro(vtkSLLevelSetReconstruct, Controller, vtkMultiProcessController);

vtkSLLevelSetReconstruct::vtkSLLevelSetReconstruct()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
}

vtkSLLevelSetReconstruct::~vtkSLLevelSetReconstruct()
{
  this->SetController(nullptr);
}

int vtkSLLevelSetReconstruct::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

namespace
{
const sltk::OptionRange* rangeRow(int i)
{
  return i >= 0 && i < sltk::OptionRangeCount ? &sltk::OptionRanges[i] : nullptr;
}
} // namespace

int vtkSLLevelSetReconstruct::GetNumberOfPropertyRanges()
{
  return sltk::OptionRangeCount;
}

const char* vtkSLLevelSetReconstruct::GetPropertyRangeName(int i)
{
  return rangeRow(i) ? rangeRow(i)->Property : nullptr;
}

double vtkSLLevelSetReconstruct::GetPropertyRangeMinimum(int i)
{
  return rangeRow(i) ? rangeRow(i)->Min : 0.0;
}

double vtkSLLevelSetReconstruct::GetPropertyRangeMaximum(int i)
{
  return rangeRow(i) ? rangeRow(i)->Max : 0.0;
}

bool vtkSLLevelSetReconstruct::GetPropertyRangeZeroIsAutomatic(int i)
{
  return rangeRow(i) && rangeRow(i)->ZeroIsAutomatic;
}

int vtkSLLevelSetReconstruct::FillOutputPortInformation(int port, vtkInformation* info)
{
  // Port 0: vtkImageData or, with OctreeStorage, vtkHyperTreeGrid (RequestDataObject).
  static const char* types[3] = { "vtkDataObject", "vtkPolyData", "vtkTable" };
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
static_assert(vtkSLLevelSetReconstruct::Q1 == static_cast<int>(sltk::InterpolatorKind::Q1) &&
    vtkSLLevelSetReconstruct::WENO3 == static_cast<int>(sltk::InterpolatorKind::Weno3) &&
    vtkSLLevelSetReconstruct::CWENO == static_cast<int>(sltk::InterpolatorKind::Cweno) &&
    vtkSLLevelSetReconstruct::CWENOZ == static_cast<int>(sltk::InterpolatorKind::CwenoZ),
  "the filter's InterpolatorType names the registry's codes (InterpolatorKind.h)");

/// The properties' ranges, Core's (OptionRanges.h: the plugin XML's domains are
/// made from them): a value outside is refused with its name and range, never clamped.
sltk::Status checkRanges(vtkSLLevelSetReconstruct* self)
{
  SLTK_RETURN_IF_ERROR(sltk::vtkbridge::checkPropertyRanges({
    { "InitialGuess", double(self->GetInitialGuess()), 0, 2 }, // an enumeration
  }));
  return sltk::vtkbridge::checkOptionRanges({
    { "NumberOfRuns", double(self->GetNumberOfRuns()) },
    { "MaximumNumberOfIterations", double(self->GetMaximumNumberOfIterations()) },
    { "Tolerance", self->GetTolerance() },
    { "Padding", double(self->GetPadding()) },
    { "FinalEta", self->GetFinalEta() },
    { "OutlierDeviations", self->GetOutlierDeviations() },
    { "ThinningFactor", self->GetThinningFactor() },
    { "NumberOfThreads", double(self->GetNumberOfThreads()) },
    { "CellSizeFactor", self->GetCellSizeFactor() },
    { "MaximumLevel", double(self->GetMaximumLevel()) },
    { "OutsideThresholdFactor", self->GetOutsideThresholdFactor() },
    { "MemoryBudget", double(self->GetMemoryBudget()) },
  });
}

sltk::Status optionsOf(vtkSLLevelSetReconstruct* self, sltk::ReconstructionOptions& o)
{
  SLTK_RETURN_IF_ERROR(checkRanges(self));
  o = sltk::ReconstructionOptions{};
  o.Runs = self->GetNumberOfRuns();
  o.CellSizeFactor = self->GetCellSizeFactor();
  o.MaximumLevel = self->GetMaximumLevel();
  o.OutsideThresholdFactor = self->GetOutsideThresholdFactor();
  o.Padding = self->GetPadding();
  o.MaxIterations = self->GetMaximumNumberOfIterations();
  o.Tolerance = self->GetTolerance();
  o.Guess = static_cast<sltk::InitialGuess>(self->GetInitialGuess());
  if (self->GetNumberOfRunParameterValues() % 2 != 0)
  {
    return sltk::Status::invalidArgument("RunParameters has " + std::to_string(self->GetNumberOfRunParameterValues()) +
      " values: give (p, eta) pairs, an even number of values (or none for Table 4.1)");
  }
  for (int k = 0; k < self->GetNumberOfRunParameters(); ++k)
  {
    o.Schedule.push_back({ self->GetRunP(k), self->GetRunEta(k) });
  }
  if (o.Schedule.empty() && self->GetFinalEta() != sltk::table41(3).Eta)
  {
    // Table 4.1 with eta of runs >= 3 replaced (noisy data: Fig. 4.8, 4.11).
    o.Schedule = { sltk::table41(1), sltk::table41(2), { sltk::table41(3).P, self->GetFinalEta() } };
  }
  o.MemoryBudget = static_cast<std::uint64_t>(self->GetMemoryBudget()) << 20;
  o.Cleaning.Automatic = self->GetAutomaticCleaning();
  o.LocalOffset = self->GetLocalOffset();
  o.FollowFarPoints = self->GetFollowFarPoints();
  o.Cleaning.RemoveOutliers = self->GetRemoveOutliers();
  o.Cleaning.Outliers.Deviations = self->GetOutlierDeviations();
  o.Cleaning.ThinningFactor = self->GetThinningFactor();
  o.DetectTunnels = self->GetDetectTunnels();
  o.LeastSquaresQ1 = self->GetLeastSquaresQ1();
  return sltk::vtkbridge::interpolatorOf(self->GetInterpolator(), o.Interpolator);
}

constexpr int EveryGhostLevel = 32; // ParaView asks for 1, some filters 2-3

/// One execution makes all three outputs. Say so in the data information:
/// the surface and the table are complete for every ghost level, and so is
/// the image on one rank (piece 0 holds the whole grid); a distributed image
/// holds the `imageGhostLevels` it was given (toImage()), so a consumer that
/// needs more (ParaView's Gradient asks for one) runs the reconstruction again
/// and gets them. Drop the piece keys that the internal contour filter left on
/// the surface (ShallowCopy), so that the executive stamps the requested piece
/// on every output. Otherwise, under MPI, ParaView's request of port 1 with
/// one ghost level executes the whole reconstruction a second time.
void markOutputsComplete(vtkInformationVector* outputs, int imageGhostLevels = EveryGhostLevel)
{
  for (int port = 0; port < outputs->GetNumberOfInformationObjects(); ++port)
  {
    vtkDataObject* data = outputs->GetInformationObject(port)->Get(vtkDataObject::DATA_OBJECT());
    if (data)
    {
      data->GetInformation()->Remove(vtkDataObject::DATA_PIECE_NUMBER());
      data->GetInformation()->Remove(vtkDataObject::DATA_NUMBER_OF_PIECES());
      data->GetInformation()->Set(
        vtkDataObject::DATA_NUMBER_OF_GHOST_LEVELS(), port == 0 ? imageGhostLevels : EveryGhostLevel);
    }
  }
}

/// Port 0 as the type RequestDataObject makes for OctreeStorage (a hyper
/// tree grid with it, an image without); null, with the error, otherwise.
template <class T>
T* portZeroAs(vtkSLLevelSetReconstruct* self, vtkDataObject* output)
{
  T* typed = T::SafeDownCast(output);
  if (!typed)
  {
    vtkErrorWithObjectMacro(self,
      "port 0 is a " << (output ? output->GetClassName() : "null") << " where OctreeStorage "
                     << (self->GetOctreeStorage() ? "on" : "off")
                     << " needs another type: update the pipeline after changing it");
  }
  return typed;
}

/// Runs 2..R stored as tiles (OctreeStorage): the field as a hyper tree grid
/// (every stored node's distance to the cloud computed first), the surface
/// contoured tile by tile, the run summary with the stored and the uniform
/// node counts per run. Under MPI the ranks share the tiles out while they
/// compute (Documentation/Octree.md, "Distributing the tiled band"); each rank
/// outputs its pieces of the hyper tree grid and of the surface, rank 0 also
/// the history and the run summary.
template <int D>
int reconstructTiledInto(vtkSLLevelSetReconstruct* self, const sltk::ReconstructionPlan<D>& plan, double z,
  const sltk::Context& ctx, const sltk::Communicator& comm, vtkDataObject* output, vtkPolyData* surface,
  vtkTable* history)
{
  auto* grid = portZeroAs<vtkHyperTreeGrid>(self, output);
  if (!grid)
  {
    return 0;
  }
  sltk::TiledReconstructionResult<D> result;
  const sltk::CountingCommunicator counted(comm);
  const sltk::Status status = sltk::reconstructTiled(plan, ctx, result, counted); // the same status on every rank
  if (!status.isOk())
  {
    vtkErrorWithObjectMacro(self, "Reconstruction failed: " << status.message());
    return 0;
  }
  const std::int64_t bytesSent = counted.bytesSent(), collectives = counted.collectives();
  grid->Initialize();
  // Each rank outputs its own trees and contours its own blocks of tiles (its ghosts hold the
  // nodes around them): the pieces join.
  sltk::vtkbridge::tiledZeroLevelSet(result.Field, result.Box, surface, result.Owners, comm.rank(), z);
  if (self->GetGenerateHyperTreeGrid())
  {
    sltk::completeTiledDistances(plan, ctx, result.Field, result.Owners, comm.rank()); // its own tiles
    const sltk::PointLocator<D>& locator = *plan.Locator;
    sltk::vtkbridge::tiledToHyperTreeGrid<D>(
      result.Field, result.Box, [&locator](const std::array<double, D>& x) { return locator.nearest(x).Distance; },
      grid, result.Owners, comm.rank(), z); // Initialize()s the grid: its field data after it
    if (!result.Storage.empty())
    {
      vtkNew<vtkDoubleArray> leaves; // the trees' leaves over every rank, on every rank
      leaves->SetName("GlobalLeaves");
      leaves->InsertNextValue(static_cast<double>(result.Storage.back().Leaves));
      grid->GetFieldData()->AddArray(leaves);
    }
  }
  sltk::vtkbridge::communicationSummary(comm.size(), bytesSent, collectives, grid);
  if (comm.rank() > 0)
  {
    return 1; // the history and the run summary once, on rank 0
  }
  sltk::vtkbridge::runSummary(result.Records, grid);
  vtkNew<vtkDoubleArray> stored, uniform, leaves, largest;
  stored->SetName("RunStoredNodes");
  uniform->SetName("RunUniformNodes");
  leaves->SetName("RunLeaves");
  largest->SetName("RunLargestRankLeaves");
  for (size_t r = 0; r < result.Records.Runs.size(); ++r)
  {
    // Run 1 is uniform (its grid is the coarsest: a leaf per node; the largest rank's, its
    // slab's, from the history), but for a single run, which is then stored in tiles: every
    // tiled run has a storage record.
    const double all = static_cast<double>(result.Records.Runs[r].Grid.nodeCount());
    double held = all, leafCount = all, largestCount = all;
    for (const sltk::IterationRecord& it : result.Records.History)
    {
      largestCount = it.Run == static_cast<int>(r + 1) ? static_cast<double>(it.LargestRankLeaves) : largestCount;
    }
    for (const sltk::TiledRunRecord& run : result.Storage)
    {
      const bool thisRun = run.Run == static_cast<int>(r + 1);
      held = thisRun ? static_cast<double>(run.StoredNodes) : held;
      leafCount = thisRun ? static_cast<double>(run.Leaves) : leafCount;
      largestCount = thisRun ? static_cast<double>(run.LargestRankLeaves) : largestCount;
    }
    stored->InsertNextValue(held);
    uniform->InsertNextValue(all);
    leaves->InsertNextValue(leafCount);
    largest->InsertNextValue(largestCount);
  }
  grid->GetFieldData()->AddArray(stored);
  grid->GetFieldData()->AddArray(uniform);
  grid->GetFieldData()->AddArray(leaves);
  grid->GetFieldData()->AddArray(largest);
  sltk::vtkbridge::historyTable(result.Records.History, history);
  return 1;
}

/// Plans (ReconstructionPlan.h) and runs Algorithm 1 on `cloud` (moved in),
/// then fills the image (lying in the plane z = `z` in 2D), the history and,
/// with OctreeStorage, the surface.
template <int D>
int reconstructInto(vtkSLLevelSetReconstruct* self, sltk::PointCloud<D> cloud, double z, const sltk::Context& ctx,
  const sltk::Communicator& comm, int ghostLevels, vtkDataObject* output, vtkPolyData* surface, vtkTable* history)
{
  sltk::ReconstructionOptions options;
  sltk::Status status = optionsOf(self, options);
  if (!status.isOk())
  {
    vtkErrorWithObjectMacro(self, << status.message());
    return 0;
  }
  options.Ranks = comm.size(); // the memory check sizes this machine's ranks' windows
  options.RanksHere = sltk::ranksSharingThisMachine(comm.size());
  options.OctreeStorage = self->GetOctreeStorage();
  sltk::ReconstructionPlan<D> plan;
  status = comm.agree(sltk::planReconstruction(std::move(cloud), options, ctx, plan));
  if (!status.isOk())
  {
    vtkErrorWithObjectMacro(self, "Input point set rejected: " << status.message());
    return 0;
  }
  if (self->GetOctreeStorage()) // a planar cloud: quadtrees in the plane z
  {
    return reconstructTiledInto<D>(self, plan, z, ctx, comm, output, surface, history);
  }
  auto* image = portZeroAs<vtkImageData>(self, output);
  if (!image)
  {
    return 0;
  }
  sltk::ReconstructionResult<D> result;
  const sltk::CountingCommunicator counted(comm);
  status = sltk::reconstruct(plan, ctx, result, counted);
  if (!status.isOk())
  {
    vtkErrorWithObjectMacro(self, "Reconstruction failed: " << status.message());
    return 0;
  }
  sltk::vtkbridge::toImage(result, z, ghostLevels, image);
  sltk::vtkbridge::runSummary(result, image);
  sltk::vtkbridge::communicationSummary(comm.size(), counted.bytesSent(), counted.collectives(), image);
  if (comm.rank() == 0) // every rank has it; ParaView would append one copy per rank
  {
    sltk::vtkbridge::historyTable(result.History, history);
  }
  return 1;
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

vtkTypeBool vtkSLLevelSetReconstruct::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return sltk::vtkbridge::guardedRequest(this,
    [&]
    {
      if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
      {
        return this->RequestDataObject(request, inputVector, outputVector);
      }
      return this->Superclass::ProcessRequest(request, inputVector, outputVector);
    });
}

int vtkSLLevelSetReconstruct::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkDataObject* current = info->Get(vtkDataObject::DATA_OBJECT());
  if (this->OctreeStorage ? !vtkHyperTreeGrid::SafeDownCast(current) : !vtkImageData::SafeDownCast(current))
  {
    vtkSmartPointer<vtkDataObject> made;
    if (this->OctreeStorage)
    {
      made = vtkSmartPointer<vtkHyperTreeGrid>::New();
    }
    else
    {
      made = vtkSmartPointer<vtkImageData>::New();
    }
    info->Set(vtkDataObject::DATA_OBJECT(), made);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkSLLevelSetReconstruct::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0); // image or hyper tree grid
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);
  vtkTable* history = vtkTable::GetData(outputVector, 2);

  // Under MPI every rank has read the whole cloud (RequestUpdateExtent) and
  // reconstructs its slab of every run (a collective call on the Controller's
  // ranks), whatever piece it was asked for; on one rank a request for a piece
  // other than 0 gets empty outputs (piece 0 holds the whole result).
  std::unique_ptr<sltk::Communicator> comm;
  const sltk::Status made = sltk::vtkbridge::makeCommunicator(this->Controller, comm);
  if (!made.isOk())
  {
    vtkErrorMacro(<< made.message());
    return 0;
  }
  const int port =
    request->Has(vtkExecutive::FROM_OUTPUT_PORT()) ? std::max(0, request->Get(vtkExecutive::FROM_OUTPUT_PORT())) : 0;
  vtkInformation* outInfo = outputVector->GetInformationObject(port);
  if (comm->size() == 1 && outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    markOutputsComplete(outputVector);
    return 1;
  }
  sltk::PointCloud<3> cloud;
  const sltk::Status status = comm->agree(sltk::vtkbridge::toCloud(input, cloud));
  if (!status.isOk())
  {
    vtkErrorMacro("Input point set rejected: " << status.message());
    return 0;
  }
  // Every rank needs the whole cloud. A caller that gave each rank its own piece (a
  // distributed data set, or points on one rank only) gets the union of the pieces
  // (CloudPieces.h); the surface's DistanceToCloud and the cloud's point arrays are then
  // taken from every piece (SLTKCloudPieces.h).
  const bool joined = sltk::joinCloudPieces(cloud, *comm);
  if (joined)
  {
    vtkLog(
      INFO, "the ranks held different pieces of the cloud: reconstructing their union, " << cloud.size() << " points");
  }
  // Survey coordinates: a cloud far from the origin for its size is reconstructed in its
  // local frame and the outputs are put back (LocalFrame.h). Its precision is checked
  // where the user gave it: moved, it would hide digits the file never had.
  const std::array<double, 3> shift =
    cloud.Points.empty() ? std::array<double, 3>{} : sltk::localFrameShift(sltk::boundingBox(cloud));
  const sltk::Status precise = comm->agree(sltk::isZeroShift(shift) ? sltk::Status::ok() : sltk::validateCloud(cloud));
  if (!precise.isOk())
  {
    vtkErrorMacro("Input point set rejected: " << precise.message());
    return 0;
  }
  sltk::moveToLocalFrame(cloud, shift);

  const sltk::Status ranges = comm->agree(checkRanges(this)); // before the thread pool takes NumberOfThreads
  if (!ranges.isOk())
  {
    vtkErrorMacro(<< ranges.message());
    return 0;
  }
  sltk::ThreadPool pool(sltk::threadsPerRank(this->NumberOfThreads, comm->size()));
  this->ThreadsUsed = pool.size();
  sltk::vtkbridge::AlgorithmInterrupter progress(this);
  sltk::vtkbridge::VTKLogger logger;
  sltk::Context ctx;
  ctx.Executor = &pool;
  ctx.Progress = &progress;
  ctx.Log = &logger;
  // The ghost levels asked of the image (ParaView asks structured data for one under MPI).
  vtkInformation* imageInfo = outputVector->GetInformationObject(0);
  const int ghostLevels = imageInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    ? imageInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    : 0;
  sltk::PointCloud<2> flat;
  double z = 0.0;
  const int done = sltk::flattenIfPlanar(cloud, flat, z)
    ? reconstructInto<2>(this, std::move(flat), z, ctx, *comm, ghostLevels, output, surface, history)
    : reconstructInto<3>(this, std::move(cloud), 0.0, ctx, *comm, ghostLevels, output, surface, history);
  if (!done)
  {
    return 0;
  }
  if (!this->OctreeStorage)
  {
    sltk::vtkbridge::zeroLevelSet(vtkImageData::SafeDownCast(output), surface);
  }
  sltk::vtkbridge::toUserFrame(shift, output, surface);
  vtkSmartPointer<vtkPointSet> attributesFrom = input;
  if (joined) // every piece with its arrays, now that the reconstruction's memory is free
  {
    std::set<std::string> dropped;
    attributesFrom = sltk::vtkbridge::piecesWithPointData(input, *comm, &dropped);
    for (const std::string& name : dropped)
    {
      vtkWarningMacro("the cloud's point array '"
        << name << "' is not on the surface: some ranks' pieces lack it or hold another type or number of "
        << "components; give every piece the same arrays");
    }
  }
  sltk::vtkbridge::transferCloudAttributes(attributesFrom, surface);
  markOutputsComplete(outputVector,
    comm->size() > 1 && !this->OctreeStorage ? std::min(ghostLevels, sltk::vtkbridge::ImageGhostLevelsAvailable)
                                             : EveryGhostLevel);
  return 1;
}

void vtkSLLevelSetReconstruct::AddRunParameters(double p, double eta)
{
  this->RunSchedule.push_back(p);
  this->RunSchedule.push_back(eta);
  this->Modified();
}

void vtkSLLevelSetReconstruct::AddRunParameterValue(double value)
{
  this->RunSchedule.push_back(value);
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

int vtkSLLevelSetReconstruct::GetNumberOfRunParameterValues() const
{
  return static_cast<int>(this->RunSchedule.size());
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
  sltk::InterpolatorKind kind{};
  os << indent << "Interpolator: "
     << (sltk::interpolatorFromCode(this->Interpolator, kind) ? sltk::interpolatorInfo(kind).Label : "?") << "\n";
  os << indent << "NumberOfRuns: " << this->NumberOfRuns << "\n";
  os << indent << "CellSizeFactor: " << this->CellSizeFactor << "\n";
  os << indent << "MaximumLevel: " << this->MaximumLevel << "\n";
  os << indent << "OutsideThresholdFactor: " << this->OutsideThresholdFactor << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << " MB\n";
  os << indent << "AutomaticCleaning: " << this->AutomaticCleaning << "\n";
  os << indent << "LocalOffset: " << this->LocalOffset << "\n";
  os << indent << "FollowFarPoints: " << this->FollowFarPoints << "\n";
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
  os << indent << "LeastSquaresQ1: " << this->LeastSquaresQ1 << "\n";
  os << indent << "OctreeStorage: " << this->OctreeStorage << "\n";
  os << indent << "GenerateHyperTreeGrid: " << this->GenerateHyperTreeGrid << "\n";
  os << indent << "OutlierDeviations: " << this->OutlierDeviations << "\n";
  os << indent << "ThinningFactor: " << this->ThinningFactor << "\n";
}
