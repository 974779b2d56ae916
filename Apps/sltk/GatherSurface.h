// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file GatherSurface.h
/// `mpirun -np N sltk reconstruct`: every rank contours its block of the grid
/// (vtkSLLevelSetReconstruct.h), and rank 0 joins the pieces into the one
/// surface it writes and measures. Neighbouring blocks share their boundary
/// points with the same values, so the pieces' vertices there coincide
/// bitwise and are merged exactly (no tolerance): the joined surface is as
/// closed as each piece.

#include <vtkSmartPointer.h>

class vtkMultiProcessController;
class vtkPolyData;

namespace sltkcli
{

/// Rank 0: every rank's `piece` appended, coincident points merged; other
/// ranks (and one rank): `piece`. A collective call on `controller`'s ranks
/// (nullptr or one rank: nothing to gather).
vtkSmartPointer<vtkPolyData> gatherSurface(vtkPolyData* piece, vtkMultiProcessController* controller);

} // namespace sltkcli
