// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkCWENOHJBSolver
 * @brief   Semi-Lagrangian solver of time-dependent Hamilton-Jacobi-Bellman
 *          equations v_t + H(t, x, Dv) = 0 with CWENO/CWENOZ/WENO3/Q1
 *          reconstructions (thesis ch. 2, 3, scheme (3.7)).
 *
 * Output: vtkImageData over Bounds with Dimensions nodes per axis (node
 * centred, both ends included) carrying the point array "ValueFunction".
 * The filter produces sub-extents: under MPI each rank computes only the
 * block the pipeline requests.
 *
 * Problems are chosen by Preset (the thesis's tests). This version evaluates
 * the initial datum v0 exactly (FinalTime = 0); time stepping is not built
 * yet and a positive FinalTime is reported as an error.
 */
#ifndef vtkCWENOHJBSolver_h
#define vtkCWENOHJBSolver_h

#include "SLTKFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class SLTKFILTERS_EXPORT vtkCWENOHJBSolver : public vtkImageAlgorithm
{
public:
  static vtkCWENOHJBSolver* New();
  vtkTypeMacro(vtkCWENOHJBSolver, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum InterpolatorType
  {
    Q1 = 0,
    WENO3 = 1,
    CWENO = 2,
    CWENOZ = 3
  };

  enum PresetType
  {
    Test1Rotation = 1 ///< 3.5.1: rigid rotation of a C2 bump on [0,1]^2
  };

  ///@{
  /// The thesis test to solve. Default Test1Rotation.
  vtkSetClampMacro(Preset, int, Test1Rotation, Test1Rotation);
  vtkGetMacro(Preset, int);
  ///@}

  ///@{
  /// Nodes per axis, both ends included (thesis: N). Unused axes must be 1. Default 81 81 1.
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  ///@{
  /// Domain (xmin, xmax, ymin, ymax, zmin, zmax). Default the unit square.
  vtkSetVector6Macro(Bounds, double);
  vtkGetVector6Macro(Bounds, double);
  ///@}

  ///@{
  /// Final time T >= 0. Default 0 (the initial datum).
  vtkSetClampMacro(FinalTime, double, 0.0, 1e30);
  vtkGetMacro(FinalTime, double);
  ///@}

  ///@{
  /// Courant number lambda: dt = lambda * dx. Default 3 (Test 1), range 0.01-100.
  vtkSetClampMacro(CourantNumber, double, 0.01, 100.0);
  vtkGetMacro(CourantNumber, double);
  ///@}

  ///@{
  /// Runge-Kutta order of the characteristics: 1 (2.43), 2 (2.44), 3 (2.45). Default 3.
  vtkSetClampMacro(RungeKuttaOrder, int, 1, 3);
  vtkGetMacro(RungeKuttaOrder, int);
  ///@}

  ///@{
  /// Reconstruction at the feet. Default CWENOZ.
  vtkSetClampMacro(Interpolator, int, Q1, CWENOZ);
  vtkGetMacro(Interpolator, int);
  ///@}

  ///@{
  /// Threads; 0 means all hardware threads. Default 0.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkCWENOHJBSolver();
  ~vtkCWENOHJBSolver() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// Checks Dimensions and Bounds; reports the first problem with vtkErrorMacro.
  bool ValidateGrid();

  int Preset = Test1Rotation;
  int Dimensions[3] = { 81, 81, 1 };
  double Bounds[6] = { 0.0, 1.0, 0.0, 1.0, 0.0, 0.0 };
  double FinalTime = 0.0;
  double CourantNumber = 3.0;
  int RungeKuttaOrder = 3;
  int Interpolator = CWENOZ;
  int NumberOfThreads = 0;

private:
  vtkCWENOHJBSolver(const vtkCWENOHJBSolver&) = delete;
  void operator=(const vtkCWENOHJBSolver&) = delete;
};

#endif
