// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file P4estSupport.h
/// What every p4est user in P4est/ needs first (private header): the
/// package initialised once per process, and the MPI_Comm of a communicator
/// seam (sltk/exec/Communicator.h).

#include "sltk/exec/Communicator.h"

#include <mpi.h>

namespace sltk
{
namespace p4est
{

/// The MPI_Comm p4est works on: the communicator's own (SLTK::Mpi), or
/// MPI_COMM_SELF for the serial communicator, with MPI initialised when the
/// process has not done it (a serial program). Fails for a communicator of
/// several ranks that has no MPI handle. Also initialises libsc and p4est once.
Status p4estCommunicator(const Communicator& comm, MPI_Comm& mpiComm);

} // namespace p4est
} // namespace sltk
