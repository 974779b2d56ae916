// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkCWENOHJBSolver
 * @brief   Semi-Lagrangian solver of time-dependent Hamilton-Jacobi-Bellman
 *          equations v_t + H(t, x, Dv) = 0 with CWENO/CWENOZ/WENO3/Q1
 *          reconstructions (thesis ch. 2, 3, scheme (3.7)).
 *
 * Problems are the thesis's tests (Preset): 1 rotation of a C2 bump (2D,
 * pure transport), 2 semi-concave data (1D), 3 eikonal with a source (1D,
 * periodic, one control per RK stage), 4 quadratic Hamiltonian (2D), 5 the
 * Zermelo swimmer with obstacles and its reachable set (2D). Each uses its
 * thesis domain, RK order, controls and time step (lambda dx), with
 * NumberOfNodes nodes per direction.
 *
 * Output: vtkImageData with the point array "ValueFunction" at FinalTime
 * (Test 5 also "ReachTime", the first time a node enters the reachable set
 * (3.40), -1 if never) and, in its field data, "L1Error" and "LinfError"
 * (when an exact solution is known), "Steps", "EvaluationsPerNode",
 * "FinalTime". The output advertises sub-extents so that downstream parallel
 * writers get one block per rank; every rank computes the whole grid
 * (distributed HJB runs are not built yet).
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
    TEST1_ROTATION = 1,    ///< 3.5.1
    TEST2_SEMICONCAVE = 2, ///< 3.5.2
    TEST3_EIKONAL = 3,     ///< 3.5.3
    TEST4_QUADRATIC = 4,   ///< 3.5.4
    TEST5_ZERMELO = 5      ///< 3.5.5
  };

  ///@{
  /// The thesis test to solve. Default TEST1_ROTATION.
  vtkSetClampMacro(Preset, int, TEST1_ROTATION, TEST5_ZERMELO);
  vtkGetMacro(Preset, int);
  ///@}

  ///@{
  /// N: nodes per direction, both ends included (Test 3: distinct periodic nodes;
  /// Test 5: along x, y follows the domain). Default 81, range 5-100000.
  vtkSetClampMacro(NumberOfNodes, int, 5, 100000);
  vtkGetMacro(NumberOfNodes, int);
  ///@}

  ///@{
  /// Final time T; negative: the preset's (Tests 1, 2, 3: 1; Test 4: 0.5; Test 5: 3). Default -1.
  vtkSetMacro(FinalTime, double);
  vtkGetMacro(FinalTime, double);
  ///@}

  ///@{
  /// Courant number lambda: dt = lambda dx; 0: the preset's (Test 1: 3, Test 2: 10,
  /// Test 4: 1.25, Tests 3 and 5: 1). Default 0, range 0-100.
  vtkSetClampMacro(CourantNumber, double, 0.0, 100.0);
  vtkGetMacro(CourantNumber, double);
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

  int Preset = TEST1_ROTATION;
  int NumberOfNodes = 81;
  double FinalTime = -1.0;
  double CourantNumber = 0.0;
  int Interpolator = CWENOZ;
  int NumberOfThreads = 0;

private:
  vtkCWENOHJBSolver(const vtkCWENOHJBSolver&) = delete;
  void operator=(const vtkCWENOHJBSolver&) = delete;
};

#endif
