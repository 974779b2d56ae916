// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CheckPly.h
/// What vtkPLYReader does not check before it reads (Documentation/Architecture.md,
/// "Reading files"): VTK 9.2's reader asserts on a truncated ASCII file, crashes
/// on a vertex element without x, y and z, and pads a truncated binary file
/// with copies of its last point, and reads the points a face names without a
/// bounds check (a face index beyond the vertices crashes it; found by
/// bench/fuzz). checkPlyFile reads the header and walks the data (binary:
/// element by element, list counts included, against the file's size; ASCII:
/// one non-empty line per element, as many numbers per vertex line as the
/// vertex has scalar properties), checks every vertex index of a face against
/// the vertex count, and names what is wrong.

#include "sltk/core/Status.h"

#include <string>
#include <vector>

namespace sltkcli
{

/// Ok when `path` is a PLY file that vtkPLYReader can read whole: a "ply" magic
/// line, a known format, a vertex element with scalar x, y and z, and all the
/// data the header announces. Otherwise an I/O error naming the file, the
/// problem and the fix.
sltk::Status checkPlyFile(const std::string& path);

/// The vertices' x, y, z in double (3 per vertex, in order) when vtkPLYReader,
/// which stores float, would lose digits of them: the header declares them
/// double or 32-bit integers (binary or ASCII). Left empty when it declares
/// float (the reader's points are then the file's values). For a file that
/// checkPlyFile accepted.
sltk::Status plyCoordinatesInDouble(const std::string& path, std::vector<double>& xyz);

} // namespace sltkcli
