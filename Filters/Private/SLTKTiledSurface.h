// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SLTKTiledSurface.h
/// The zero level set of a tiled reconstruction (sltk/octree/TiledField.h,
/// Documentation/Octree.md "The tiled band") as one vtkPolyData, without the
/// full grid: the cells of the blocks of 4^D tile positions that hold a tile
/// (the cells of their slots without a tile too, at +-gamma) are contoured by
/// vtkFlyingEdges3D (vtkFlyingEdges2D in 2D) on one image a block, whose extent is the
/// block's in the global grid (global origin and spacing, so a node shared by
/// two blocks has the same coordinates in both), and the pieces are merged at
/// identical points. The union is the uniform contour of the same nodes: as
/// watertight as it.

#include "sltk/exec/Context.h"
#include "sltk/octree/TiledField.h"
#include "sltk/recon/UnitBox.h"

#include <cstdint>
#include <vector>

class vtkPolyData;

namespace sltk
{
namespace vtkbridge
{

/// The zero level set of `field` in the user's units (`box`), with normals.
/// With `owners` (a distributed field's, per slot: TiledReconstructionResult)
/// only the blocks `rank` owns: this rank's piece, which joins the others'
/// at their shared points. A 2D field's zero level set is a curve (segments, no
/// normals) in the plane `z`. The blocks are contoured on `ctx`'s threads.
template <int D>
void tiledZeroLevelSet(const TiledField<D>& field, const UnitBox<D>& box, vtkPolyData* surface, const Context& ctx,
  const std::vector<std::int32_t>& owners = {}, int rank = 0, double z = 0.0);

} // namespace vtkbridge
} // namespace sltk
