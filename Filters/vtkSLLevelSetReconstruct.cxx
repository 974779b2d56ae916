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
#include "sltk/recon/ReconstructionSummary.h"

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
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"

#include <algorithm>
#include <climits>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

vtkStandardNewMacro(vtkSLLevelSetReconstruct);
vtkCxxSetObjectMacro(vtkSLLevelSetReconstruct, Controller, vtkMultiProcessController);

struct vtkSLLevelSetReconstruct::Internals
{
  sltk::ReconstructionOptions Options; ///< the properties' values, Core's defaults
  /// Property values Core's options cannot hold, kept as given so that GetX
  /// returns them and the next execution refuses them with the property's name,
  /// as any value outside its range: an Interpolator or InitialGuess code outside
  /// Core's enumeration, a negative MemoryBudget, a RunParameters value still
  /// without its pair.
  std::optional<int> Interpolator, InitialGuess, MemoryBudget;
  std::optional<double> UnpairedRunValue;
  std::optional<sltk::ReconstructionSummary> Summary; ///< the last execution's

  /// The first kept value, refused; ok when none is kept.
  sltk::Status refusedValue() const
  {
    sltk::InterpolatorKind kind{};
    if (this->Interpolator)
    {
      return sltk::interpolatorOfCode(*this->Interpolator, kind);
    }
    if (this->InitialGuess)
    {
      return sltk::checkOptionRange(sltk::InitialGuessRange, *this->InitialGuess, "InitialGuess");
    }
    if (this->MemoryBudget)
    {
      return sltk::checkOptionRange(sltk::optionRange("MemoryBudget"), *this->MemoryBudget, "MemoryBudget");
    }
    if (this->UnpairedRunValue)
    {
      return sltk::Status::invalidArgument("RunParameters has " +
        std::to_string(2 * this->Options.Schedule.size() + 1) +
        " values: give (p, eta) pairs, an even number of values (or none for Table 4.1)");
    }
    return sltk::Status::ok();
  }

  /// The options of an execution on `comm`'s ranks: the properties', refused
  /// when Core cannot hold one or one is outside Core's ranges.
  sltk::Status optionsOn(const sltk::Communicator& comm, sltk::ReconstructionOptions& options) const
  {
    // The least memory available over the ranks (every rank reaches this call):
    // a C_dx the windows' limit sizes is then the same on every rank.
    const std::int64_t available = comm.size() > 1
      ? comm.allReduce(static_cast<std::int64_t>(sltk::availableMemoryBytes()), sltk::ReduceOp::Min)
      : 0;
    SLTK_RETURN_IF_ERROR(this->refusedValue());
    SLTK_RETURN_IF_ERROR(sltk::validateOptionRanges(this->Options));
    options = this->Options;
    options.Ranks = comm.size(); // the memory check sizes this machine's ranks' windows
    options.RanksHere = sltk::ranksSharingThisMachine(comm.size());
    options.MemoryAvailable = static_cast<std::uint64_t>(std::max<std::int64_t>(0, available));
    return sltk::Status::ok();
  }
};

vtkSLLevelSetReconstruct::vtkSLLevelSetReconstruct()
  : Impl(new Internals)
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

namespace
{
/// vtkSetMacro's semantics: Modified() only when the value changes.
template <class T>
void setOption(vtkObject* self, T& field, T value)
{
  if (field != value)
  {
    field = value;
    self->Modified();
  }
}

/// A property that Core holds in a type of its own: `hold(value)` converts it
/// into the options, or returns false when Core's type cannot hold it, which is
/// then kept in `kept` (returned by the getter, refused when the filter runs).
template <class Hold>
void setConverted(vtkObject* self, int current, int value, std::optional<int>& kept, Hold hold)
{
  if (value != current)
  {
    kept.reset();
    if (!hold(value))
    {
      kept = value;
    }
    self->Modified();
  }
}
} // namespace

// The properties that are fields of Core's options, read and written in place.
#define SLTK_OPTION_PROPERTY(Name, Type, field)                                                                        \
  void vtkSLLevelSetReconstruct::Set##Name(Type value)                                                                 \
  {                                                                                                                    \
    setOption(this, this->Impl->Options.field, value);                                                                 \
  }                                                                                                                    \
  Type vtkSLLevelSetReconstruct::Get##Name()                                                                           \
  {                                                                                                                    \
    return this->Impl->Options.field;                                                                                  \
  }

