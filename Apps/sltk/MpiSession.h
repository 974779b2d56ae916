// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file MpiSession.h
/// `mpirun -np N sltk ...`: when a launcher started this process (OpenMPI's
/// OMPI_COMM_WORLD_SIZE, PMI/PMIx's PMI_SIZE or PMIX_RANK in the environment),
/// MPI is initialised and a vtkMPIController becomes VTK's global controller,
/// so the filters split their work over the ranks (vtkCWENOHJBSolver.h). A
/// plain `sltk ...` never touches MPI (no start-up cost, no MPI messages).
///
/// Rank 0 speaks for all: the other ranks print nothing (every rank reaches
/// the same agreed error, Communicator::agree, so rank 0's message is theirs),
/// and only rank 0 writes the output files.

#include <vtkSmartPointer.h>

class vtkMPIController;

namespace sltkcli
{

class MpiSession
{
public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// This process's rank and the rank count (0 and 1 without a launcher).
  static int rank();
  static int size();
  /// The largest `value` over the ranks (a collective call: every rank makes it).
  static double maxOverRanks(double value);

private:
  vtkSmartPointer<vtkMPIController> Controller;
};

} // namespace sltkcli
