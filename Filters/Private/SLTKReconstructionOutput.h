// SPDX-License-Identifier: BSD-3-Clause
#ifndef SLTKReconstructionOutput_h
#define SLTKReconstructionOutput_h
/// \file SLTKReconstructionOutput.h
/// Core reconstruction results -> VTK outputs: the image with the signed
/// distance and the distance to the cloud, the zero isosurface/contour, and the
/// convergence history table.

#include "sltk/recon/Reconstruction.h"

class vtkImageData;
class vtkPolyData;
class vtkTable;

namespace sltk
{
namespace vtkbridge
{

/// Copies phi ("SignedDistance", active scalars) and d ("DistanceToCloud") into
/// `image`; a 2D result becomes an image with one z layer at height z.
template <int D>
void toImage(const ReconstructionResult<D>& result, double z, vtkImageData* image);

/// Per-run summary as field data of the image: CloudSpacing (h_P), and one
/// tuple per run in RunGridDimensions (3 components), RunIterations,
/// RunEnergy (E_2), RunCloudError (Err_P), RunSeconds.
template <int D>
void runSummary(const ReconstructionResult<D>& result, vtkImageData* image);

/// Zero level set of the image's SignedDistance: triangles (3D, flying edges)
/// or line segments (2D).
void zeroLevelSet(vtkImageData* image, vtkPolyData* surface);

/// The convergence history: Run, Iteration, Energy (E_2), Change (eps_1),
/// CloudError (Err_P), BandSize, Seconds.
void historyTable(const std::vector<IterationRecord>& history, vtkTable* table);

extern template void toImage(const ReconstructionResult<2>&, double, vtkImageData*);
extern template void toImage(const ReconstructionResult<3>&, double, vtkImageData*);
extern template void runSummary(const ReconstructionResult<2>&, vtkImageData*);
extern template void runSummary(const ReconstructionResult<3>&, vtkImageData*);

} // namespace vtkbridge
} // namespace sltk

#endif
