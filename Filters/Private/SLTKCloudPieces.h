// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SLTKCloudPieces.h
/// The cloud's pieces with their point data, from every rank. When the ranks
/// hold different pieces of the cloud (sltk/cloud/CloudPieces.h), the
/// reconstruction runs on the union of their points; the surface's vertices
/// then take their attributes (transferCloudAttributes) from the nearest
/// point of any piece, so every rank needs the pieces' arrays too.

#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"

#include <cstdint>

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

/// Collective. The DistanceToCloud array of transferCloudAttributes on every
/// rank's `surface` piece, from the shares of the cloud the ranks hold (`share`,
/// global indices firstId, ...: vtkSLLevelSetReconstruct's CloudPiecesAreShares)
/// without gathering them: the shares go to their owners (PointOwners.h) and
/// every rank's vertices are asked of every owner (nearestOverRanks, first within
/// `radius`), in rounds of at most `round` vertices over all the ranks (each
/// rank's round / P): the queries of a round, 24 bytes each and the same on every
/// rank, bound the memory whatever the ranks. The same values as the nearest
/// point of the whole cloud gives.
void distanceToShares(vtkPointSet* share, std::int64_t firstId, vtkPolyData* surface, double radius,
  const Communicator& comm, const Context& ctx, std::int64_t round = 1 << 15);

} // namespace vtkbridge
} // namespace sltk
