// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SurfacePieces.h
/// Topology of a reconstructed surface for `sltk reconstruct`: the number of
/// connected pieces and the Euler characteristic V - E + F (2 for one closed
/// piece of genus 0; the level set of Algorithm 1 is closed by construction
/// unless it touches the grid boundary).

class vtkPolyData;

namespace sltkcli
{

struct SurfaceTopology
{
  long long Pieces = 0;
  long long Euler = 0;
};

SurfaceTopology surfaceTopology(vtkPolyData* surface);

} // namespace sltkcli
