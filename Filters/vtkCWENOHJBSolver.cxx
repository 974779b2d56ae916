// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCWENOHJBSolver.h"

#include "SLTKBridge.h"
#include "SLTKCommunicator.h"
#include "SLTKGuard.h"

#include "sltk/exec/Communicator.h"
#include "sltk/hjb/DistributedHjbSolver.h"

#include "sltk/hjb/HjbResult.h"
#include "sltk/hjb/HjbSolver.h"
#include "sltk/hjb/PresetRun.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkCWENOHJBSolver);
vtkCxxSetObjectMacro(vtkCWENOHJBSolver, Controller, vtkMultiProcessController);

vtkCWENOHJBSolver::vtkCWENOHJBSolver()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
  this->SetDynamicsX("-2*pi*y");
  this->SetDynamicsY("2*pi*x");
  this->SetDynamicsZ("0");
  this->SetInitialValue("max(0.25 - hypot(x - 0.5, y), 0)");
}

vtkCWENOHJBSolver::~vtkCWENOHJBSolver()
{
  for (char** text : { &this->DynamicsX, &this->DynamicsY, &this->DynamicsZ, &this->RunningCost, &this->InitialValue,
         &this->Obstacle, &this->ExactSolution, &this->ArgminA1, &this->ArgminA2, &this->ArgminA3 })
  {
    delete[] * text;
    *text = nullptr;
  }
  this->Solver.reset();
  this->SetController(nullptr);
}

int vtkCWENOHJBSolver::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

namespace
{
std::string text(const char* s)
{
  return s ? std::string(s) : std::string();
}

/// The custom problem's grid from the input image's information (v_0 on its nodes).
sltk::Status gridFromImage(vtkInformation* inInfo, sltk::HjbExpressionSpec& spec)
{
  int extent[6];
  double origin[3], spacing[3];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  inInfo->Get(vtkDataObject::ORIGIN(), origin);
  inInfo->Get(vtkDataObject::SPACING(), spacing);
  spec.Dimension = 0;
  for (int a = 0; a < 3; ++a)
  {
    const int n = extent[2 * a + 1] - extent[2 * a] + 1;
    if (n > 1 && spec.Dimension != a)
    {
      return sltk::Status::invalidArgument(
        "the input image must span x, then y, then z (its extent has one node along an earlier axis)");
    }
    spec.Dimension += n > 1 ? 1 : 0;
    spec.Nodes[a] = n;
    spec.Lower[a] = origin[a] + extent[2 * a] * spacing[a];
    const bool periodic = spec.Bounds[a] == sltk::Boundary::Periodic;
    spec.Upper[a] = spec.Lower[a] + (periodic ? n : n - 1) * spacing[a];
  }
  if (spec.Dimension == 0)
  {
    return sltk::Status::invalidArgument("the input image has a single node: give it at least 5 nodes along x");
  }
  return sltk::Status::ok();
}

/// v_0 from the image's active point scalars (else its first point array), x fastest.
sltk::Status valuesFromImage(vtkImageData* image, sltk::HjbExpressionSpec& spec)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars && image->GetPointData()->GetNumberOfArrays() > 0)
  {
    scalars = image->GetPointData()->GetArray(0);
  }
  if (!scalars || scalars->GetNumberOfComponents() != 1)
  {
    return sltk::Status::invalidArgument("the input image needs a one-component point array (v0) as active scalars");
  }
  const vtkIdType n = scalars->GetNumberOfTuples();
  spec.InitialValues.resize(static_cast<size_t>(n));
  for (vtkIdType k = 0; k < n; ++k)
  {
    spec.InitialValues[static_cast<size_t>(k)] = scalars->GetTuple1(k);
  }
  spec.Initial.clear();
  return sltk::Status::ok();
}

/// A node array of the output's block (x fastest); +inf (never reached) becomes -1.
vtkSmartPointer<vtkDoubleArray> pointArray(const std::vector<double>& values, const char* name)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), std::isinf(values[k]) ? -1.0 : values[k]);
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