SLTK_OPTION_PROPERTY(NumberOfRuns, int, Runs)
SLTK_OPTION_PROPERTY(CellSizeFactor, double, CellSizeFactor)
SLTK_OPTION_PROPERTY(MaximumLevel, int, MaximumLevel)
SLTK_OPTION_PROPERTY(OutsideThresholdFactor, double, OutsideThresholdFactor)
SLTK_OPTION_PROPERTY(MaximumNumberOfIterations, int, MaxIterations)
SLTK_OPTION_PROPERTY(Tolerance, double, Tolerance)
SLTK_OPTION_PROPERTY(Padding, int, Padding)
SLTK_OPTION_PROPERTY(FinalEta, double, FinalEta)
SLTK_OPTION_PROPERTY(LocalOffset, bool, LocalOffset)
SLTK_OPTION_PROPERTY(FollowFarPoints, bool, FollowFarPoints)
SLTK_OPTION_PROPERTY(SeedFarPoints, bool, SeedFarPoints)
SLTK_OPTION_PROPERTY(FeetWithinBeta, bool, FeetWithinBeta)
SLTK_OPTION_PROPERTY(AutomaticCleaning, bool, Cleaning.Automatic)
SLTK_OPTION_PROPERTY(RemoveOutliers, bool, Cleaning.RemoveOutliers)
SLTK_OPTION_PROPERTY(OutlierDeviations, double, Cleaning.Outliers.Deviations)
SLTK_OPTION_PROPERTY(ThinningFactor, double, Cleaning.ThinningFactor)
SLTK_OPTION_PROPERTY(DetectTunnels, bool, DetectTunnels)
SLTK_OPTION_PROPERTY(OctreeStorage, bool, OctreeStorage)
#undef SLTK_OPTION_PROPERTY

// The properties in other units than Core's, converted here only: enumerations
// as their codes, MemoryBudget in MB (Core: bytes).
void vtkSLLevelSetReconstruct::SetInterpolator(int code)
{
  setConverted(this, this->GetInterpolator(), code, this->Impl->Interpolator,
    [this](int c)
    {
      sltk::InterpolatorKind kind{};
      if (c == AUTOMATIC)
      {
        this->Impl->Options.Interpolator.reset();
        return true;
      }
      if (!sltk::interpolatorFromCode(c, kind))
      {
        return false;
      }
      this->Impl->Options.Interpolator = kind;
      return true;
    });
}

int vtkSLLevelSetReconstruct::GetInterpolator()
{
  const std::optional<sltk::InterpolatorKind>& kind = this->Impl->Options.Interpolator;
  return this->Impl->Interpolator.value_or(kind ? static_cast<int>(*kind) : AUTOMATIC);
}

void vtkSLLevelSetReconstruct::SetInitialGuess(int code)
{
  setConverted(this, this->GetInitialGuess(), code, this->Impl->InitialGuess,
    [this](int c)
    {
      const bool valid = sltk::inOptionRange(sltk::InitialGuessRange, c);
      this->Impl->Options.Guess = valid ? static_cast<sltk::InitialGuess>(c) : this->Impl->Options.Guess;
      return valid;
    });
}

int vtkSLLevelSetReconstruct::GetInitialGuess()
{
  return this->Impl->InitialGuess.value_or(static_cast<int>(this->Impl->Options.Guess));
}

void vtkSLLevelSetReconstruct::SetMemoryBudget(int megabytes)
{
  setConverted(this, this->GetMemoryBudget(), megabytes, this->Impl->MemoryBudget,
    [this](int mb)
    {
      this->Impl->Options.MemoryBudget =
        mb >= 0 ? static_cast<std::uint64_t>(mb) * sltk::BytesPerMB : this->Impl->Options.MemoryBudget;
      return mb >= 0;
    });
}

int vtkSLLevelSetReconstruct::GetMemoryBudget()
{
  const std::uint64_t mb = this->Impl->Options.MemoryBudget / sltk::BytesPerMB;
  return this->Impl->MemoryBudget.value_or(static_cast<int>(std::min<std::uint64_t>(mb, INT_MAX)));
}

