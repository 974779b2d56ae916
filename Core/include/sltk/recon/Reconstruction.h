// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Reconstruction.h
/// Algorithm 1 of the thesis with the multi-run schedule (4.5.2): a signed
/// distance function whose zero level set is a closed curve (2D) or surface
/// (3D) through an unorganised point cloud.
///
/// For each run r = 1..R on the grid dx = C_dx h_P / 2^(r-1) (4.36):
///  1. the distance d to the cloud (4.4.2);
///  2. initial data: outside marking (4.4.4) in run 1, the previous run's
///     result interpolated on the new grid afterwards; cut (1.49);
///  3. until (4.33) or MaxIterations: band B^n (1.48), energies E_p and E_2
///     (4.29)/(4.30), the SL step (4.22)/(4.24) on B^n, the reinitialisation
///     band (1.53), constrained reinitialisation (1.38)-(1.45), cutting (1.49),
///     the metrics eps_1 (4.34) and Err_P (4.35).

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/grid/Slabs.h"
#include "sltk/recon/MissedPlaces.h"
#include "sltk/recon/ReconstructionOptions.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <cmath>
#include <cstdint>

#include <string>
#include <vector>

namespace sltk
{

/// What a reconstruction reports besides its fields and records, whatever the
/// dimension (ReconstructionSummary.h's too).
struct ReconstructionReport
{
  double CloudSpacing = 0.0;                               ///< h_P (of the cleaned cloud)
  double CellSizeFactor = 0.0;                             ///< C_dx used (chosen when automatic)
  double OutsideThresholdFactor = 0.0;                     ///< K_P used (raised when run 1 was restarted)
  InterpolatorKind Interpolator = InterpolatorKind::Weno3; ///< at the feet (chosen when automatic)
  double CloudNoise = -1.0; ///< the cloud's noise in h_P (CloudNoise.h) when it chose the interpolator; else < 0
  std::vector<std::string> Choices;    ///< the plan's automatic choices and their reasons
  CloudCleaningReport Cleaning;        ///< what the pre-processing removed and merged
  std::vector<std::string> Recoveries; ///< runs that lost their zero level set and what was done instead
  /// What the result does not fit in the cloud (points left far from the
  /// surface) and the option that may help; empty when it fits.
  std::vector<std::string> Warnings;
  /// False when more than FitShare of the points lie more than two finest cells and h_P from
  /// the surface (StoppingRule.h), when a place where the surface misses nearly every point
  /// holds LostPartShare of them (a lost part, MissedPlaces.h), or when the result has more
  /// Pieces than CloudComponents: the result does not fit the cloud, and Warnings says so first.
  bool FitsCloud = true;
  /// When it does not fit: the cloud is a few groups of points far apart whose grid is
  /// coarse for each (separateGroupsAdvice), and Warnings advise their own runs.
  bool SeparateGroups = false;
  /// The result's pieces: the connected components of {phi < 0} on the last run's grid
  /// (InsideComponents.h); -1 when not counted (the reconstruction failed).
  std::int64_t Pieces = -1;
  /// The cloud's connected components when points closer than PieceLinkFactor local
  /// spacings (at least PieceLinkFactor h_P) are linked (PointClusters.h, cloudComponents);
  /// -1 when not counted.
  std::int64_t CloudComponents = -1;
};

template <int D>
struct ReconstructionResult : ReconstructionReport
{
  GridField<D> SignedDistance; ///< phi of the last run (negative inside), cut at +-gamma far away
  GridField<D> Distance;       ///< d of the last run (4.4.2)
  /// The last run's whole grid, and this rank's slab of it (grid/Slabs.h): on
  /// several ranks SignedDistance and Distance hold the window, rows
  /// Slab.First .. Slab.Stop - 1, of which Slab.Begin .. Slab.End - 1 are owned
  /// (exact); on one rank the whole grid.
  GridSpec<D> WholeGrid;
  SlabPlan Slab;
  std::vector<RunRecord<D>> Runs;
  std::vector<IterationRecord> History;
  /// Where the points the last run misses lie, the largest groups first (MissedPlaces.h);
  /// empty when it misses none.
  std::vector<MissedPlace<D>> MissedPlaces;
};

/// Runs Algorithm 1. The cloud is validated first, then cleaned when
/// options.Cleaning asks for it (CloudCleaning.h; Err_P (4.35) is measured on
/// the cleaned cloud) and validated again; grids beyond the memory
/// budget are refused before anything is allocated. Progress goes to the
/// context's interrupter (abort: Status aborted, result holds what was done).
template <int D>
Status reconstruct(const PointCloud<D>& cloud, const ReconstructionOptions& options, const Context& ctx,
  ReconstructionResult<D>& result);

/// Runs Algorithm 1 on a plan (planReconstruction(), with its chosen options plan.Options).
/// Beyond the thesis, a run that loses its zero level set is recovered rather
/// than failed when it can be (Recoveries says how): run 1 with an automatic
/// K_P restarts with the ladder's next K_P (once); a later run is
/// replaced by the previous run's result.
///
/// On a communicator of several ranks (every rank holding the same plan,
/// made from the whole cloud) each run's grid is cut into slabs along its
/// last axis (grid/Slabs.h; Documentation/Distributed.md): each rank stores
/// and computes its window, exchanges ghost rows after every update, and the
/// energy, eps_1, Err_P, the stopping rule and the recoveries are reduced, so
/// every rank takes the same decisions. A collective call.
template <int D>
Status reconstruct(const ReconstructionPlan<D>& plan, const Context& ctx, ReconstructionResult<D>& result,
  const Communicator& comm = serialCommunicator());

/// The records of a unit-box reconstruction (History and Runs) in the user's
/// units: lengths times box.Scale, E_2 ~ length^((2 + D - 1) / 2). The fields
/// are left as they are.
template <int D>
void recordsToUser(const UnitBox<D>& box, ReconstructionResult<D>& result)
{
  const double energyScale = std::pow(box.Scale, (2.0 + D - 1.0) / 2.0);
  for (auto& it : result.History)
  {
    it.Energy *= energyScale;
    it.CloudError *= box.Scale;
  }
  for (auto& run : result.Runs)
  {
    run.Grid = box.toUser(run.Grid);
    run.Energy *= energyScale;
    run.CloudError *= box.Scale;
  }
  for (auto& place : result.MissedPlaces)
  {
    place.Centre = box.toUser(place.Centre);
    place.Lower = box.toUser(place.Lower);
    place.Upper = box.toUser(place.Upper);
  }
}

extern template Status reconstruct(
  const PointCloud<2>&, const ReconstructionOptions&, const Context&, ReconstructionResult<2>&);
extern template Status reconstruct(
  const PointCloud<3>&, const ReconstructionOptions&, const Context&, ReconstructionResult<3>&);
extern template Status reconstruct(
  const ReconstructionPlan<2>&, const Context&, ReconstructionResult<2>&, const Communicator&);
extern template Status reconstruct(
  const ReconstructionPlan<3>&, const Context&, ReconstructionResult<3>&, const Communicator&);

} // namespace sltk