static_assert(vtkCWENOHJBSolver::Q1 == static_cast<int>(sltk::InterpolatorKind::Q1) &&
    vtkCWENOHJBSolver::WENO3 == static_cast<int>(sltk::InterpolatorKind::Weno3) &&
    vtkCWENOHJBSolver::CWENO == static_cast<int>(sltk::InterpolatorKind::Cweno) &&
    vtkCWENOHJBSolver::CWENOZ == static_cast<int>(sltk::InterpolatorKind::CwenoZ),
  "the filter's InterpolatorType names the registry's codes (InterpolatorKind.h)");

int vtkCWENOHJBSolver::BuildSolver(vtkInformation* inInfo, vtkImageData* values,
  std::unique_ptr<sltk::HjbSolver>& solver, const sltk::Communicator* comm)
{
  // The properties' ranges (enumerations here, the others Core's, OptionRanges.h, from which
  // the plugin XML's domains are made): refused, never clamped.
  sltk::Status status = sltk::vtkbridge::checkPropertyRanges({
    { "Preset", double(this->Preset), CUSTOM, TEST5_ZERMELO },
    { "ControlSet", double(this->ControlSet), NO_CONTROL, SPHERE },
    { "RKOrder", double(this->RKOrder), 1, 3 },
  });
  if (status.isOk())
  {
    status = sltk::vtkbridge::checkOptionRanges({
      { "NumberOfNodes", double(this->NumberOfNodes) },
      { "CourantNumber", this->CourantNumber },
      { "NumberOfThreads", double(this->NumberOfThreads) },
      { "ControlDimension", double(this->ControlDimension) },
      { "TabulationPoints", double(this->TabulationPoints) },
      { "WarmStartPoints", double(this->WarmStartPoints) },
      { "MinimizerTolerance", this->MinimizerTolerance },
    });
  }
  if (!status.isOk())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  sltk::InterpolatorKind interpolator{};
  status = sltk::hjbInterpolatorOfCode(this->Interpolator, interpolator);
  if (!status.isOk())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  if (this->Preset != CUSTOM)
  {
    sltk::PresetRunOptions options;
    options.Preset = static_cast<sltk::HjbPreset>(this->Preset);
    options.Nodes = this->NumberOfNodes;
    options.FinalTime = this->FinalTime;
    options.CourantNumber = this->CourantNumber;
    options.Interpolator = interpolator;
    status = comm && comm->size() > 1 ? sltk::makeDistributedPresetSolver(options, *comm, solver)
                                      : sltk::makePresetSolver(options, solver);
  }
  else
  {
    sltk::HjbExpressionSpec spec;
    spec.Dynamics = { text(this->DynamicsX), text(this->DynamicsY), text(this->DynamicsZ) };
    spec.Cost = text(this->RunningCost);
    spec.Initial = text(this->InitialValue);
    spec.Obstacle = text(this->Obstacle);
    spec.Exact = text(this->ExactSolution);
    spec.Argmin = { text(this->ArgminA1), text(this->ArgminA2), text(this->ArgminA3) };
    spec.ReachableSet = this->ComputeReachableSet != 0;
    spec.Dimension = 0;
    for (int a = 0; a < 3; ++a)
    {
      spec.Bounds[a] = this->PeriodicAxes[a] ? sltk::Boundary::Periodic : sltk::Boundary::Extrapolate;
      spec.Nodes[a] = this->Dimensions[a];
      spec.Lower[a] = this->DomainBounds[2 * a];
      spec.Upper[a] = this->DomainBounds[2 * a + 1];
      spec.Dimension += this->Dimensions[a] > 1 ? 1 : 0;
      spec.ControlLower[a] = this->ControlLowerBound[a];
      spec.ControlUpper[a] = this->ControlUpperBound[a];
      spec.ControlCenter[a] = this->ControlCenter[a];
    }
    if (spec.Dimension == 0 || this->Dimensions[0] <= 1 || (this->Dimensions[1] <= 1 && this->Dimensions[2] > 1))
    {
      vtkErrorMacro("Dimensions (" << this->Dimensions[0] << ", " << this->Dimensions[1] << ", " << this->Dimensions[2]
                                   << ") must use x, then y, then z: e.g. {201, 1, 1} in 1D, {81, 81, 1} in 2D");
      return 0;
    }
    spec.Controls = static_cast<sltk::ControlKind>(this->ControlSet);
    spec.ControlDimension = this->ControlDimension;
    spec.ControlRadius = this->ControlRadius;
    spec.Order = static_cast<sltk::RkOrder>(this->RKOrder);
    spec.FinalTime = this->FinalTime >= 0.0 ? this->FinalTime : 1.0;
    spec.CourantNumber = this->CourantNumber > 0.0 ? this->CourantNumber : 1.0;
    spec.Minimizer.TabulationPoints = this->TabulationPoints;
    spec.Minimizer.WarmTabulationPoints = this->WarmStartPoints;
    spec.Minimizer.Tolerance = this->MinimizerTolerance;
    spec.Minimizer.PerStageControls = this->PerStageControls != 0;
    spec.Interpolator = interpolator;
    if (inInfo)
    {
      status = gridFromImage(inInfo, spec);
      if (status.isOk() && values)
      {
        status = valuesFromImage(values, spec);
      }
      else if (status.isOk())
      {
        spec.Initial = "0"; // RequestInformation: only the grid and the times are needed
      }
    }
    if (status.isOk())
    {
      status = comm && comm->size() > 1 ? sltk::makeDistributedExpressionSolver(spec, *comm, solver)
                                        : sltk::makeExpressionSolver(spec, solver);
    }
  }
  if (!status.isOk())
  {
    vtkErrorMacro("HJB problem: " << status.message());
    return 0;
  }
  return 1;
}