void vtkSLLevelSetReconstruct::SetOptions(const sltk::ReconstructionOptions& options)
{
  this->Impl->Options = options;
  this->Impl->Interpolator.reset();
  this->Impl->InitialGuess.reset();
  this->Impl->MemoryBudget.reset();
  this->Impl->UnpairedRunValue.reset();
  this->Modified();
}

const sltk::ReconstructionOptions& vtkSLLevelSetReconstruct::GetOptions() const
{
  return this->Impl->Options;
}

const sltk::ReconstructionSummary* vtkSLLevelSetReconstruct::GetLastSummary() const
{
  return this->Impl->Summary ? &*this->Impl->Summary : nullptr;
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
    vtkSLLevelSetReconstruct::CWENOZ == static_cast<int>(sltk::InterpolatorKind::CwenoZ) &&
    vtkSLLevelSetReconstruct::LEAST_SQUARES_Q1 == static_cast<int>(sltk::InterpolatorKind::LeastSquaresQ1),
  "the filter's InterpolatorType names the registry's codes (InterpolatorKind.h)");

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
  vtkTable* history, sltk::ReconstructionSummary& summary)
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
  const sltk::CommTraffic traffic = counted.traffic();
  grid->Initialize();
  // Each rank outputs its own trees and contours its own blocks of tiles (its ghosts hold the
  // nodes around them): the pieces join.
  sltk::vtkbridge::tiledZeroLevelSet(result.Field, result.Box, surface, ctx, result.Owners, comm.rank(), z);
  if (self->GetGenerateHyperTreeGrid())
  {
    sltk::completeTiledDistances(plan, ctx, result.Field, result.Owners, comm.rank()); // its own tiles
    const sltk::PointLocator<D>& locator = *plan.Locator;
    sltk::vtkbridge::tiledToHyperTreeGrid<D>(
      result.Field, result.Box, [&locator](const std::array<double, D>& x) { return locator.nearest(x).Distance; },
      grid, ctx, result.Owners, comm.rank(), z); // Initialize()s the grid: its field data after it
    if (!result.Storage.empty())
    {
      vtkNew<vtkDoubleArray> leaves; // the trees' leaves over every rank, on every rank
      leaves->SetName("GlobalLeaves");
      leaves->InsertNextValue(static_cast<double>(result.Storage.back().Leaves));
      grid->GetFieldData()->AddArray(leaves);
    }
  }
  summary = sltk::summarize(result, plan.Options.FrameShift); // places in the user's coordinates
  summary.Ranks = comm.size();
  summary.PlanPointsHeldMax = plan.PointsHeldMax;
  summary.PlanTraffic = plan.Traffic;
  summary.Traffic = traffic;
  sltk::vtkbridge::communicationSummary(summary, grid);
  if (comm.rank() > 0)
  {
    return 1; // the history and the run summary once, on rank 0
  }
  sltk::vtkbridge::runSummary(summary, grid);
  sltk::vtkbridge::historyTable(result.Records.History, history);
  return 1;
}

