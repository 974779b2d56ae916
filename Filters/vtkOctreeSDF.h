// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOctreeSDF
 * @brief   The octree version of the reconstruction (thesis ch. 5): a
 *          watertight signed distance from an unorganised point cloud, stored
 *          only near the surface and output as a vtkHyperTreeGrid.
 *
 * vtkSLLevelSetReconstruct with OctreeStorage always on, and every property
 * of it with the same meaning (CellSizeFactor and NumberOfRuns give the
 * finest cell, dx = CellSizeFactor * h_P / 2^(R-1)). Run 1 is computed on its
 * uniform grid, the coarsest; runs 2..R, one level finer each, store only the
 * tiles of 8^3 finest nodes around the front, the finest levels of the octree
 * (Documentation/Octree.md, "The tiled band"), so memory follows the surface.
 * A planar cloud (no z extent) is reconstructed in 2D: tiles of 8^2 nodes, a
 * 2D hyper tree grid (a quadtree per 8^2 nodes) in its plane, and a curve.
 *
 * Outputs:
 *  - port 0: vtkHyperTreeGrid, one tree per 8^3 finest nodes, refined to one
 *    leaf per node where a tile is stored but for its flat cells (one leaf at
 *    +-gamma each), and a single leaf (+-gamma) elsewhere; cell data SignedDistance (active scalars), DistanceToCloud,
 *    Level and Rank (owning rank); field data the run summary
 *    (vtkSLLevelSetReconstruct's, with RunStoredNodes and RunUniformNodes)
 *    and GlobalLeaves (the leaves of every rank). VTK's hyper tree grid
 *    filters (contour, threshold, dual grid) work on it.
 *  - port 1: vtkPolyData, the zero level set, contoured from the finest
 *    nodes: continuous and watertight (not drawn cell by cell as in the
 *    thesis's 5.3.1).
 *  - port 2: vtkTable, the convergence history with, per iteration,
 *    StoredNodes, Leaves (the octree's, over every rank), LargestRankLeaves
 *    (the most one rank owns) and UniformNodes (the uniform grid of the same
 *    finest cell), the thesis's Fig. 5.7 and 5.14.
 *
 * Under MPI (pvbatch, pvserver, mpirun sltk; the Controller) the ranks share
 * the tiles out in Morton order while they compute
 * (Documentation/Octree.md, "Distributing the tiled band"): each rank outputs
 * the trees it owns and its piece of the surface (the pieces join), rank 0
 * also the history.
 *
 * Turning OctreeStorage off is refused when the filter runs:
 * vtkSLLevelSetReconstruct computes the uniform grids.
 */
#ifndef vtkOctreeSDF_h
#define vtkOctreeSDF_h

#include "SLTKFiltersModule.h" // for export macro
#include "vtkSLLevelSetReconstruct.h"

class vtkHyperTreeGrid;

class SLTKFILTERS_EXPORT vtkOctreeSDF : public vtkSLLevelSetReconstruct
{
public:
  static vtkOctreeSDF* New();
  vtkTypeMacro(vtkOctreeSDF, vtkSLLevelSetReconstruct);

  ///@{
  /// Port 0, the octree (null before the filter has run); GetOutput(port)
  /// any port (1: the surface, 2: the history).
  vtkHyperTreeGrid* GetOutput();
  vtkDataObject* GetOutput(int port);
  ///@}

protected:
  vtkOctreeSDF();
  ~vtkOctreeSDF() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkOctreeSDF(const vtkOctreeSDF&) = delete;
  void operator=(const vtkOctreeSDF&) = delete;
};

#endif
