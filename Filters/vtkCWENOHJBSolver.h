// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkCWENOHJBSolver
 * @brief   Semi-Lagrangian solver of time-dependent Hamilton-Jacobi-Bellman
 *          equations v_t + H(t, x, Dv) = 0 with CWENO/CWENOZ/WENO3/Q1
 *          reconstructions (thesis ch. 2, 3, scheme (3.7)).
 *
 * The problem is either one of the thesis's tests (Preset 1-5: 1 rotation of
 * a C2 bump, 2 semi-concave data (1D), 3 eikonal with a source (1D,
 * periodic), 4 quadratic Hamiltonian, 5 the Zermelo swimmer with obstacles
 * and its reachable set; each with its domain, RK order, controls and time
 * step, NumberOfNodes per direction) or, with Preset = CUSTOM, given by
 * formulas in x, y, z, t, a1, a2, a3 (thesis (3.1)-(3.4), (3.39)):
 *
 *   v_t + max_{a in A} { -f_D(t, x, a) . Dv - f_C(t, x, a) } = 0,  v(0, x) = v_0(x),
 *   and, with an obstacle g, v = max(v, g) (state constraint g <= 0).
 *
 * Custom problems live on Dimensions nodes (1 on unused axes: {201, 1, 1} is
 * 1D) over DomainBounds, or on the grid of the optional input image, whose
 * active point scalars then give v_0. Syntax of the formulas: sltk/expr/Expression.h
 * (+ - * / % ^, comparisons, c ? a : b, sin ... atan2, min, max, clamp, if, pi, e).
 *
 * Output: vtkImageData with the point array "ValueFunction" at the requested
 * time; "ReachTime" (the first time a node is reached (3.40), -1 if never)
 * with an obstacle, with ComputeReachableSet, and for Test 5; in the field
 * data "Time", "Steps", "EvaluationsPerNode", "Ranks" (how many the solve was
 * split over) and, when an exact solution is
 * known, "L1Error" and "LinfError". The output advertises the scheme's time
 * steps t_k = k dt (TIME_STEPS), so ParaView animates the evolution: playing
 * forward continues from the last step computed, an earlier time restarts.
 * It also advertises sub-extents so that parallel writers get one block per
 * rank.
 *
 * Under MPI (pvbatch, pvserver, mpirun sltk hjb; the Controller, by default
 * the global controller), a custom problem is split over the ranks: each rank
 * stores and steps a slab of the last axis with ghost rows exchanged after
 * every step (sltk/hjb/DistributedHjbSolver.h; the values are bitwise those of
 * one rank), and the slabs are gathered for the requested extent. The presets
 * are still solved whole on every rank.
 */
#ifndef vtkCWENOHJBSolver_h
#define vtkCWENOHJBSolver_h

