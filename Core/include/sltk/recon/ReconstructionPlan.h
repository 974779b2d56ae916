// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReconstructionPlan.h
/// Everything about a reconstruction that is known before its first grid is
/// allocated, computed once for reconstruct(), the filter, `sltk info` and the
/// benchmarks (Documentation/Architecture.md, "Data flow of a reconstruction"):
///
///  1. the options and the cloud are validated (PointCloud.h);
///  2. the cloud is cleaned when asked (CloudCleaning.h) and validated again;
///  3. it is moved into the unit box [-1, 1]^D (4.5, UnitBox.h);
///  4. one point locator is built on it, used for h_P (4.36), the distance d
///     (4.4.2) and the exact distances near the band (ExactDistanceCache.h);
///  5. the automatic parameters: C_dx against the memory budget, thinning of
///     a cloud denser than the finest grid, K_P from the enclosure of the
///     initial surface (AutomaticParameters.h), each logged with its reason;
///  6. h_P (4.36), run 1's initial ellipsoid when one is asked for, and the
///     grid of every run, dx^(r) = C_dx h_P / 2^(r-1) (4.36), run 1 padded so
///     that the initial surface K_P h_P outside the cloud (4.4.4) fits;
///  7. the memory of the finest grid against the budget (refused with a C_dx
///     that fits).

