// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TreeImage.h
/// `sltk reconstruct --octree -o FILE.vti`: the uniform image of the finest
/// grid written from the octree's trees, one piece of its extent at a time, so
/// that the whole image is never held (Documentation/Octree.md, "The image
/// from the trees").

#include "sltk/core/Status.h"

#include <array>
#include <string>

class vtkHyperTreeGrid;

namespace sltkcli
{

/// Writes the finest grid of `dims` nodes of the trees (vtkOctreeSDF's output
/// on one rank) as XML image data: every node takes the values
/// (SignedDistance, DistanceToCloud) of the leaf that holds it, its own leaf in
/// a tile, else the flat cell or the tree around it; the trees' field data
/// are copied. The file holds pieces of at most `pieceNodes` nodes (at least
/// 4 pieces), each filled when the writer asks for it.
sltk::Status writeTreeImage(const std::string& path, vtkHyperTreeGrid* trees, const std::array<long long, 3>& dims,
  long long pieceNodes = 1LL << 21);

} // namespace sltkcli
