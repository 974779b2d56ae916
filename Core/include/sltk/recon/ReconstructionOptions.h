// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReconstructionOptions.h
/// Parameters of Algorithm 1 (thesis 4.3-4.5) and the records it returns.

#include "sltk/cloud/CloudCleaning.h"
#include "sltk/exec/CommTraffic.h"
#include "sltk/grid/GridSpec.h"
#include "sltk/interp/InterpolatorKind.h"
#include "sltk/levelset/ReinitOptions.h"
#include "sltk/recon/OptionRanges.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace sltk
{

/// How the first run's initial data is built.
enum class InitialGuess : std::uint8_t
{
  OutsideMarking = 0, ///< 4.4.4: external marking + fast sweeping
  BoundingSphere = 1, ///< a sphere around the cloud (the knot test)
  BoundingEllipsoid = 2
};

/// InitialGuess's values as a filter property (an enumeration, not a row of
/// OptionRanges: the plugin XML lists its values).
constexpr OptionRange InitialGuessRange{ "InitialGuess", 0, 2, false };

/// The unit of MemoryBudget in the front ends (the filters' property, the CLI's
/// --memory-budget): MB of 2^20 bytes.
constexpr std::uint64_t BytesPerMB = std::uint64_t(1) << 20;

/// p and eta of one run (Table 4.1).
struct RunParameters
{
  double P = 2.0;
  double Eta = 1.0;
};

/// Table 4.1: r = 1: (1, 0.05); r = 2: (2, 0.05); r >= 3: (2, 1).
inline RunParameters table41(int run)
{
  if (run <= 1)
  {
    return { 1.0, 0.05 };
  }
  if (run == 2)
  {
    return { 2.0, 0.05 };
  }
  return { 2.0, 1.0 };
}

/// The ranges of C_dx, K_P and the finest octree level given explicitly (0 is
/// automatic; OptionRanges.h holds every option's range).
constexpr double CellSizeFactorRange[2] = { optionRange("CellSizeFactor").Min, optionRange("CellSizeFactor").Max };
constexpr double OutsideThresholdFactorRange[2] = { optionRange("OutsideThresholdFactor").Min,
  optionRange("OutsideThresholdFactor").Max };
constexpr int MaximumLevelRange[2] = { static_cast<int>(optionRange("MaximumLevel").Min),
  static_cast<int>(optionRange("MaximumLevel").Max) };

struct ReconstructionOptions
{
  int Runs = 3; ///< runs of Algorithm 1, each halving dx (4.36)
  /// C_dx (4.36); 0: automatic, 1 (the thesis's default) unless the finest grid
  /// would not fit the memory budget (AutomaticParameters.h).
  double CellSizeFactor = 0.0;
  /// The thesis's octree level instead of C_dx (0: off): the finest cell is the
  /// cloud's largest extent / 2^MaximumLevel, (5.1) with (5.10)-(5.11), so run 1
  /// is at level MaximumLevel - Runs + 1 (GridPlan.h cellSizeFactorForLevel).
  int MaximumLevel = 0;
  /// K_P: gamma_P = K_P h_P (4.4.4; the thesis: 2, 10 for scans with holes);
  /// 0: automatic, the K_P whose initial surface encloses the most (AutomaticParameters.h).
  double OutsideThresholdFactor = 0.0;
  int Padding = 10;        ///< empty cells around the cloud per side
  int MaxIterations = 100; ///< iteration cap per run (4.33)
  int MinIterations = 10;  ///< iterations forced before (4.33) may stop a run
  double Tolerance = 1e-4; ///< threshold of Delta_E (4.33)
  int EnergyWindow = 10;   ///< k = min(n, EnergyWindow) of (4.33)
  /// At the feet (4.22)/(4.24). Empty (the default): automatic, the chapter 5
  /// least-squares Q1 (5.5, LsqQ1.h) on a cloud whose noise is below
  /// AutomaticInterpolatorNoise, else WENO3, the thesis's chapter 4 choice for
  /// laser scans (AutomaticParameters.h; measured in Documentation/Profile.md);
  /// the plan holds the kind chosen. Or any kind of InterpolatorKind.h.
  std::optional<InterpolatorKind> Interpolator;
  InitialGuess Guess = InitialGuess::OutsideMarking;
  /// Per-run p and eta; empty: Table 4.1 with FinalEta. Run r uses entry min(r, size) - 1.
  std::vector<RunParameters> Schedule;
  /// eta of the runs r >= 3 when Schedule is empty (Table 4.1: 1); larger
  /// values smooth noisy data (thesis Fig. 4.8, 4.11). A schedule replaces it.
  double FinalEta = 1.0;
  double BetaFactor = 2.0;  ///< beta = 2 dx (4.4.6)
  double GammaFactor = 4.0; ///< gamma = 4 dx (4.4.6)
  int ReinitDilation = 1;   ///< k of the reinitialisation band (1.53)
  /// Constrained reinitialisation (4.4.5); 10 pseudo-time steps (dtau = dx/2) carry
  /// information across the band (gamma + k dx = 5 dx) once, which was enough on the
  /// bunny (same Err_P to 3 digits as 50 steps, half the time).
  ReinitOptions Reinit = []
  {
    ReinitOptions r;
    r.MaxIterations = 10;
    return r;
  }();
  /// Beyond the thesis: run 1's initial surface at K_P h_P rho(x), rho the local
  /// sparsity of the cloud (recon/LocalOffset.h); false: the thesis's K_P h_P.
  bool LocalOffset = true;
  /// Beyond the thesis: (4.33) stops a run only once the surface has reached
  /// the cloud or stopped approaching it: while more than 1% of the points lie
  /// over one cell of run 1 from the zero level set and that fraction fell by
  /// 10% over the last EnergyWindow iterations, the run goes on (up to
  /// MaxIterations). False: the thesis's rule alone.
  bool FollowFarPoints = true;
  /// Beyond the thesis, opt-in: each run after the first starts from the
  /// previous run's surface united with balls around the points that run left
  /// outside by more than a cell and h_P (recon/FarPointSeeds.h): thin parts a
  /// coarse run lost grow back on the finer grids. Off by default: on the
  /// teapot it adds a piece (Documentation/Numerics.md). False: the thesis's transfer.
  bool SeedFarPoints = false;
  /// Bytes; 0: AutomaticMemoryBudget (1 GiB) when C_dx is automatic, the memory available otherwise.
  /// The automatic 1 GiB sizes the whole grid (its C_dx); split over ranks, their windows are
  /// checked against the memory available.
  std::uint64_t MemoryBudget = 0;
  /// The ranks the grids are split over (the front ends set it from their
  /// communicator) and how many of them share this machine's memory
  /// (ranksSharingThisMachine): the memory check sizes their windows
  /// (SlabPolicy.h). The automatic C_dx sizes the whole grid, so that it is
  /// the same on any rank count, unless those windows do not fit the limit
  /// (MemoryBudget given, else MemoryAvailable): then the smallest C_dx whose
  /// windows fit (Documentation/Distributed.md, "Memory check").
  int Ranks = 1;
  int RanksHere = 1;
  /// Bytes the windows may take when no MemoryBudget is given; 0: this
  /// machine's memory available (availableMemoryBytes). Under MPI the front
  /// ends set the least over the ranks, so that a C_dx it sizes is the same on
  /// every rank.
  std::uint64_t MemoryAvailable = 0;
  /// The octree storage: runs 2..R stored in tiles (octree/TiledReconstruction.h): the memory check
  /// sizes run 1's grid and the finest run's tiles (TiledMemory.h), not the
  /// finest uniform grid. The automatic C_dx still sizes the uniform grid.
  bool OctreeStorage = false;
  bool DetectTunnels = false; ///< 4.5.6: follow grad phi where 0.6 h_P < d < 2 dx and |grad d| < 0.5
  /// Beyond the thesis: the SL step (4.24) takes its four feet only where |phi| <= beta (the
  /// cut-off's plateau, where the front can be after the step); the band beyond takes the
  /// step's first-order expansion (LevelSetStepParameters::FeetWithin), a starting value the
  /// reinitialisation (1.38)-(1.45) then rebuilds from the front. Half the band's feet for
  /// the same surfaces (Documentation/Profile.md, "The feet within beta"). False: the thesis's step.
  bool FeetWithinBeta = true;
  /// Pre-processing of merged, noisy scans (CloudCleaning.h): automatic by
  /// default (gross outliers only, thinning only when the cloud is denser than
  /// the finest grid), so the thesis's clouds are reconstructed as given.
  CloudCleaningOptions Cleaning;
  /// Where the cloud's frame lies in the user's coordinates: the shift a front end
  /// subtracted from a cloud far from the origin (cloud/LocalFrame.h). The positions
  /// messages name add it back, so that they are the user's; it changes no result.
  std::array<double, 3> FrameShift{};

  /// The thesis's parameters (4.5.2): C_dx = 1, K_P = 2, no cleaning, its
  /// stopping rule; the
  /// reproductions of its tables start from these.
  static ReconstructionOptions thesis()
  {
    ReconstructionOptions o;
    o.CellSizeFactor = 1.0;
    o.OutsideThresholdFactor = 2.0;
    o.Cleaning.Automatic = false;
    o.LocalOffset = false;
    o.FollowFarPoints = false;
    o.Interpolator = InterpolatorKind::Weno3; // chapter 4's
    o.FeetWithinBeta = false;
    return o;
  }

  RunParameters parameters(int run) const
  {
    if (this->Schedule.empty())
    {
      RunParameters table = table41(run);
      table.Eta = run >= 3 ? this->FinalEta : table.Eta;
      return table;
    }
    const size_t i =
      static_cast<size_t>(run) < this->Schedule.size() ? static_cast<size_t>(run) - 1 : this->Schedule.size() - 1;
    return this->Schedule[i];
  }
};

/// One iteration of a run: the convergence history of Algorithm 1.
struct IterationRecord
{
  int Run = 0;
  int Iteration = 0;
  double Energy = 0.0;     ///< E_2(phi^n) (4.33)
  double Change = 0.0;     ///< eps_1^n (4.34) between successive (reinitialised) iterates, over the
                           ///< nodes an iteration can change (the reinitialisation band)
  double CloudError = 0.0; ///< Err_P^n (4.35)
  Index BandSize = 0;      ///< |B^n|
  Index StoredNodes = 0;   ///< tiled storage: nodes held after the iteration (run 1: its grid); 0 otherwise
  /// Tiled storage: the octree's leaves after the iteration (a stored node within the grid, a flat
  /// cell of a tile, or a slot without a tile: the hyper tree grid's leaves, TiledField::leafCount,
  /// Documentation/Octree.md), over every rank
  /// and the most one rank owns; run 1 (uniform): its grid's nodes and the largest slab's. 0 otherwise.
  Index Leaves = 0;
  Index LargestRankLeaves = 0;
  Index UniformNodes = 0; ///< tiled storage: the run's uniform grid (the same finest cell); 0 otherwise
  double Seconds = 0.0;   ///< wall time since the run started
};

/// One run's figures, whatever the dimension (ReconstructionSummary.h's runs too).
struct RunFigures
{
  RunParameters Parameters;
  int Iterations = 0;
  double Energy = 0.0;
  double CloudError = 0.0;
  double FarPoints =
    0.0; ///< fraction of the points more than one cell of run 1 (C_dx h_P, at least h_P) from the surface
  /// Fraction of the points the surface misses, more than two of this run's cells and more
  /// than h_P from it (misfitDistance): after the last run, whether the result fits the
  /// cloud (Reconstruction.h, FitShare).
  double MisfitPoints = 0.0;
  double Seconds = 0.0;
  Index MeanBandSize = 0;
  Index GhostRows = 0; ///< on several ranks: each slab's ghost rows (RunSlab.h); 0 on one rank
  Index FarFeet = 0;   ///< on several ranks: feet of the run's steps interpolated by another rank (all ranks')
  /// The most points one rank's run read: on slabs its window's and those within reach of it
  /// (recon/RunPoints.h); the whole cloud on one rank and on the tiled band.
  Index PointsHeld = 0;
  /// Single-node specks of the run's result given their neighbours' mean (levelset/IsolatedNodes.h)
  Index MergedNodes = 0;
  /// This rank's traffic from the run's set-up to the end of its iterations and the
  /// summaries after them (zeros unless the communicator counts it, CountingCommunicator.h).
  CommTraffic Traffic;
};

template <int D>
struct RunRecord : RunFigures
{
  GridSpec<D> Grid;
};

} // namespace sltk
