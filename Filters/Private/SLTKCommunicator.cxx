// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKCommunicator.h"

#include "sltk/mpi/MpiCommunicator.h"

#include "vtkMPI.h"
#include "vtkMPICommunicator.h"
#include "vtkMPIController.h"
#include "vtkMultiProcessController.h"

namespace sltk
{
namespace vtkbridge
{

Status makeCommunicator(vtkMultiProcessController* controller, std::unique_ptr<Communicator>& out)
{
  out.reset();
  if (!controller)
  {
    controller = vtkMultiProcessController::GetGlobalController();
  }
  auto* mpiController = vtkMPIController::SafeDownCast(controller);
  auto* communicator = mpiController ? vtkMPICommunicator::SafeDownCast(mpiController->GetCommunicator()) : nullptr;
  if (!communicator || !communicator->GetMPIComm() || !communicator->GetMPIComm()->GetHandle())
  {
    out = newSerialCommunicator();
    return Status::ok();
  }
  std::unique_ptr<mpi::MpiCommunicator> comm;
  SLTK_RETURN_IF_ERROR(mpi::MpiCommunicator::fromHandle(communicator->GetMPIComm()->GetHandle(), comm));
  out = std::move(comm);
  return Status::ok();
}

} // namespace vtkbridge
} // namespace sltk
