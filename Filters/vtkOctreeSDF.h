// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOctreeSDF
 * @brief   Signed distance to an unorganised point cloud on an adaptive
 *          octree (p4est), output as a vtkHyperTreeGrid (thesis ch. 5).
 *
 * Input: any vtkPointSet (points only). Output: vtkHyperTreeGrid with the
 * cell array "SignedDistance", refined from MinimumLevel near nothing to
 * MaximumLevel near the reconstructed surface.
 *
 * @warning This version validates the input and creates the output type; the
 * adaptive level-set solver is not built yet and the filter reports so as an
 * error.
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
  /// Coarsest refinement level of the octree. Default 3, range 0-20.
  vtkSetClampMacro(MinimumLevel, int, 0, 20);
  vtkGetMacro(MinimumLevel, int);
  ///@}

  ///@{
  /// Finest refinement level (near the surface). Default 7, range 1-20.
  vtkSetClampMacro(MaximumLevel, int, 1, 20);
  vtkGetMacro(MaximumLevel, int);
  ///@}

  ///@{
  /// Threads; 0 means all hardware threads. Default 0.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /// The output data object.
  vtkHyperTreeGrid* GetOutput();

  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  vtkOctreeSDF();
  ~vtkOctreeSDF() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  virtual int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  int MinimumLevel = 3;
  int MaximumLevel = 7;
  int NumberOfThreads = 0;

private:
  vtkOctreeSDF(const vtkOctreeSDF&) = delete;
  void operator=(const vtkOctreeSDF&) = delete;
};

#endif
