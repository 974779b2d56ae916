// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef SLTKOctreeOutput_h
#define SLTKOctreeOutput_h
/// \file SLTKOctreeOutput.h
/// The octree forest (Octree/include/sltk/octree/CloudForest.h) as a
/// vtkHyperTreeGrid (never installed or wrapped; built with SLTK::Octree).
///
/// - The brick of trees is the HTG's grid of trees (dimensions = trees + 1
///   per axis, coordinates in the user's units), branch factor 2: one p4est
///   tree is one hyper tree, one p4est leaf one HTG leaf at the same level and
///   position (child index x + 2y + 4z, as p4est's Morton child id).
/// - Under MPI each rank's output holds its own leaves. A hyper tree is created
///   on a rank only when the rank owns leaves in it; the siblings created on
///   the way down to an owned leaf belong to other ranks and are **masked**
///   (vtkHyperTreeGrid::SetMask), so the union of all ranks' unmasked leaves
///   is the whole forest, each leaf once. Serially nothing is masked.
/// - Cell data: DistanceToCloud (distance from the leaf's centre to the cloud,
///   user units), Level, Rank (owner). Refined cells hold the mean of their
///   children's distances (the thesis's coarsening rule, 5.2.2), masked leaves
///   their parent's, both rank -1 (VTK's HTG filters use the unmasked
///   leaves). No SignedDistance: the level-set solver on the tree is not built
///   (Documentation/Octree.md).

class vtkHyperTreeGrid;

namespace sltk
{
namespace octree
{
class CloudForest;
}
namespace vtkbridge
{

/// Fills `output` (reset first) with this rank's leaves of `forest`.
void forestToHyperTreeGrid(const octree::CloudForest& forest, vtkHyperTreeGrid* output);

} // namespace vtkbridge
} // namespace sltk

#endif