int vtkCWENOHJBSolver::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo =
    inputVector[0]->GetNumberOfInformationObjects() > 0 ? inputVector[0]->GetInformationObject(0) : nullptr;
  std::unique_ptr<sltk::HjbSolver> plan;
  if (!this->BuildSolver(this->Preset == CUSTOM ? inInfo : nullptr, nullptr, plan))
  {
    return 0;
  }
  const sltk::HjbGrid& grid = plan->grid();
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
  const std::vector<double> times = plan->stepTimes();
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
  const double range[2] = { times.front(), times.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_DOUBLE, 1);
  return 1;
}

int vtkCWENOHJBSolver::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  if (inputVector[0]->GetNumberOfInformationObjects() > 0)
  {
    // v_0 is needed on the whole grid, whatever piece is asked for.
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
    int whole[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), whole, 6);
    inInfo->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }
  return 1;
}

vtkTypeBool vtkCWENOHJBSolver::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return sltk::vtkbridge::guardedRequest(
    this, [&] { return this->Superclass::ProcessRequest(request, inputVector, outputVector); });
}

//------------------------------------------------------------------------------
int vtkCWENOHJBSolver::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo =
    inputVector[0]->GetNumberOfInformationObjects() > 0 ? inputVector[0]->GetInformationObject(0) : nullptr;
  vtkImageData* input = inInfo ? vtkImageData::GetData(inInfo) : nullptr;
  const bool custom = this->Preset == CUSTOM;
  vtkMTimeType key = this->GetMTime();
  if (custom && input)
  {
    key = std::max(key, input->GetMTime());
  }
  if (!this->Solver || key != this->SolverKey)
  {
    this->Solver.reset();
    const sltk::Status made = sltk::vtkbridge::makeCommunicator(this->Controller, this->Communicator);
    if (!made.isOk())
    {
      vtkErrorMacro(<< made.message());
      return 0;
    }
    if (!this->BuildSolver(custom ? inInfo : nullptr, custom ? input : nullptr, this->Solver, this->Communicator.get()))
    {
      return 0;
    }
    this->SolverKey = key;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  double t = this->Solver->finalTime();
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }
  sltk::ThreadPool pool(
    sltk::threadsPerRank(this->NumberOfThreads, this->Communicator ? this->Communicator->size() : 1));
  this->ThreadsUsed = pool.size();
  sltk::vtkbridge::AlgorithmInterrupter progress(this);
  sltk::Context ctx;
  ctx.Executor = &pool;
  ctx.Progress = &progress;
  const sltk::Status status = this->Solver->advanceTo(t, ctx);
  if (!status.isOk())
  {
    vtkErrorMacro("HJB solve failed at t = " << this->Solver->time() << ": " << status.message());
    return 0;
  }
  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  // This piece's nodes only; a distributed solve sends each rank the nodes it asks for (a collective call).
  sltk::HjbRunResult result;
  this->Solver->resultBlock({ extent[0], extent[1], extent[2], extent[3], extent[4], extent[5] }, result);
  if (!result.ExactNotFiniteAt.empty())
  {
    // The error norms would be NaN: say where the formula fails instead of dropping them.
    std::ostringstream where;
    const auto& at = result.ExactNotFiniteAt;
    for (size_t a = 0; a + 1 < at.size(); ++a)
    {
      where << (a ? ", " : "") << "xyz"[a] << " = " << at[a];
    }
    vtkErrorMacro("ExactSolution '" << (this->ExactSolution ? this->ExactSolution : "") << "' (sltk hjb --exact) is "
                                    << at.back() << " at t = " << result.FinalTime << ", " << where.str()
                                    << ": give a formula that is finite on the whole domain");
    return 0;
  }
  vtkImageData* output = vtkImageData::GetData(outInfo);
  for (int k = 0; k < 6; ++k)
  {
    extent[k] = static_cast<int>(result.Block[static_cast<size_t>(k)]);
  }
  output->SetExtent(extent);
  output->SetOrigin(result.Grid.Origin.data());
  output->SetSpacing(result.Grid.Spacing.data());
  output->GetPointData()->SetScalars(pointArray(result.Value, "ValueFunction"));
  if (!result.ReachTime.empty())
  {
    output->GetPointData()->AddArray(pointArray(result.ReachTime, "ReachTime"));
  }
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), result.FinalTime);
  vtkFieldData* fd = output->GetFieldData();
  addScalar(fd, "Time", result.FinalTime);
  addScalar(fd, "Steps", static_cast<double>(result.Steps));
  addScalar(fd, "EvaluationsPerNode", result.EvaluationsPerNode);
  addScalar(fd, "Ranks", this->Solver->ranks()); // the ranks the solve was split over
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
  os << indent << "DynamicsX: " << text(this->DynamicsX) << "\n";
  os << indent << "DynamicsY: " << text(this->DynamicsY) << "\n";
  os << indent << "DynamicsZ: " << text(this->DynamicsZ) << "\n";
  os << indent << "RunningCost: " << text(this->RunningCost) << "\n";
  os << indent << "InitialValue: " << text(this->InitialValue) << "\n";
  os << indent << "Obstacle: " << text(this->Obstacle) << "\n";
  os << indent << "ExactSolution: " << text(this->ExactSolution) << "\n";
  os << indent << "Argmin: " << text(this->ArgminA1) << " | " << text(this->ArgminA2) << " | " << text(this->ArgminA3)
     << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " " << this->Dimensions[2]
     << "\n";
  os << indent << "ControlSet: " << this->ControlSet << " (dimension " << this->ControlDimension << ")\n";
  os << indent << "RKOrder: " << this->RKOrder << "\n";
  os << indent << "TabulationPoints: " << this->TabulationPoints << "\n";
  os << indent << "WarmStartPoints: " << this->WarmStartPoints << "\n";
}
