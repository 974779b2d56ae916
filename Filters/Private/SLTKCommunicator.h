// SPDX-License-Identifier: BSD-3-Clause
#ifndef SLTKCommunicator_h
#define SLTKCommunicator_h
/// \file SLTKCommunicator.h
/// The communicator seam (sltk/exec/Communicator.h) from a VTK controller
/// (never installed or wrapped): a vtkMPIController gives an MPI communicator
/// on its MPI_Comm (vtkMPICommunicator::GetMPIComm()->GetHandle()), any other
/// controller (none, the dummy controller of pvpython --no-mpi, a socket
/// controller) the serial one.

#include "sltk/exec/Communicator.h"

#include <memory>

class vtkMultiProcessController;

namespace sltk
{
namespace vtkbridge
{

/// The communicator of `controller`; nullptr means
/// vtkMultiProcessController::GetGlobalController(). `out` must not outlive
/// the controller.
Status makeCommunicator(vtkMultiProcessController* controller, std::unique_ptr<Communicator>& out);

} // namespace vtkbridge
} // namespace sltk

#endif
