// SPDX-License-Identifier: BSD-3-Clause
// The communicator seam from VTK's controllers (Filters/Private/SLTKCommunicator.h),
// serially and under `mpiexec -n 2`: a vtkMPIController gives an MPI
// communicator with its ranks, any other controller the serial one.
#include "FilterTestCheck.h"
#include "SLTKCommunicator.h"

#include "vtkDummyController.h"
#include "vtkMPIController.h"
#include "vtkNew.h"

#include <iostream>
#include <string>

using sltktest::check;

int main(int argc, char* argv[])
{
  std::unique_ptr<sltk::Communicator> comm;
  // No global controller yet: serial.
  check(sltk::vtkbridge::makeCommunicator(nullptr, comm).isOk() && comm->size() == 1 && !comm->nativeHandle(),
    "no controller gives the serial communicator");
  vtkNew<vtkDummyController> dummy;
  check(sltk::vtkbridge::makeCommunicator(dummy, comm).isOk() && comm->size() == 1,
    "the dummy controller gives the serial communicator");

  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int rank = controller->GetLocalProcessId(), size = controller->GetNumberOfProcesses();
  check(sltk::vtkbridge::makeCommunicator(nullptr, comm).isOk(), "the MPI controller gives a communicator");
  check(comm->size() == size && comm->rank() == rank && comm->nativeHandle() != nullptr,
    "ranks of the MPI communicator are the controller's (" + std::to_string(comm->rank()) + "/" +
      std::to_string(comm->size()) + " vs " + std::to_string(rank) + "/" + std::to_string(size) + ")");
  const std::int64_t sum = comm->allReduce(std::int64_t(rank + 1), sltk::ReduceOp::Sum);
  check(sum == std::int64_t(size) * (size + 1) / 2, "all-reduce over the controller's ranks");
  const sltk::Status agreed =
    comm->agree(rank == size - 1 ? sltk::Status::invalidArgument("bad input on the last rank") : sltk::Status::ok());
  check(agreed.code() == sltk::StatusCode::InvalidArgument &&
      agreed.message().find("bad input on the last rank") != std::string::npos,
    "every rank gets the last rank's error: " + agreed.message());
  // The controller still works after the seam's collectives (no message left behind).
  int one = 1, total = 0;
  controller->AllReduce(&one, &total, 1, vtkCommunicator::SUM_OP);
  check(total == size, "the controller's own all-reduce after the seam's");

  int anyFailed = 0;
  controller->AllReduce(&sltktest::failures(), &anyFailed, 1, vtkCommunicator::MAX_OP);
  comm.reset();
  vtkMultiProcessController::SetGlobalController(nullptr);
  controller->Finalize();
  if (rank == 0)
  {
    std::cout << (anyFailed ? "communicator seam: FAILED" : "communicator seam ok") << " on " << size << " rank(s)\n";
  }
  return anyFailed ? 1 : 0;
}
