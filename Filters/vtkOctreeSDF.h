// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOctreeSDF
 * @brief   The adaptive octree (p4est) of the reconstruction over an
 *          unorganised point cloud, output as a vtkHyperTreeGrid (thesis ch. 5).
 *
 * Input: any vtkPointSet (points only; under MPI every rank's points are
 * gathered, and a rank may have none). Output: a vtkHyperTreeGrid whose trees
 * are the p4est brick's, refined uniformly to MinimumLevel and to
 * MaximumLevel in the band of the cloud, 2:1 balanced, with the cell arrays
 * "DistanceToCloud" (distance from each leaf's centre to the cloud), "Level"
 * and "Rank" (owning rank). Under MPI each rank outputs its own leaves; the
 * leaves of other ranks met on the way are masked. Field data: GlobalLeaves,
 * UniformCells (the uniform grid of the finest level), CloudSpacing (h_P).
 * Documentation/Octree.md describes the forest.
 *
 * @warning The level-set solver on the octree is not built yet: there is no
 * "SignedDistance" array and no zero level set. The output is the adaptive
 * grid and the distance to the cloud only.
 */
#ifndef vtkOctreeSDF_h
#define vtkOctreeSDF_h

#include "SLTKFiltersModule.h" // for export macro
#include "vtkAlgorithm.h"

class vtkHyperTreeGrid;

class SLTKFILTERS_EXPORT vtkOctreeSDF : public vtkAlgorithm
{
public:
  static vtkOctreeSDF* New();
  vtkTypeMacro(vtkOctreeSDF, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Coarsest refinement level of the octree (every tree refined uniformly to
  /// it). Default 3, range 0-18, at most MaximumLevel. Values outside are
  /// refused when the filter runs, not clamped.
  vtkSetMacro(MinimumLevel, int);
  vtkGetMacro(MinimumLevel, int);
  ///@}

  ///@{
  /// Finest refinement level L, reached in the band of the cloud; the finest
  /// cell is the tree's edge / 2^L (5.1). Default 7, range 0-18.
  vtkSetMacro(MaximumLevel, int);
  vtkGetMacro(MaximumLevel, int);
  ///@}

  ///@{
  /// Threads per rank; 0 means all hardware threads. Default 0, range 0-1024.
  vtkSetMacro(NumberOfThreads, int);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Memory the forest may take on all ranks together, in MB; 0 means the
  /// memory available. A MaximumLevel whose forest would not fit is refused
  /// with the level that fits. Default 0, range 0-16777216.
  vtkSetMacro(MemoryBudget, int);
  vtkGetMacro(MemoryBudget, int);
  ///@}

  /// The output data object.
  vtkHyperTreeGrid* GetOutput();

  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

protected:
  vtkOctreeSDF();
  ~vtkOctreeSDF() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  virtual int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  int MinimumLevel = 3;
  int MaximumLevel = 7;
  int NumberOfThreads = 0;
  int MemoryBudget = 0;

private:
  vtkOctreeSDF(const vtkOctreeSDF&) = delete;
  void operator=(const vtkOctreeSDF&) = delete;
};

#endif
