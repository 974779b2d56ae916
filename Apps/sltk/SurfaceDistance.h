// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SurfaceDistance.h
/// Distances between a reconstructed surface and a reference mesh, for
/// `sltk reconstruct --reference`: each mesh's vertices are projected on the
/// other mesh's triangles (exact point-to-triangle distance).
///   Chamfer   = (mean_{a in A} d(a, B) + mean_{b in B} d(b, A)) / 2
///   Hausdorff = max(max_{a in A} d(a, B), max_{b in B} d(b, A))

#include "sltk/core/Status.h"

#include <string>

class vtkPolyData;

namespace sltkcli
{

struct SurfaceDistances
{
  double Chamfer = 0.0;
  double Hausdorff = 0.0;
  double MeanToReference = 0.0;   ///< mean_{a in result} d(a, reference)
  double MeanFromReference = 0.0; ///< mean_{b in reference} d(b, result)
};

/// Reads a reference mesh (.ply .obj .stl .vtp .vtk .off) with triangles.
sltk::Status readMesh(const std::string& path, vtkPolyData* mesh);

sltk::Status surfaceDistances(vtkPolyData* result, vtkPolyData* reference, SurfaceDistances& out);

} // namespace sltkcli
