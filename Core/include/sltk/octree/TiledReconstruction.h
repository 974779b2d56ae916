// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledReconstruction.h
/// Algorithm 1 (thesis 4.3-4.5) with the memory of runs 2..R proportional to
/// the surface: the adaptive idea of chapter 5 (refine where |phi| < beta,
/// 5.2.2; one level more per run, 5.3) on tiles of the uniform grids
/// (TiledField.h, Documentation/Octree.md "The tiled band").
///
///  - Run 1 is the uniform version's (its grid is the coarsest, 1/4^(R-1)
///    of the finest in 3D, and the outside marking 4.4.4 needs the whole box).
///  - Run r >= 2 keeps the tiles within one tile of run r-1's band, with phi
///    transferred by Q1 and d exact where the band reaches (within one node of
///    a band node, computed the first time); every other tile is a side
///    (+-gamma) taken from the sign of run r-1's phi.
///  - Every iteration is the uniform version's (4.22)/(4.24) step, energy
///    (4.29)/(4.30), reinitialisation (4.4.5), cut (1.49) and stopping rule
///    (4.33), run on copies of tiles or blocks of tiles and the nodes around
///    them; the slots within the reinitialisation's reach of a band node get
///    tiles first, so the band may move anywhere. The feet of (4.24) must stay
///    within 30 nodes of their tile (checked: an error names the displacement
///    otherwise).
///  - One deviation: the reinitialisation's pseudo-time steps evaluate the sign
///    (1.31) from the current iterate rather than from phi0 (the steady state
///    is the same; every step needs its tiles' neighbours, Documentation/Octree.md).
///
/// The result is the uniform version's finest grid, stored sparsely: the
/// same nodes, with phi = +-gamma where no tile is.

#include "sltk/exec/Communicator.h"
#include "sltk/octree/TiledField.h"
#include "sltk/recon/Reconstruction.h"
#include "sltk/recon/ReconstructionSummary.h"

namespace sltk
{

/// Storage of one run.
struct TiledRunRecord
{
  int Run = 0;
  Index Tiles = 0;             ///< tiles at the end of the run
  Index StoredNodes = 0;       ///< Tiles * 8^D
  Index Leaves = 0;            ///< the octree's leaves at the end of the run (IterationRecord::Leaves)
  Index LargestRankLeaves = 0; ///< the most of them one rank owns
  Index UniformNodes = 0;      ///< the uniform grid of the run
  Index AddedTiles = 0;        ///< tiles added during the run (the band moved)
  Index FreedTiles = 0;        ///< tiles freed during the run (the band left them: PruneTiles.h)
  Index PeakTiles = 0;         ///< the most tiles held at once during the run's iterations (distributed: the
                               ///< sum of each rank's most, ghosts included)
  Index ExactDistances = 0;    ///< nodes whose distance to the cloud was computed (TiledDistances)
  double Bytes = 0.0;          ///< the field's memory at the end of the run (this rank's)
  int GhostLayers = 0;         ///< distributed: the most layers of ghost tiles a step read (1 when the feet stay near)
};

template <int D>
struct TiledReconstructionResult
{
  /// The records of every run and iteration (History, Runs, Choices,
  /// recoveries...) in the user's units; SignedDistance and Distance are empty.
  ReconstructionResult<D> Records;
  TiledField<D> Field; ///< the last run's phi and d (near the band), unit-box units (4.5)
  UnitBox<D> Box;      ///< unit box <-> the user's units
  std::vector<TiledRunRecord> Storage;
  /// Distributed: the rank that owns each slot of Field (empty on one rank);
  /// the slots of a block of 4^D (aligned on multiples of 4) have one owner.
  /// Field then holds this rank's tiles and copies of the other ranks' tiles
  /// next to its slots (ghosts); every other tile's slot is Remote.
  std::vector<std::int32_t> Owners;
};

/// Whether slot `slot` is `rank`'s under a distributed result's `owners`
/// (TiledReconstructionResult::Owners; empty: every slot is).
inline bool ownedBy(const std::vector<std::int32_t>& owners, Index slot, int rank)
{
  return owners.empty() || owners[static_cast<size_t>(slot)] == rank;
}

/// Runs Algorithm 1 on the plan (planReconstruction()) with runs >= 2 tiled.
/// A plan with one run is run 1 alone, stored in tiles. With a communicator
/// of several ranks (each holding the same plan) the tiles are shared out in
/// Morton order (Documentation/Octree.md, "Distributing the tiled band"): every
/// rank returns the same records, and its tiles hold the one-rank values.
template <int D>
Status reconstructTiled(const ReconstructionPlan<D>& plan, const Context& ctx, TiledReconstructionResult<D>& result,
  const Communicator& comm = serialCommunicator());

/// Gathers a distributed result's tiles on rank `root` (collective): there,
/// Field becomes the whole field, as one rank computes it, and Owners is
/// cleared; the other ranks keep theirs. Nothing on one rank.
template <int D>
void gatherTiles(TiledReconstructionResult<D>& result, const Communicator& comm, int root = 0);

/// The run computes the distance to the cloud only within one node of the
/// band (TiledField's d is NaN elsewhere); this gives every stored node its
/// exact distance (the plan's cloud), for an output of the whole field;
/// with `owners` (a distributed result's) only the tiles `rank` owns, the
/// ones its output holds (not its ghosts). Returns how many nodes were
/// computed.
template <int D>
Index completeTiledDistances(const ReconstructionPlan<D>& plan, const Context& ctx, TiledField<D>& field,
  const std::vector<std::int32_t>& owners = {}, int rank = 0);

/// The summary of the records (summarize(ReconstructionResult), its missed places moved by
/// `frame`) with each run's storage: its stored nodes, its uniform grid's nodes and the
/// octree's leaves (run 1, uniform unless it is the only run: its grid's nodes, the
/// largest rank's from its history).
template <int D>
ReconstructionSummary summarize(const TiledReconstructionResult<D>& result, const std::array<double, 3>& frame = {});

extern template Status reconstructTiled(
  const ReconstructionPlan<2>&, const Context&, TiledReconstructionResult<2>&, const Communicator&);
extern template ReconstructionSummary summarize(const TiledReconstructionResult<2>&, const std::array<double, 3>&);
extern template ReconstructionSummary summarize(const TiledReconstructionResult<3>&, const std::array<double, 3>&);
extern template void gatherTiles(TiledReconstructionResult<2>&, const Communicator&, int);
extern template void gatherTiles(TiledReconstructionResult<3>&, const Communicator&, int);
extern template Index completeTiledDistances(
  const ReconstructionPlan<2>&, const Context&, TiledField<2>&, const std::vector<std::int32_t>&, int);
extern template Index completeTiledDistances(
  const ReconstructionPlan<3>&, const Context&, TiledField<3>&, const std::vector<std::int32_t>&, int);
extern template Status reconstructTiled(
  const ReconstructionPlan<3>&, const Context&, TiledReconstructionResult<3>&, const Communicator&);

} // namespace sltk
