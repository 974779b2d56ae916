// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SLTKTiledGrid.h
/// A tiled reconstruction (sltk/octree/TiledField.h, Documentation/Octree.md
/// "The tiled band") as a vtkHyperTreeGrid, without the full grid: one hyper
/// tree per slot of 8^3 nodes (8^2 in 2D: a quadtree per slot, in the plane z), its cell centred on the slot's nodes
/// (the tree's cells are the uniform grid's dual cells). A slot with a tile is refined down to one leaf per node
/// holding that node's values, but for its flat cells (TiledField::flatCell: every node at the same +-gamma), each one
/// leaf with that value and the distance to the cloud at its centre; a slot without one is a single leaf (+-gamma, the
/// distance at its centre). The leaves of a last slot's tile beyond the grid's nodes are masked. A refined cell holds
/// the mean of its unmasked children. The dual grid of the leaves (vtkHyperTreeGridContour) therefore contours the
/// nodes' values as the uniform grid does near the front.

#include "sltk/exec/Context.h"
#include "sltk/octree/TiledField.h"
#include "sltk/recon/UnitBox.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

class vtkHyperTreeGrid;

namespace sltk
{
namespace vtkbridge
{

/// The field (every stored d computed: completeTiledDistances) in the user's
/// units (`box`) as cell data SignedDistance (active scalars), DistanceToCloud,
/// Level and Rank; `distanceAt` gives the distance to the cloud at a unit-box
/// point (a slot's centre). With `owners` (a distributed field's, per slot:
/// TiledReconstructionResult) only the trees of the slots `rank` owns: this
/// rank's piece; the pieces' union is the whole grid of trees. A 2D field's
/// grid lies in the plane `z`.
template <int D>
void tiledToHyperTreeGrid(const TiledField<D>& field, const UnitBox<D>& box,
  const std::function<double(const std::array<double, D>&)>& distanceAt, vtkHyperTreeGrid* output, const Context& ctx,
  const std::vector<std::int32_t>& owners = {}, int rank = 0, double z = 0.0);

} // namespace vtkbridge
} // namespace sltk