#include "SLTKFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkMultiProcessController;
namespace sltk
{
class Communicator;
class HjbSolver;
}

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
    CUSTOM = 0,            ///< the formulas below
    TEST1_ROTATION = 1,    ///< 3.5.1
    TEST2_SEMICONCAVE = 2, ///< 3.5.2
    TEST3_EIKONAL = 3,     ///< 3.5.3
    TEST4_QUADRATIC = 4,   ///< 3.5.4
    TEST5_ZERMELO = 5      ///< 3.5.5
  };

  ///@{
  /// The thesis test to solve. Default TEST1_ROTATION. Like every property with
  /// a range below, a value outside it is refused by the next update with its
  /// name and range, never clamped.
  vtkSetMacro(Preset, int);
  vtkGetMacro(Preset, int);
  ///@}

  ///@{
  /// N: nodes per direction, both ends included (Test 3: distinct periodic nodes;
  /// Test 5: along x, y follows the domain). Default 81, range 5-100000.
  vtkSetMacro(NumberOfNodes, int);
  vtkGetMacro(NumberOfNodes, int);
  ///@}

  ///@{
  /// Final time T; negative: the preset's (Tests 1, 2, 3: 1; Test 4: 0.5; Test 5: 3; custom: 1). Default -1.
  vtkSetMacro(FinalTime, double);
  vtkGetMacro(FinalTime, double);
  ///@}

  ///@{
  /// Courant number lambda: dt = lambda dx (custom: the smallest spacing); 0: the
  /// preset's (Test 1: 3, Test 2: 10, Test 4: 1.25, Tests 3 and 5: 1; custom: 1). Default 0, range 0-100.
  vtkSetMacro(CourantNumber, double);
  vtkGetMacro(CourantNumber, double);
  ///@}

  ///@{
  /// Reconstruction at the feet, an InterpolatorType value (RequestData refuses
  /// any other value with an error). Default CWENOZ.
  vtkSetMacro(Interpolator, int);
  vtkGetMacro(Interpolator, int);
  ///@}

  ///@{
  /// Threads of this rank; 0 (the default) means the cores this process may use shared among
  /// the MPI ranks on its machine, at most VTK_SMP_MAX_THREADS (sltk::threadsPerRank, the rule
  /// of every front end).
  vtkSetMacro(NumberOfThreads, int);
  vtkGetMacro(NumberOfThreads, int);
  /// The threads the last execution ran on this rank.
  vtkGetMacro(ThreadsUsed, int);
  ///@}

  enum ControlSetType
  {
    NO_CONTROL = 0, ///< pure transport, no minimisation
    BOX = 1,        ///< ControlLowerBound <= a <= ControlUpperBound
    BALL = 2,       ///< |a - ControlCenter| <= ControlRadius
    SPHERE = 3      ///< |a - ControlCenter| = ControlRadius (e.g. the Zermelo heading)
  };

  ///@{
  /// Custom problem: the components of f_D (in x, y, z, t, a1, a2, a3), one per
  /// axis used; the running cost f_C (empty: 0); v_0 (x, y, z; ignored with an
  /// input image); the obstacle g (x, y, z; empty: none); the exact solution
  /// (x, y, z, t; empty: unknown, else L1Error/LinfError are reported).
  vtkSetStringMacro(DynamicsX);
  vtkGetStringMacro(DynamicsX);
  vtkSetStringMacro(DynamicsY);
  vtkGetStringMacro(DynamicsY);
  vtkSetStringMacro(DynamicsZ);
  vtkGetStringMacro(DynamicsZ);
  vtkSetStringMacro(RunningCost);
  vtkGetStringMacro(RunningCost);
  vtkSetStringMacro(InitialValue);
  vtkGetStringMacro(InitialValue);
  vtkSetStringMacro(Obstacle);
  vtkGetStringMacro(Obstacle);
  vtkSetStringMacro(ExactSolution);
  vtkGetStringMacro(ExactSolution);
  ///@}

  ///@{
  /// Custom problem: closed-form argmin a*(t, x, y, z) of (3.7), one formula
  /// per control component (a1..a3 as many as ControlDimension). When given,
  /// it replaces the search of A (projected onto A; one evaluation per node
  /// and step). All empty (the default): the minimiser searches A.
  vtkSetStringMacro(ArgminA1);
  vtkGetStringMacro(ArgminA1);
  vtkSetStringMacro(ArgminA2);
  vtkGetStringMacro(ArgminA2);
  vtkSetStringMacro(ArgminA3);
  vtkGetStringMacro(ArgminA3);
  ///@}

  ///@{
  /// Custom problem grid: nodes per axis (1 on unused axes; periodic axes count
  /// distinct nodes) and the domain (xmin, xmax, ymin, ymax, zmin, zmax).
  /// Ignored when an input image is connected. Default {81, 81, 1} on [-1, 1]^3.
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  vtkSetVector6Macro(DomainBounds, double);
  vtkGetVector6Macro(DomainBounds, double);
  ///@}

  ///@{
  /// Custom problem: per axis, 1 for periodic, 0 for extrapolation (feet outside
  /// use the linear extension of the data). Default {0, 0, 0}.
  vtkSetVector3Macro(PeriodicAxes, int);
  vtkGetVector3Macro(PeriodicAxes, int);
  ///@}

  ///@{
  /// Custom problem: the control set A and its dimension m (a1..am). Default NO_CONTROL, m = 1.
  vtkSetMacro(ControlSet, int);
  vtkGetMacro(ControlSet, int);
  vtkSetMacro(ControlDimension, int);
  vtkGetMacro(ControlDimension, int);
  vtkSetVector3Macro(ControlLowerBound, double);
  vtkGetVector3Macro(ControlLowerBound, double);
  vtkSetVector3Macro(ControlUpperBound, double);
  vtkGetVector3Macro(ControlUpperBound, double);
  vtkSetVector3Macro(ControlCenter, double);
  vtkGetVector3Macro(ControlCenter, double);
  vtkSetMacro(ControlRadius, double);
  vtkGetMacro(ControlRadius, double);
  ///@}

  ///@{
  /// Custom problem: RK order of the feet (3.8) and of the cost quadrature (3.9). Default 3.
  vtkSetMacro(RKOrder, int);
  vtkGetMacro(RKOrder, int);
  ///@}

  ///@{
  /// Custom problem, minimisation over A (thesis 3.2): tabulation points per
  /// axis of A, then Nelder-Mead (golden section in 1D) to this tolerance on
  /// the control; one control per RK stage (A^nu) or one per step. Defaults 33, 1e-8, on.
  vtkSetMacro(TabulationPoints, int);
  vtkGetMacro(TabulationPoints, int);
  ///@}

  ///@{
  /// Custom problem: 0 (default) tabulates A at every node and step (thesis
  /// 3.2). N > 0 tabulates A at the first step only and then searches an N^q
  /// grid of tabulation spacing around each node's previous argmin (q the
  /// control parameters): ~8x fewer evaluations where the optimal control
  /// moves continuously in time (Test 4), but it can miss the global minimum
  /// where the control jumps. 0..15.
  vtkSetMacro(WarmStartPoints, int);
  vtkGetMacro(WarmStartPoints, int);
  vtkSetMacro(MinimizerTolerance, double);
  vtkGetMacro(MinimizerTolerance, double);
  vtkSetMacro(PerStageControls, vtkTypeBool);
  vtkGetMacro(PerStageControls, vtkTypeBool);
  vtkBooleanMacro(PerStageControls, vtkTypeBool);
  ///@}

  ///@{
  /// Custom problem: also output ReachTime without an obstacle (3.40). Default off.
  vtkSetMacro(ComputeReachableSet, vtkTypeBool);
  vtkGetMacro(ComputeReachableSet, vtkTypeBool);
  vtkBooleanMacro(ComputeReachableSet, vtkTypeBool);
  ///@}

  ///@{
  /// The ranks a custom problem is split over (nullptr, the default: the global controller, as in
  /// pvbatch and pvserver; a vtkDummyController solves on this process alone).
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkCWENOHJBSolver();
  ~vtkCWENOHJBSolver() override;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Builds the solver of the current properties (and input image, or its grid only when values is null),
  /// split over `comm`'s ranks for a custom problem when comm has more than one.
  int BuildSolver(vtkInformation* inInfo, vtkImageData* values, std::unique_ptr<sltk::HjbSolver>& solver,
    const sltk::Communicator* comm = nullptr);


  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Every request runs guarded: an exception becomes the filter's error (SLTKGuard.h).
  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Preset = TEST1_ROTATION;
  int NumberOfNodes = 81;
  double FinalTime = -1.0;
  double CourantNumber = 0.0;
  int Interpolator = CWENOZ;
  int NumberOfThreads = 0;
  int ThreadsUsed = 0;
  char* DynamicsX = nullptr;
  char* DynamicsY = nullptr;
  char* DynamicsZ = nullptr;
  char* RunningCost = nullptr;
  char* InitialValue = nullptr;
  char* Obstacle = nullptr;
  char* ExactSolution = nullptr;
  char* ArgminA1 = nullptr;
  char* ArgminA2 = nullptr;
  char* ArgminA3 = nullptr;
  int Dimensions[3] = { 81, 81, 1 };
  double DomainBounds[6] = { -1.0, 1.0, -1.0, 1.0, -1.0, 1.0 };
  int PeriodicAxes[3] = { 0, 0, 0 };
  int ControlSet = NO_CONTROL;
  int ControlDimension = 1;
  double ControlLowerBound[3] = { -1.0, -1.0, -1.0 };
  double ControlUpperBound[3] = { 1.0, 1.0, 1.0 };
  double ControlCenter[3] = { 0.0, 0.0, 0.0 };
  double ControlRadius = 1.0;
  int RKOrder = 3;
  int TabulationPoints = 33;
  int WarmStartPoints = 0;
  double MinimizerTolerance = 1e-8;
  vtkTypeBool PerStageControls = 1;
  vtkTypeBool ComputeReachableSet = 0;

private:
  vtkMultiProcessController* Controller = nullptr;
  std::unique_ptr<sltk::Communicator> Communicator; ///< the Solver's (declared first: destroyed after it)
  std::unique_ptr<sltk::HjbSolver> Solver;          ///< kept between time requests (animation)
  vtkMTimeType SolverKey = 0;                       ///< max MTime of this filter and its input when built
  vtkCWENOHJBSolver(const vtkCWENOHJBSolver&) = delete;
  void operator=(const vtkCWENOHJBSolver&) = delete;
};

#endif
