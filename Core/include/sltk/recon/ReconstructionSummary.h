// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReconstructionSummary.h
/// What a reconstruction reports besides its fields, in one type whatever the
/// dimension and the storage: the front ends' summary (the filters' field
/// data, `sltk reconstruct`'s table and --json), so that a front end reads it
/// typed rather than by the name of a field array.

#include "sltk/recon/Reconstruction.h"

#include <array>
#include <cstdint>
#include <vector>

namespace sltk
{

/// One run, in the user's units.
struct RunSummary : RunFigures
{
  std::array<Index, 3> GridDimensions{ 1, 1, 1 }; ///< nodes per axis (1 on the axes a 2D run lacks)
  /// The octree storage (ReconstructionOptions::OctreeStorage; 0 otherwise): the
  /// nodes stored at the run's end, the nodes of its uniform grid, the octree's
  /// leaves over every rank and the most of them one rank owns (run 1, uniform:
  /// its grid's nodes, the largest slab's).
  Index StoredNodes = 0;
  Index UniformNodes = 0;
  Index Leaves = 0;
  Index LargestRankLeaves = 0;
};

struct ReconstructionSummary : ReconstructionReport
{
  std::vector<RunSummary> Runs;
  bool OctreeStorage = false; ///< the runs' StoredNodes, UniformNodes, Leaves and LargestRankLeaves are set
  /// The ranks the reconstruction ran on, and this rank's traffic (CommTraffic.h): bytes
  /// sent point to point (the ghost exchanges), its payload of the collectives times the
  /// ranks it reached, and collective calls (CountingCommunicator.h); each run's in Runs.
  int Ranks = 1;
  CommTraffic Traffic;
  /// The most points of the cloud a rank held while planning (ReconstructionPlan::PointsHeldMax):
  /// the whole cloud, or with shares the owners' points and the cleaned cloud gathered.
  std::int64_t PlanPointsHeldMax = 0;
  /// This rank's traffic while planning on the shares (ReconstructionPlan::Traffic), apart from Traffic.
  CommTraffic PlanTraffic;
  /// Where the last run's surface misses points (MissedPlaces.h), the largest places first,
  /// in the user's coordinates (the front end's local frame added back); z = 0 in 2D.
  std::vector<MissedPlace<3>> MissedPlaces;
};

/// The summary of a result whose records are in the user's units
/// (recordsToUser), its missed places moved by `frame` (the front end's local
/// frame, ReconstructionOptions::FrameShift); the traffic is the caller's to fill in.
template <int D>
ReconstructionSummary summarize(const ReconstructionResult<D>& result, const std::array<double, 3>& frame = {});

extern template ReconstructionSummary summarize(const ReconstructionResult<2>&, const std::array<double, 3>&);
extern template ReconstructionSummary summarize(const ReconstructionResult<3>&, const std::array<double, 3>&);

} // namespace sltk
