// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file Forest.h
/// A p4est forest of octrees over a box (thesis ch. 5): the adaptive grid of
/// vtkOctreeSDF. This first piece owns the forest and refines it uniformly;
/// the adaptive level-set machinery builds on it.
///
/// The communicator is passed as an opaque handle (an MPI_Comm cast to
/// void*), so this header needs neither mpi.h nor p4est headers.

#include "sltk/core/Status.h"

#include <cstdint>
#include <memory>

namespace sltk
{
namespace octree
{

class Forest
{
public:
  /// A single-tree unit cube [0,1]^3 forest on the communicator, refined
  /// uniformly to `level`. MPI must be initialised by the caller.
  static Status createUniform(void* mpiComm, int level, std::unique_ptr<Forest>& forest);
  ~Forest();

  std::int64_t globalOctants() const;
  std::int64_t localOctants() const;
  int rank() const;

private:
  struct Impl;
  explicit Forest(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> P;
};

} // namespace octree
} // namespace sltk
