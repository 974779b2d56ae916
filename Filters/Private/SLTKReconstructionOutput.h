// SPDX-License-Identifier: BSD-3-Clause
#ifndef SLTKReconstructionOutput_h
#define SLTKReconstructionOutput_h
/// \file SLTKReconstructionOutput.h
/// Core reconstruction results -> VTK outputs: the image with the signed
/// distance and the distance to the cloud, the zero isosurface/contour, and the
/// convergence history table.

#include "sltk/recon/Reconstruction.h"
#include "sltk/recon/ReconstructionSummary.h"
#include "sltk/recon/SlabPolicy.h"

class vtkDataObject;
class vtkImageData;
class vtkPointSet;
class vtkPolyData;
class vtkTable;

namespace sltk
{
namespace vtkbridge
{

/// Moves phi ("SignedDistance", active scalars) and d ("DistanceToCloud") into
/// `image` (the result's fields are freed one by one as they are copied, so the
/// peak memory holds three fields, not four); a 2D result becomes an image with
/// one z layer at height z. A distributed result (several ranks) gives this
/// rank's block of the whole grid's extent: its owned rows and the next rank's
/// first row, so that neighbouring blocks share their boundary points, and
/// up to `ghostLevels` rows beyond it on each side another rank owns (VTK's
/// ghost levels of a structured piece: at most the window's ghost rows but
/// the shared one; flagged DUPLICATEPOINT and DUPLICATECELL in vtkGhostType).
template <int D>
void toImage(ReconstructionResult<D>& result, double z, int ghostLevels, vtkImageData* image);

/// The most ghost levels a distributed image can carry: the window's ghost
/// rows but the one the blocks share (SlabPolicy.h).
constexpr int ImageGhostLevelsAvailable = static_cast<int>(SlabGhostRows) - 1;

/// Per-run summary as field data of the output (the image, or the tiled
/// reconstruction's hyper tree grid): CloudSpacing (h_P), the cleaning
/// counts, CellSizeFactor and OutsideThresholdFactor used, FitsCloud (1 or 0), Pieces (the
/// result's, InsideComponents.h) and CloudComponents (the cloud's at 4 local spacings), AutomaticChoices,
/// Recoveries and Warnings (strings: the automatic choices, the recoveries, and
/// what the result does not fit with the option that may help; Reconstruction.h), and one
/// tuple per run in RunGridDimensions (3 components), RunIterations,
/// RunEnergy (E_2), RunCloudError (Err_P), RunFarPoints (fraction of the points
/// more than one cell of run 1 from the surface), RunMisfitPoints (... more than two
/// of the run's cells and than h_P), RunSeconds, RunGhostRows (the
/// slabs' ghost rows at the run's end; 0 on one rank), RunFarFeet, RunMergedNodes
/// (single-node specks merged, levelset/IsolatedNodes.h), RunPointsHeld (the most points a
/// rank's run read, RunFigures::PointsHeld), MissedPlaces (where the last run's
/// surface misses points, a tuple of 11 per place: Points, Nearby, Centre, Lower, Upper); with the
/// octree storage also RunStoredNodes, RunUniformNodes, RunLeaves and
/// RunLargestRankLeaves (ReconstructionSummary.h).
void runSummary(const ReconstructionSummary& summary, vtkDataObject* image);

/// The distributed run's traffic as field data of the image: Ranks, and this
/// rank's RankBytesSent (point to point: the ghost-row exchanges),
/// RankCollectiveBytes (its payload of the collectives times the ranks it
/// reached) and RankCollectives (reductions, agreements, gathers), with each
/// run's share in RunRankBytesSent, RunRankCollectiveBytes and
/// RunRankCollectives, one value a run, and the plan's on the shares in
/// PlanRankBytesSent, PlanRankCollectiveBytes and PlanRankCollectives (CommTraffic.h).
void communicationSummary(const ReconstructionSummary& summary, vtkDataObject* image);

/// Zero level set of the image's SignedDistance: triangles (3D, flying edges)
/// or line segments (2D), coincident vertices merged; ghost rows (toImage())
/// left out.
void zeroLevelSet(vtkImageData* image, vtkPolyData* surface);

/// Per-vertex data for users (beyond the thesis): "DistanceToCloud", the
/// distance from every surface vertex to its nearest cloud point (large where
/// the surface spans a hole of the sampling: threshold it to trim), and every
/// point array of the cloud (colours, normals, intensities) copied from that
/// nearest point, under its own name ("Cloud" + name when the surface already
/// has one, e.g. CloudNormals).
void transferCloudAttributes(vtkPointSet* cloud, vtkPolyData* surface);

/// The convergence history: Run, Iteration, Energy (E_2), Change (eps_1),
/// CloudError (Err_P), BandSize, Seconds; a tiled history (the octree) also
/// StoredNodes, Leaves (the octree's, over every rank), LargestRankLeaves (the
/// most one rank owns) and UniformNodes (the uniform grid at the same cell).
/// Run 1 is uniform: its leaves are its grid's nodes.
void historyTable(const std::vector<IterationRecord>& history, vtkTable* table);

extern template void toImage(ReconstructionResult<2>&, double, int, vtkImageData*);
extern template void toImage(ReconstructionResult<3>&, double, int, vtkImageData*);

} // namespace vtkbridge
} // namespace sltk

#endif