/// Plans (ReconstructionPlan.h) and runs Algorithm 1 on `cloud` (moved in:
/// the whole cloud, or with `firstId` this rank's share of it, its first point's
/// global index), then fills the image (lying in the plane z = `z` in 2D), the
/// history and, with OctreeStorage, the surface.
template <int D>
int reconstructInto(vtkSLLevelSetReconstruct* self, const sltk::ReconstructionOptions& options,
  sltk::PointCloud<D> cloud, const std::int64_t* firstId, double z, const sltk::Context& ctx,
  const sltk::Communicator& comm, int ghostLevels, vtkDataObject* output, vtkPolyData* surface, vtkTable* history,
  sltk::ReconstructionSummary& summary)
{
  sltk::ReconstructionPlan<D> plan;
  sltk::Status status =
    comm.agree(firstId ? sltk::planReconstructionOnRanks(std::move(cloud), *firstId, options, ctx, comm, plan)
                       : sltk::planReconstruction(std::move(cloud), options, ctx, plan));
  cloud = sltk::PointCloud<D>(); // a share: the plan holds what the runs read
  if (!status.isOk())
  {
    vtkErrorWithObjectMacro(self, "Input point set rejected: " << status.message());
    return 0;
  }
  if (options.OctreeStorage) // a planar cloud: quadtrees in the plane z
  {
    return reconstructTiledInto<D>(self, plan, z, ctx, comm, output, surface, history, summary);
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
  summary = sltk::summarize(result, plan.Options.FrameShift); // places in the user's coordinates
  summary.Ranks = comm.size();
  summary.PlanPointsHeldMax = plan.PointsHeldMax;
  summary.PlanTraffic = plan.Traffic;
  summary.Traffic = counted.traffic();
  sltk::vtkbridge::runSummary(summary, image);
  sltk::vtkbridge::communicationSummary(summary, image);
  if (comm.rank() == 0) // every rank has it; ParaView would append one copy per rank
  {
    sltk::vtkbridge::historyTable(result.History, history);
  }
  return 1;
}
/// The surface's DistanceToCloud and the cloud's point arrays (transferCloudAttributes):
/// from the input when every rank holds the whole cloud; from the shares' owners when the
/// ranks hold shares (`firstId`: this rank's first point's global index) without point
/// arrays; else from every piece gathered, now that the reconstruction's memory is free.
/// `spacing`: h_P, in the user's units. Collective.
void surfaceAttributes(vtkSLLevelSetReconstruct* self, vtkPointSet* input, const std::int64_t* firstId, bool joined,
  double spacing, const sltk::Communicator& comm, const sltk::Context& ctx, vtkPolyData* surface)
{
  const bool arrays = comm.anyRank(input && input->GetPointData()->GetNumberOfArrays() > 0);
  if (firstId && !arrays) // the cloud is not gathered
  {
    const double radius = 8.0 * spacing; // most vertices lie within a cell of a point
    sltk::vtkbridge::distanceToShares(input, *firstId, surface, radius, comm, ctx);
    return;
  }
  vtkSmartPointer<vtkPointSet> attributesFrom = input;
  if (joined || firstId)
  {
    std::set<std::string> dropped;
    attributesFrom = sltk::vtkbridge::piecesWithPointData(input, comm, &dropped);
    for (const std::string& name : dropped)
    {
      vtkWarningWithObjectMacro(self,
        "the cloud's point array '"
          << name << "' is not on the surface: some ranks' pieces lack it or hold another type or number of "
          << "components; give every piece the same arrays");
    }
  }
  sltk::vtkbridge::transferCloudAttributes(attributesFrom, surface);
}
} // namespace

