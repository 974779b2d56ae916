// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSLLevelSetReconstruct
 * @brief   Watertight implicit surface from an unorganised point cloud by a
 *          semi-Lagrangian level-set method (Zhao's model, thesis ch. 1, 2, 4).
 *
 * Input: any vtkPointSet; only its points are used (cells are ignored).
 * Outputs:
 *  - port 0: vtkImageData with the point arrays "SignedDistance" (negative
 *    inside; cut at +-4 dx away from the surface, (1.49)) and "DistanceToCloud",
 *    and a per-run summary in its field data (CloudSpacing, RunGridDimensions,
 *    RunIterations, RunEnergy, RunCloudError, RunFarPoints, RunMisfitPoints, RunSeconds;
 *    MissedPlaces, where the last run misses points, a tuple of 11 per place (Points,
 *    Nearby: the cloud's points there, Centre, Lower, Upper in the input's coordinates);
 *    FitsCloud, 0 when more than 5% of the points lie more than two finest cells
 *    and h_P from the surface, when one place holds at least 0.5% of them and the
 *    surface misses 85% of the points there (a lost part, MissedPlaces.h), or when the result has more Pieces (components of
 *    its inside) than the cloud has CloudComponents (points within 4 local spacings linked); the strings
 * AutomaticChoices, Recoveries and Warnings, the last empty unless the result leaves points far from its surface, with
 * the option that may help); with OctreeStorage a vtkHyperTreeGrid with the same values as cell data;
 *  - port 1: vtkPolyData, the zero isosurface (3D) or contour (2D);
 *  - port 2: vtkTable, the convergence history (run, iteration, energy E_2,
 *    eps_1, Err_P, band size, time) for ParaView line charts.
 *
 * The grid is derived from the data: dx = CellSizeFactor * h_P / 2^(r-1) in
 * run r, where h_P is the mean nearest-neighbour spacing of the cloud
 * (thesis (4.36)), padded by Padding cells on each side. A cloud whose z
 * extent is zero is reconstructed in 2D (a closed curve in its plane). A cloud
 * far from the origin for its size (survey coordinates) is reconstructed in a
 * local frame and the outputs come back in its coordinates, the surface's points
 * in double (sltk/cloud/LocalFrame.h).
 *
 * Under MPI (pvbatch, pvserver, mpirun sltk reconstruct; the Controller, by
 * default the global controller) every rank reads the whole cloud and plans
 * the same grids, and each run's grid is split into slabs along its last
 * axis (sltk/recon/Reconstruction.h, Documentation/Distributed.md): each rank
 * stores and computes its slab, and outputs its block of the image (its
 * owned rows and the next rank's first row, in the whole grid's extent), its
 * piece of the zero level set (the pieces join: they share the block
 * boundaries' points) and, on rank 0, the whole history. A block carries the
 * ghost levels asked of it (up to 5 rows of the neighbours', flagged in
 * vtkGhostType); the surface and the history are complete for any ghost level
 * (so that ParaView's request of one for the surface does not run the
 * reconstruction again), the image for the levels it holds.
 * With OctreeStorage, runs 2..R share their tiles out over the ranks in
 * Morton order while they compute (Documentation/Octree.md, "Distributing the
 * tiled band"), with the one-rank iterations and values (to rounding,
 * Documentation/Octree.md): each rank outputs the trees of its own tiles
 * (cell array Rank) and its piece of the surface (the pieces join), rank 0
 * also the history and the run summary.
 */
#ifndef vtkSLLevelSetReconstruct_h
#define vtkSLLevelSetReconstruct_h

#include "SLTKFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkMultiProcessController;
#ifndef __VTK_WRAP__
namespace sltk
{
struct ReconstructionOptions;
struct ReconstructionSummary;
}
#endif

class SLTKFILTERS_EXPORT vtkSLLevelSetReconstruct : public vtkImageAlgorithm
{
public:
  static vtkSLLevelSetReconstruct* New();
  vtkTypeMacro(vtkSLLevelSetReconstruct, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Core's table of the options' ranges (sltk/recon/OptionRanges.h), the one
  /// source of the filters' checks, the CLI's and the plugin XML's domains: row
  /// `i`'s property, its range and whether its 0 means automatic (the
  /// reconstruction's and vtkCWENOHJBSolver's properties).
  static int GetNumberOfPropertyRanges();
  static const char* GetPropertyRangeName(int i);
  static double GetPropertyRangeMinimum(int i);
  static double GetPropertyRangeMaximum(int i);
  static bool GetPropertyRangeZeroIsAutomatic(int i);
  ///@}

  /// Spatial reconstruction used at the feet of the characteristics.
  enum InterpolatorType
  {
    AUTOMATIC = -1,      ///< LEAST_SQUARES_Q1 on a cloud whose noise is below 0.08 h_P, else WENO3 (logged)
    Q1 = 0,              ///< multilinear (4.28)
    WENO3 = 1,           ///< dimension-split WENO3 (2.65)-(2.76)
    CWENO = 2,           ///< central WENO (3.10)-(3.28)
    CWENOZ = 3,          ///< central WENO-Z
    LEAST_SQUARES_Q1 = 4 ///< the thesis's chapter 5 least-squares Q1 (5.5), discontinuous between cells
  };

  ///@{
  /// Interpolator (default AUTOMATIC): an InterpolatorType value; RequestData
  /// refuses any other value with an error. AUTOMATIC measures the cloud's noise
  /// (field data CloudNoise, in h_P) and takes LEAST_SQUARES_Q1 below 0.08,
  /// WENO3 (the thesis's choice for laser scans) otherwise (field data
  /// Interpolator: the code used).
  /// LEAST_SQUARES_Q1 is the nearest node's Q1 polynomial fitted by least squares
  /// to its 3^D - 1 neighbours with the centre constraint (5.5); measured against
  /// WENO3 in Documentation/Profile.md.
  virtual void SetInterpolator(int value);
  virtual int GetInterpolator();
  ///@}

  // The properties below are not clamped: a value outside its documented range
  // is refused, naming the property and the range, when the filter runs.

  ///@{
  /// Number of runs of the multi-run schedule, each halving dx (Table 4.1). Default 3, range 1-6.
  virtual void SetNumberOfRuns(int value);
  virtual int GetNumberOfRuns();
  ///@}

  ///@{
  /// C_dx: grid spacing of the first run in units of h_P (4.36). Default 0:
  /// automatic (1, the thesis's, unless the finest grid would exceed
  /// MemoryBudget; sltk/recon/AutomaticParameters.h); otherwise 0.05-100
  /// (other values are refused when the filter runs).
  virtual void SetCellSizeFactor(double value);
  virtual double GetCellSizeFactor();
  ///@}

  ///@{
  /// The thesis's octree level instead of CellSizeFactor (default 0: off):
  /// the finest cell is the cloud's largest extent / 2^MaximumLevel ((5.1)
  /// with (5.10)-(5.11)), run 1 at level MaximumLevel - NumberOfRuns + 1.
  /// Range 1-30 with CellSizeFactor 0; a level whose grid would not fit the
  /// memory is refused with the level that fits.
  virtual void SetMaximumLevel(int value);
  virtual int GetMaximumLevel();
  ///@}

  ///@{
  /// K_P: the outside-marking threshold K_P h_P of the initial data (4.4.4).
  /// Default 0: automatic (the K_P of 2-32, at least 2 CellSizeFactor, whose
  /// initial surface encloses the most; the thesis uses 2, and 10 for scans
  /// with holes); otherwise 0.1-100.
  virtual void SetOutsideThresholdFactor(double value);
  virtual double GetOutsideThresholdFactor();
  ///@}

  ///@{
  /// Iteration cap per run (4.33). Default 100, range 1-100000.
  virtual void SetMaximumNumberOfIterations(int value);
  virtual int GetMaximumNumberOfIterations();
  ///@}

  ///@{
  /// Stopping tolerance on the relative energy change (4.33). Default 1e-4, range 0-1.
  virtual void SetTolerance(double value);
  virtual double GetTolerance();
  ///@}

  ///@{
  /// Empty cells added around the cloud's bounding box on every side. Default 10, range 4-1000.
  virtual void SetPadding(int value);
  virtual int GetPadding();
  ///@}

  /// Initial surface of the first run.
  enum InitialGuessType
  {
    OUTSIDE_MARKING = 0, ///< 4.4.4: marking from the boundary, threshold K_P h_P
    BOUNDING_SPHERE = 1, ///< a sphere around the cloud (the thesis's knot test)
    BOUNDING_ELLIPSOID = 2
  };

  ///@{
  /// Initial surface of the first run. Default OUTSIDE_MARKING.
  virtual void SetInitialGuess(int value);
  virtual int GetInitialGuess();
  ///@}

  ///@{
  /// eta of the runs r >= 3 (Table 4.1: 1). Larger values smooth noisy data
  /// (thesis Fig. 4.8, 4.11). Default 1, range 0-100.
  virtual void SetFinalEta(double value);
  virtual double GetFinalEta();
  ///@}

  ///@{
  /// Per-run p and eta of the model (4.9), as in the thesis's Table 4.1: run r
  /// uses entry min(r, n), so the last entry holds for all later runs. Empty
  /// (the default) means Table 4.1 with FinalEta for the runs r >= 3; a
  /// schedule replaces FinalEta. Example, the thesis's teapot (4.5.5), which
  /// keeps details with eta = 0 in the first two runs: (1, 0), (2, 0), (2, 1).
  /// Entries need 1 <= p <= 10 and 0 <= eta <= 100 (checked at execution).
  void AddRunParameters(double p, double eta);
  /// Appends one value, p and eta alternating (the ParaView property's command,
  /// so that an odd count reaches the filter and is refused instead of being
  /// dropped by the proxy).
  void AddRunParameterValue(double value);
  void RemoveAllRunParameters();
  int GetNumberOfRunParameters() const;
  int GetNumberOfRunParameterValues() const; ///< 2 per (p, eta) pair; odd when a value was added alone
  double GetRunP(int index) const;
  double GetRunEta(int index) const;
  ///@}

  ///@{
  /// LocalOffset (default on): run 1's initial surface lies K_P h_P rho(x) from
  /// the cloud, rho the local sparsity of the sampling (1 where it is even, up to
  /// 4; sltk/recon/LocalOffset.h); off: K_P h_P everywhere, as in the thesis.
  virtual void SetLocalOffset(bool value);
  virtual bool GetLocalOffset();
  vtkBooleanMacro(LocalOffset, bool);
  ///@}

  ///@{
  /// FollowFarPoints (default on): a run that the energy rule (4.33) would stop
  /// goes on while more than 1% of the points lie over one cell of run 1 from
  /// the surface and that fraction still falls (by 10% per 10 iterations), up
  /// to MaximumNumberOfIterations; off: the thesis's rule alone.
  virtual void SetFollowFarPoints(bool value);
  virtual bool GetFollowFarPoints();
  vtkBooleanMacro(FollowFarPoints, bool);
  ///@}

  ///@{
  /// FeetWithinBeta (default on): the SL step (4.24) interpolates its feet only
  /// at band nodes with |phi| <= beta; the band beyond takes the step to first
  /// order, which the reinitialisation rebuilds from the front; off: the thesis's
  /// step on the whole band.
  virtual void SetFeetWithinBeta(bool value);
  virtual bool GetFeetWithinBeta();
  vtkBooleanMacro(FeetWithinBeta, bool);
  ///@}

  ///@{
  /// SeedFarPoints (default off): each run after the first starts from the
  /// previous run's surface united with balls around the points that run left
  /// outside by more than a cell and h_P, so thin parts a coarse run lost grow
  /// back on the finer grids (it can add a piece: the teapot); off: the thesis's transfer.
  virtual void SetSeedFarPoints(bool value);
  virtual bool GetSeedFarPoints();
  vtkBooleanMacro(SeedFarPoints, bool);
  ///@}

  ///@{
  /// Memory budget of the automatic CellSizeFactor in MB; 0 (default): 1024 MB.
  /// With an explicit CellSizeFactor, 0 means the memory available. Under
  /// several ranks the check sizes the windows of the ranks on each machine
  /// (sltk/recon/SlabPolicy.h).
  virtual void SetMemoryBudget(int value);
  virtual int GetMemoryBudget();
  ///@}

  ///@{
  /// Pre-processing of merged range scans (sltk/cloud/CloudCleaning.h).
  /// AutomaticCleaning (default on) removes gross outliers only and thins a
  /// cloud denser than the finest grid; it is off as soon as RemoveOutliers or
  /// ThinningFactor is set. RemoveOutliers drops points whose mean distance to their 8 nearest
  /// neighbours exceeds the mean by OutlierDeviations standard deviations
  /// (default 3, range 0.5-100). ThinningFactor > 0 replaces the points of each
  /// voxel (edge ThinningFactor times the density spacing) by their mean
  /// (default 0: no thinning, range 0-100). The field data of port 0 report
  /// InputPoints, OutliersRemoved, ThinningCell and ReconstructedPoints.
  virtual void SetAutomaticCleaning(bool value);
  virtual bool GetAutomaticCleaning();
  vtkBooleanMacro(AutomaticCleaning, bool);
  virtual void SetRemoveOutliers(bool value);
  virtual bool GetRemoveOutliers();
  vtkBooleanMacro(RemoveOutliers, bool);
  virtual void SetOutlierDeviations(double value);
  virtual double GetOutlierDeviations();
  virtual void SetThinningFactor(double value);
  virtual double GetThinningFactor();
  ///@}

  ///@{
  /// Tunnel detection (thesis 4.5.6): where 0.6 h_P < d < 2 dx and |grad d| < 0.5,
  /// follow grad phi instead of grad d, so that the front goes down long narrow
  /// holes (two close sheets of points) instead of stopping at their mouth. Default off.
  virtual void SetDetectTunnels(bool value);
  virtual bool GetDetectTunnels();
  vtkBooleanMacro(DetectTunnels, bool);
  ///@}

  ///@{
  /// OctreeStorage (default off): runs 2..R store only the tiles of 8^3
  /// nodes (8^2 for a planar cloud) within one tile of the front, the finest levels of the octree
  /// (sltk/octree/TiledReconstruction.h, Documentation/Octree.md "The tiled
  /// band"): the same iterations and surface as the uniform grids, with memory
  /// that follows the surface. Port 0 is then a vtkHyperTreeGrid instead of
  /// the image: one tree per 8^3 nodes, refined to one leaf per node where a
  /// tile is stored but for its flat cells (one leaf at +-gamma each), and a
  /// single leaf (+-gamma) elsewhere, with the cell data
  /// SignedDistance, DistanceToCloud, Level and Rank, and the run summary in
  /// its field data (with RunStoredNodes, RunUniformNodes, RunLeaves and
  /// GlobalLeaves); the surface (port 1) is contoured tile by tile; the history
  /// (port 2) gains StoredNodes, Leaves, LargestRankLeaves and UniformNodes.
  /// vtkOctreeSDF is this filter with OctreeStorage always on. The automatic
  /// restart with a finer C_dx for thin parts is not done.
  virtual void SetOctreeStorage(bool value);
  virtual bool GetOctreeStorage();
  vtkBooleanMacro(OctreeStorage, bool);
  ///@}

  ///@{
  /// With OctreeStorage, whether port 0's hyper tree grid gets its trees
  /// (default on). Off, it holds only the run summary: no distance to the
  /// cloud is computed at the stored nodes beyond the band and no tree is
  /// built, for callers that want the surface alone (the CLI without -o);
  /// on the full dragon (52.7M stored nodes) the trees cost 1.5 GB and 3 minutes.
  vtkSetMacro(GenerateHyperTreeGrid, bool);
  vtkGetMacro(GenerateHyperTreeGrid, bool);
  vtkBooleanMacro(GenerateHyperTreeGrid, bool);
  ///@}

  ///@{
  /// Under MPI, whether each rank's input is its own share of one cloud (default
  /// off): no point in two shares, and the shares in rank order make the cloud's
  /// order, as a parallel read leaves them (the CLI's). On, the plan's cloud steps
  /// (validation, cleaning, unit box, h_P, noise, automatic C_dx and thinning) run
  /// on the shares, each point at the rank owning its place, and only the
  /// cleaned and thinned cloud is gathered on every rank; the result is the one
  /// a rank holding the whole cloud gives. Off, ranks whose inputs differ
  /// reconstruct the union of their points, a point repeated in several pieces
  /// (ghost points) counted once (sltk/cloud/CloudPieces.h).
  vtkSetMacro(CloudPiecesAreShares, bool);
  vtkGetMacro(CloudPiecesAreShares, bool);
  vtkBooleanMacro(CloudPiecesAreShares, bool);
  ///@}

  ///@{
  /// Deprecated: use SetOctreeStorage, GetOctreeStorage, OctreeStorageOn and
  /// OctreeStorageOff (AdaptiveStorage is OctreeStorage's old name; these
  /// forwarding methods are removed in the next release).
  void SetAdaptiveStorage(bool on) { this->SetOctreeStorage(on); }
  bool GetAdaptiveStorage() { return this->GetOctreeStorage(); }
  void AdaptiveStorageOn() { this->OctreeStorageOn(); }
  void AdaptiveStorageOff() { this->OctreeStorageOff(); }
  ///@}

  ///@{
  /// Deprecated: use SetGenerateHyperTreeGrid, GetGenerateHyperTreeGrid,
  /// GenerateHyperTreeGridOn and GenerateHyperTreeGridOff (GenerateAdaptiveGrid
  /// is GenerateHyperTreeGrid's old name; these forwarding methods are removed
  /// in the next release).
  void SetGenerateAdaptiveGrid(bool on) { this->SetGenerateHyperTreeGrid(on); }
  bool GetGenerateAdaptiveGrid() { return this->GetGenerateHyperTreeGrid(); }
  void GenerateAdaptiveGridOn() { this->GenerateHyperTreeGridOn(); }
  void GenerateAdaptiveGridOff() { this->GenerateHyperTreeGridOff(); }
  ///@}

#ifndef __VTK_WRAP__
  ///@{
  /// C++ only: the options the properties above read and write, Core's object
  /// (sltk/recon/ReconstructionOptions.h, its defaults the properties'), for a
  /// front end that fills it whole (the CLI). SetOptions replaces every option
  /// (Ranks and RanksHere are the Controller's when the filter runs) and
  /// forgets the property values Core cannot hold; the filter checks the
  /// options against Core's ranges when it runs.
  void SetOptions(const sltk::ReconstructionOptions& options);
  const sltk::ReconstructionOptions& GetOptions() const;
  ///@}

  /// C++ only: what the last execution reported on this rank, typed (null before
  /// one succeeded): the run summary that port 0's field data also hold, and this
  /// rank's traffic. Under MPI every rank has the same records but for the times,
  /// the ghost rows of its slab and its traffic.
  const sltk::ReconstructionSummary* GetLastSummary() const;
#endif

  ///@{
  /// The ranks the reconstruction is split over (nullptr, the default: the global controller, as in
  /// pvbatch and pvserver; a vtkDummyController reconstructs on this process alone).
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
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

protected:
  vtkSLLevelSetReconstruct();
  ~vtkSLLevelSetReconstruct() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Port 0's type: vtkImageData, or vtkHyperTreeGrid with OctreeStorage.
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  /// Every request runs guarded: an exception becomes the filter's error (SLTKGuard.h).
  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfThreads = 0;
  int ThreadsUsed = 0;
  bool GenerateHyperTreeGrid = true;
  bool CloudPiecesAreShares = false;
  vtkMultiProcessController* Controller = nullptr;

private:
  struct Internals; // Core's options and the last summary (the wrapper never sees Core's types)
  std::unique_ptr<Internals> Impl;
  vtkSLLevelSetReconstruct(const vtkSLLevelSetReconstruct&) = delete;
  void operator=(const vtkSLLevelSetReconstruct&) = delete;
};

#endif
