// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file Forest.h
/// A p4est forest of octrees over a box (thesis ch. 5). This first piece owns
/// the forest and refines it uniformly; CloudForest.h refines it over a cloud.
/// No filter uses it (vtkOctreeSDF runs Core's tiled band,
/// Documentation/Octree.md).
///
/// The ranks are those of a communicator seam (sltk/exec/Communicator.h:
/// SLTK::Mpi's, or the serial one), so this header needs neither mpi.h nor
/// p4est headers.

#include "sltk/exec/Communicator.h"

#include <cstdint>
#include <memory>

namespace sltk
{
namespace p4est
{

class Forest
{
public:
  /// A single-tree unit cube [0,1]^3 forest on the communicator, refined
  /// uniformly to `level`.
  static Status createUniform(const Communicator& comm, int level, std::unique_ptr<Forest>& forest);
  ~Forest();

  std::int64_t globalOctants() const;
  std::int64_t localOctants() const;
  int rank() const;

private:
  struct Impl;
  explicit Forest(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> P;
};

} // namespace p4est
} // namespace sltk
