// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SLTKCloudPieces.h
/// The cloud's pieces with their point data, from every rank. When the ranks
/// hold different pieces of the cloud (sltk/cloud/CloudPieces.h), the
/// reconstruction runs on the union of their points; the surface's vertices
/// then take their attributes (transferCloudAttributes) from the nearest
/// point of any piece, so every rank needs the pieces' arrays too.

#include "sltk/exec/Communicator.h"

#include "vtkSmartPointer.h"

#include <set>
#include <string>

class vtkPointSet;
class vtkPolyData;

namespace sltk
{
namespace vtkbridge
{

/// Collective. Every rank's points with their point data, in rank order (a
/// vtkPolyData without cells). Pieces without points add nothing; the arrays
/// kept are those that every piece with points has with the same name, type and
/// components (vtkAppendPolyData's rule: others are dropped, and named in
/// `dropped` when given).
vtkSmartPointer<vtkPolyData> piecesWithPointData(
  vtkPointSet* piece, const Communicator& comm, std::set<std::string>* dropped = nullptr);

} // namespace vtkbridge
} // namespace sltk