int vtkSLLevelSetReconstruct::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The model needs the whole cloud (h_P (4.36), the bounding box and the
  // distance function see every point), whatever piece is asked of us; with
  // CloudPiecesAreShares under MPI, each rank its share: the piece of its rank.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkMultiProcessController* ranks =
    this->Controller ? this->Controller : vtkMultiProcessController::GetGlobalController();
  const bool share = this->CloudPiecesAreShares && ranks && ranks->GetNumberOfProcesses() > 1;
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), share ? ranks->GetLocalProcessId() : 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), share ? ranks->GetNumberOfProcesses() : 1);
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
  const bool octree = this->GetOctreeStorage();
  if (octree ? !vtkHyperTreeGrid::SafeDownCast(current) : !vtkImageData::SafeDownCast(current))
  {
    vtkSmartPointer<vtkDataObject> made;
    if (octree)
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

  // Under MPI every rank has read the whole cloud, or its share of it with
  // CloudPiecesAreShares (RequestUpdateExtent), and reconstructs its slab of every
  // run (a collective call on the Controller's ranks), whatever piece it was asked
  // for; on one rank a request for a piece other than 0 gets empty outputs (piece 0
  // holds the whole result).
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
  // Shares of one cloud (CloudPiecesAreShares) are planned where they are (planReconstructionOnRanks).
  // Otherwise every rank needs the whole cloud: a caller that gave each rank its own piece (a
  // distributed data set, or points on one rank only) gets the union of the pieces
  // (CloudPieces.h); the surface's DistanceToCloud and the cloud's point arrays are then
  // taken from every piece (SLTKCloudPieces.h).
  const bool shares = this->CloudPiecesAreShares && comm->size() > 1;
  if (shares && sltk::sameCloudOnEveryRank(cloud, *comm)) // every point would count once a rank
  {
    vtkErrorMacro("CloudPiecesAreShares is on, but every rank holds the same "
      << cloud.size() << " points (the whole cloud): give each rank its own share of the cloud, or turn "
      << "CloudPiecesAreShares off");
    return 0;
  }
  const std::int64_t firstId = shares ? sltk::firstGlobalIndex(cloud.size(), *comm) : 0;
  const bool joined = !shares && sltk::joinCloudPieces(cloud, *comm);
  if (joined)
  {
    vtkLog(
      INFO, "the ranks held different pieces of the cloud: reconstructing their union, " << cloud.size() << " points");
  }
  // Survey coordinates: a cloud far from the origin for its size is reconstructed in its
  // local frame and the outputs are put back (LocalFrame.h). Its precision is checked
  // where the user gave it: moved, it would hide digits the file never had.
  const sltk::Box<3> bounds = shares ? sltk::boundingBoxOverRanks(cloud, *comm) : sltk::boundingBox(cloud);
  const bool none = !(bounds.Min[0] <= bounds.Max[0]); // no point (a NaN is refused below)
  const std::array<double, 3> shift = none ? std::array<double, 3>{} : sltk::localFrameShift(bounds);
  const sltk::Status precise = comm->agree(sltk::isZeroShift(shift) ? sltk::Status::ok()
      : shares                                                      ? sltk::validateCloudShares(cloud, firstId, *comm)
                                                                    : sltk::validateCloud(cloud));
  if (!precise.isOk())
  {
    vtkErrorMacro("Input point set rejected: " << precise.message());
    return 0;
  }
  sltk::moveToLocalFrame(cloud, shift);

  this->Impl->Summary.reset();
  sltk::ReconstructionOptions options;
  sltk::Status valid = this->Impl->optionsOn(*comm, options);
  options.FrameShift = shift; // the positions Core's messages name are the user's
  if (valid.isOk())           // before the thread pool takes NumberOfThreads
  {
    valid = sltk::vtkbridge::checkOptionRanges({ { "NumberOfThreads", double(this->NumberOfThreads) } });
  }
  const sltk::Status ranges = comm->agree(valid); // every rank stops together
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
  sltk::ReconstructionSummary summary;
  sltk::Box<3> moved = bounds; // the moved cloud's box: a subtraction keeps the order of the values
  for (int a = 0; a < 3; ++a)
  {
    moved.Min[a] -= shift[a];
    moved.Max[a] -= shift[a];
  }
  const std::int64_t* first = shares ? &firstId : nullptr;
  const bool planar = sltk::flattenIfPlanar(cloud, moved, flat, z);
  const int done = planar ? reconstructInto<2>(this, options, std::move(flat), first, z, ctx, *comm, ghostLevels,
                              output, surface, history, summary)
                          : reconstructInto<3>(this, options, std::move(cloud), first, 0.0, ctx, *comm, ghostLevels,
                              output, surface, history, summary);
  if (!done)
  {
    return 0;
  }
  this->Impl->Summary = std::move(summary);
  if (!options.OctreeStorage)
  {
    sltk::vtkbridge::zeroLevelSet(vtkImageData::SafeDownCast(output), surface);
  }
  sltk::vtkbridge::toUserFrame(shift, output, surface);
  surfaceAttributes(
    this, input, shares ? &firstId : nullptr, joined, this->Impl->Summary->CloudSpacing, *comm, ctx, surface);
  markOutputsComplete(outputVector,
    comm->size() > 1 && !options.OctreeStorage ? std::min(ghostLevels, sltk::vtkbridge::ImageGhostLevelsAvailable)
                                               : EveryGhostLevel);
  return 1;
}

void vtkSLLevelSetReconstruct::AddRunParameters(double p, double eta)
{
  this->AddRunParameterValue(p);
  this->AddRunParameterValue(eta);
}

