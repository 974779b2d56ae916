// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SLTKMergePoints.h
/// The merge of a contour's coincident vertices: flying edges puts a vertex
/// on every edge that meets a node where phi is exactly 0, all at that node,
/// and the pieces of a distributed surface share their boundary vertices.
/// vtkCleanPolyData (tolerance 0, no conversions) gives the result every
/// front end writes, but it inserts one point at a time into a locator
/// (1.5 us a point: 0.45 s of the bunny's 310,563 vertices, on one thread);
/// this is the same result from a hash of the exact coordinates and one pass
/// over the cells (Documentation/Profile.md, "The contour's merge").

class vtkPolyData;

namespace sltk
{
namespace vtkbridge
{

/// vtkCleanPolyData's output (SetTolerance(0), ConvertLinesToPointsOff,
/// ConvertPolysToLinesOff, ConvertStripsToPolysOff) for `input` into
/// `output`: points with equal coordinates become one, numbered in the order
/// the lines, then the polygons, first use them, each taking the point data
/// of its first use (as VTK 9.2's vtkCleanPolyData, ParaView 5.11's, does:
/// Filters.ZeroLevelSet compares the two); repeated consecutive points of a
/// cell are dropped, and the lines left with fewer than 2 points and the
/// polygons with fewer than 3. Returns false when it left the input to
/// vtkCleanPolyData itself: vertices, strips, cell data, ghost points, global
/// ids, a line of one point or a polygon of fewer than three (which
/// vtkCleanPolyData keeps as a vertex or a line), or a coordinate that is not finite.
bool mergeCoincidentPoints(vtkPolyData* input, vtkPolyData* output);

} // namespace vtkbridge
} // namespace sltk