#include "sltk/cloud/CloudCleaning.h"
#include "sltk/cloud/PointLocator.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/levelset/Ellipsoid.h"
#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/GridPlan.h"
#include "sltk/recon/ReconstructionOptions.h"
#include "sltk/recon/UnitBox.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sltk
{

/// Memory one node of a run costs the solver: phi and d with ghosts, band
/// masks, the coarse field during the transfer between runs (measured).
constexpr double ReconstructionBytesPerNode = 40.0;

template <int D>
struct ReconstructionPlan
{
  ReconstructionOptions Options;                  ///< the options given, every automatic value chosen
  std::vector<std::string> Choices;               ///< what was chosen automatically, and why (logged)
  std::optional<OutsideFactorChoice> Enclosure;   ///< how an automatic K_P was chosen
  PointCloud<D> Cloud;                            ///< cleaned, in the unit box (4.5)
  UnitBox<D> Box;                                 ///< unit box <-> the user's units
  CloudCleaningReport Cleaning;                   ///< what the cleaning removed and merged
  std::unique_ptr<const PointLocator<D>> Locator; ///< on Cloud
  double CloudSpacing = 0.0;                      ///< h_P (4.36) of Cloud, unit-box units
  double CloudNoise = -1.0; ///< the cloud's noise in h_P before any thinning (CloudNoise.h); < 0: not measured
  std::optional<Ellipsoid<D>> InitialEllipsoid; ///< run 1's surface for InitialGuess sphere/ellipsoid
  GridPlan<D> Grids;                            ///< unit-box grids of runs 1..R
  std::vector<double> Sparsity;                 ///< rho per point of Cloud (LocalOffset); empty: uniform K_P h_P
  bool AutomaticCellSize = false;               ///< C_dx was chosen (the reconstruction may refine it)
  bool BudgetIsAutomatic = false;               ///< Options.MemoryBudget sized the automatic C_dx; not a limit
  double FirstRunReach = 0.0;                   ///< how far outside the cloud's box run 1's surface may lie
  std::int64_t PointsHeldMax = 0; ///< the most points of the cloud a rank held while planning (halos included)
  /// This rank's traffic while planning on the ranks' shares (planReconstructionOnRanks: the
  /// points' moves to their owners, the cleaning's and the automatic choices' exchanges, the
  /// gather of the cleaned cloud); none on one rank.
  CommTraffic Traffic;

  ReconstructionPlan() = default;
  ReconstructionPlan(const ReconstructionPlan&) = delete; // the locator points at Cloud
  ReconstructionPlan& operator=(const ReconstructionPlan&) = delete;

  /// The grid of run r (1-based) in the user's units.
  GridSpec<D> userGrid(int run) const { return this->Box.toUser(this->Grids.Runs[static_cast<size_t>(run - 1)]); }
  /// h_P in the user's units.
  double userCloudSpacing() const { return this->CloudSpacing * this->Box.Scale; }
  /// Estimated solver memory of run r (bytes).
  double memoryEstimate(int run) const
  {
    return static_cast<double>(this->Grids.Runs[static_cast<size_t>(run - 1)].nodeCount()) * ReconstructionBytesPerNode;
  }
};

/// planReconstruction() of the cloud whose shares the ranks hold (`share`, moved
/// in and freed once its points are at their owners: this rank's points, global indices firstId, firstId + 1, ...: a
/// parallel read's, consecutive in rank order), the same plan on every rank as one rank makes from the whole cloud, bit
/// for bit: the validation, the cleaning, the unit box, h_P, the noise, the automatic C_dx and thinning and the local
/// offset's rho run on the points' owners (CloudPoints.h, OwnedCloud); the cleaned and thinned cloud is then gathered
/// whole on every rank for the remaining steps (K_P, the windows, the grids) and the runs
/// (Documentation/Distributed.md, "Still whole on every rank"). Collective; fails on every rank alike.
template <int D>
Status planReconstructionOnRanks(PointCloud<D> share, std::int64_t firstId, const ReconstructionOptions& options,
  const Context& ctx, const Communicator& comm, ReconstructionPlan<D>& plan);

/// Checks a per-run (p, eta) schedule: the model (4.9) needs 1 <= p <= 10 and
/// 0 <= eta <= 100; the message names the first pair out of range. Front ends
/// call it to refuse a bad schedule before reading a cloud.
Status validateSchedule(const std::vector<RunParameters>& schedule);

/// Checks the options a user sets against their rows of OptionRanges.h (the
/// filters' and the CLI's ranges, narrower than what Algorithm 1 accepts),
/// the enumerations against their values and the schedule: the message names
/// the first option out of range by its filter property (MemoryBudget in MB)
/// and its range. The filters call it when they run; nothing is clamped.
Status validateOptionRanges(const ReconstructionOptions& options);

/// Checks the options of Algorithm 1 (ranges, the schedule, the reinitialisation).
template <int D>
Status validateReconstructionOptions(const ReconstructionOptions& options);

/// Steps 1-7 above on `cloud` (taken by value: moved in, cleaned and rescaled in place).
template <int D>
Status planReconstruction(
  PointCloud<D> cloud, const ReconstructionOptions& options, const Context& ctx, ReconstructionPlan<D>& plan);

/// The grids of `runs` runs from C_dx = cellSizeFactor (4.36) for the plan's
/// cloud, run 1 padded for FirstRunReach, against plan.Options.MemoryBudget.
template <int D>
Status planRunGrids(const ReconstructionPlan<D>& plan, int runs, double cellSizeFactor, GridPlan<D>& grids);

/// The grid options of `runs` runs from C_dx = cellSizeFactor (4.36) for the plan's
/// cloud and budget: run 1 padded for the plan's FirstRunReach, plus the band gamma and
/// two cells.
template <int D>
GridPlanOptions runGridOptions(const ReconstructionPlan<D>& plan, int runs, double cellSizeFactor);

/// When the plan's cloud is 2 to 16 groups of points more than PieceLinkFactor h_P
/// apart (PointClusters.h; SeparateGroups.cxx) whose own grids at C_dx = cellSizeFactor hold less than a
/// quarter of the nodes of the grid over all of them (two scanned objects in one
/// file; callers with an automatic C_dx pass the thesis's 1, where that choice starts): "The cloud is N groups of
/// points ... apart, and the grid spans the empty space between them (...); <why>: reconstruct each group in its own
/// run (split the file), the largest group's grid ..."; else "". A coarser grid cannot help such a cloud, so refusals
/// and results that do not fit say this instead.
template <int D>
std::string separateGroupsAdvice(const ReconstructionPlan<D>& plan, double cellSizeFactor, const std::string& why);

/// The same from the groups' boxes (groupBoxesOnRanks, LinkedComponents.h: computed on the
/// points' owners) and the box around every point: "" for fewer than 2 boxes.
template <int D>
std::string separateGroupsAdvice(const ReconstructionPlan<D>& plan, const std::vector<Box<D>>& boxes,
  const Box<D>& cloudBox, double cellSizeFactor, const std::string& why);

/// Nodes run r (1-based) will store: its grid's, or with OctreeStorage, for
/// runs 2..R, the tiles' estimated from the cloud (estimatedTiledNodes,
/// TiledMemory.h).
template <int D>
double storedNodesEstimate(const ReconstructionPlan<D>& plan, int run);

/// Solver memory of run r (bytes): memoryEstimate(), or with OctreeStorage,
/// for runs 2..R, its stored nodes at TiledBytesPerStoredNode and its slots
/// (what checkTiledMemory weighs for the finest run).
template <int D>
double storageMemoryEstimate(const ReconstructionPlan<D>& plan, int run);

extern template Status planRunGrids(const ReconstructionPlan<2>&, int, double, GridPlan<2>&);
extern template Status planRunGrids(const ReconstructionPlan<3>&, int, double, GridPlan<3>&);
extern template double storedNodesEstimate(const ReconstructionPlan<2>&, int);
extern template double storedNodesEstimate(const ReconstructionPlan<3>&, int);
extern template double storageMemoryEstimate(const ReconstructionPlan<2>&, int);
extern template double storageMemoryEstimate(const ReconstructionPlan<3>&, int);
extern template Status validateReconstructionOptions<2>(const ReconstructionOptions&);
extern template Status validateReconstructionOptions<3>(const ReconstructionOptions&);
extern template Status planReconstruction(
  PointCloud<2>, const ReconstructionOptions&, const Context&, ReconstructionPlan<2>&);
extern template Status planReconstruction(
  PointCloud<3>, const ReconstructionOptions&, const Context&, ReconstructionPlan<3>&);
extern template Status planReconstructionOnRanks(PointCloud<2>, std::int64_t, const ReconstructionOptions&,
  const Context&, const Communicator&, ReconstructionPlan<2>&);
extern template Status planReconstructionOnRanks(PointCloud<3>, std::int64_t, const ReconstructionOptions&,
  const Context&, const Communicator&, ReconstructionPlan<3>&);

} // namespace sltk