void vtkSLLevelSetReconstruct::AddRunParameterValue(double value)
{
  // A pair is Core's (p, eta): the first value of a pair waits for the second.
  std::optional<double>& p = this->Impl->UnpairedRunValue;
  if (p)
  {
    this->Impl->Options.Schedule.push_back({ *p, value });
    p.reset();
  }
  else
  {
    p = value;
  }
  this->Modified();
}

void vtkSLLevelSetReconstruct::RemoveAllRunParameters()
{
  if (!this->Impl->Options.Schedule.empty() || this->Impl->UnpairedRunValue)
  {
    this->Impl->Options.Schedule.clear();
    this->Impl->UnpairedRunValue.reset();
    this->Modified();
  }
}

int vtkSLLevelSetReconstruct::GetNumberOfRunParameterValues() const
{
  return 2 * this->GetNumberOfRunParameters() + (this->Impl->UnpairedRunValue ? 1 : 0);
}

int vtkSLLevelSetReconstruct::GetNumberOfRunParameters() const
{
  return static_cast<int>(this->Impl->Options.Schedule.size());
}

double vtkSLLevelSetReconstruct::GetRunP(int index) const
{
  return index >= 0 && index < this->GetNumberOfRunParameters()
    ? this->Impl->Options.Schedule[static_cast<size_t>(index)].P
    : 0.0;
}

double vtkSLLevelSetReconstruct::GetRunEta(int index) const
{
  return index >= 0 && index < this->GetNumberOfRunParameters()
    ? this->Impl->Options.Schedule[static_cast<size_t>(index)].Eta
    : 0.0;
}

void vtkSLLevelSetReconstruct::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  sltk::InterpolatorKind kind{};
  os << indent << "Interpolator: "
     << (this->GetInterpolator() == AUTOMATIC                           ? "Automatic"
            : sltk::interpolatorFromCode(this->GetInterpolator(), kind) ? sltk::interpolatorInfo(kind).Label
                                                                        : "?")
     << "\n";
  os << indent << "NumberOfRuns: " << this->GetNumberOfRuns() << "\n";
  os << indent << "CellSizeFactor: " << this->GetCellSizeFactor() << "\n";
  os << indent << "MaximumLevel: " << this->GetMaximumLevel() << "\n";
  os << indent << "OutsideThresholdFactor: " << this->GetOutsideThresholdFactor() << "\n";
  os << indent << "MemoryBudget: " << this->GetMemoryBudget() << " MB\n";
  os << indent << "AutomaticCleaning: " << this->GetAutomaticCleaning() << "\n";
  os << indent << "LocalOffset: " << this->GetLocalOffset() << "\n";
  os << indent << "FollowFarPoints: " << this->GetFollowFarPoints() << "\n";
  os << indent << "SeedFarPoints: " << this->GetSeedFarPoints() << "\n";
  os << indent << "FeetWithinBeta: " << this->GetFeetWithinBeta() << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->GetMaximumNumberOfIterations() << "\n";
  os << indent << "Tolerance: " << this->GetTolerance() << "\n";
  os << indent << "Padding: " << this->GetPadding() << "\n";
  os << indent << "InitialGuess: " << this->GetInitialGuess() << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "FinalEta: " << this->GetFinalEta() << "\n";
  os << indent << "RunParameters (p, eta):";
  for (int k = 0; k < this->GetNumberOfRunParameters(); ++k)
  {
    os << " (" << this->GetRunP(k) << ", " << this->GetRunEta(k) << ")";
  }
  os << (this->GetNumberOfRunParameterValues() == 0 ? " none (Table 4.1)\n" : "\n");
  os << indent << "RemoveOutliers: " << this->GetRemoveOutliers() << "\n";
  os << indent << "DetectTunnels: " << this->GetDetectTunnels() << "\n";
  os << indent << "OctreeStorage: " << this->GetOctreeStorage() << "\n";
  os << indent << "GenerateHyperTreeGrid: " << this->GenerateHyperTreeGrid << "\n";
  os << indent << "CloudPiecesAreShares: " << this->CloudPiecesAreShares << "\n";
  os << indent << "OutlierDeviations: " << this->GetOutlierDeviations() << "\n";
  os << indent << "ThinningFactor: " << this->GetThinningFactor() << "\n";
}
