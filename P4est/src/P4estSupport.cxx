// SPDX-License-Identifier: GPL-2.0-or-later
#include "P4estSupport.h"

#include "sltk/mpi/MpiCommunicator.h"

#include <p8est.h>

#include <string>

namespace sltk
{
namespace p4est
{

Status p4estCommunicator(const Communicator& comm, MPI_Comm& mpiComm)
{
  if (comm.nativeHandle())
  {
    mpiComm = *static_cast<MPI_Comm*>(comm.nativeHandle());
  }
  else if (comm.size() == 1)
  {
    SLTK_RETURN_IF_ERROR(mpi::ensureMpiInitialised());
    mpiComm = MPI_COMM_SELF;
  }
  else
  {
    return Status::invalidArgument("a communicator of " + std::to_string(comm.size()) +
      " ranks without an MPI handle: p4est needs MPI (build the communicator with SLTK::Mpi)");
  }
  // p4est_init registers a package once per process; a second call aborts
  // (Documentation/Toolchain.md, "Pitfalls"), e.g. when ParaView already loaded p4est.
  if (p4est_package_id < 0)
  {
    sc_init(sc_MPI_COMM_NULL, 0, 0, nullptr, SC_LP_SILENT);
    p4est_init(nullptr, SC_LP_SILENT);
  }
  return Status::ok();
}

} // namespace p4est
} // namespace sltk
