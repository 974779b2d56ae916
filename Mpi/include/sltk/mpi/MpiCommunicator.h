// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file MpiCommunicator.h
/// The MPI implementation of the communicator seam (sltk/exec/Communicator.h),
/// library SLTK::Mpi. The MPI_Comm is passed as an opaque handle, a pointer
/// to it cast to void* (what vtkMPICommunicator::GetMPIComm()->GetHandle()
/// returns in VTK 9.2), so this header needs no mpi.h. nativeHandle() gives
/// the same kind of pointer back, for p4est (P4est/).

#include "sltk/exec/Communicator.h"

#include <memory>

namespace sltk
{
namespace mpi
{

/// True when MPI_Init has been called and MPI_Finalize has not.
bool isMpiActive();

/// Initialises MPI in a process that has not (a serial program, plain
/// Python), once, and finalises it at exit; nothing when MPI is already
/// initialised. Fails when MPI was already finalised.
Status ensureMpiInitialised();

class MpiCommunicator final : public Communicator
{
public:
  /// The communicator `*static_cast<MPI_Comm*>(mpiCommPointer)`, not
  /// duplicated: it must stay valid while this object is used. Fails when
  /// MPI is not active or the pointer is null.
  static Status fromHandle(void* mpiCommPointer, std::unique_ptr<MpiCommunicator>& out);
  /// MPI_COMM_WORLD (MPI must be active).
  static Status world(std::unique_ptr<MpiCommunicator>& out);
  /// MPI_COMM_SELF: one rank (MPI must be active).
  static Status self(std::unique_ptr<MpiCommunicator>& out);

  ~MpiCommunicator() override;

  int rank() const override;
  int size() const override;
  void barrier() const override;
  void allReduce(double* values, std::size_t count, ReduceOp op) const override;
  void allReduce(std::int64_t* values, std::size_t count, ReduceOp op) const override;
  void broadcast(void* bytes, std::size_t count, int root) const override;
  void allGather(const void* bytes, std::size_t count, void* out) const override;
  void allGatherV(const void* bytes, std::size_t count, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& counts) const override;
  /// A pointer to the MPI_Comm (MPI_Comm*), valid as long as this object.
  void* nativeHandle() const override;

  using Communicator::allGatherV;
  void allToAllV(const void* send, const std::vector<std::int64_t>& sendCounts, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& receiveCounts) const override;
  bool neighbourExchange(const std::vector<Outgoing>& out, const std::vector<Incoming>& in) const override;
  void sendReceive(const void* send, std::size_t sendBytes, int destination, void* receive, std::size_t receiveBytes,
    int source) const override;
  using Communicator::allReduce;

private:
  struct Impl;
  explicit MpiCommunicator(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> P;
};

} // namespace mpi
} // namespace sltk
