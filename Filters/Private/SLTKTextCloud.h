// SPDX-License-Identifier: BSD-3-Clause
#ifndef SLTKTextCloud_h
#define SLTKTextCloud_h
/// \file SLTKTextCloud.h
/// The one reading of text point clouds (.xyz .txt .csv .pts), shared by
/// vtkSLPointCloudReader (ParaView) and the CLI (Apps/sltk/ReadPointCloud.cxx):
/// both accept the same files and refuse the others with the same messages.
/// Never wrapped or installed; no pipeline here, the caller makes its data set.

#include "sltk/core/Status.h"

#include "vtkSmartPointer.h"

#include <string>

class vtkPoints;

namespace sltk
{
namespace vtkbridge
{

/// The checks of any cloud file before a reader opens it, in this order: a
/// folder ("'<path>' is a folder: ..."), a file that cannot be opened
/// ("cannot open '<path>': ..."), an empty file ("'<path>' is empty (0 bytes): ...").
Status checkCloudFile(const std::string& path);

/// The points of a text cloud, in double: on each line the first three numbers,
/// separated by spaces, tabs, commas or semicolons (further columns, such as
/// normals, are ignored). Blank lines and lines starting with '#' or '/' are
/// skipped, and so is one header line (no number) before the first point. A
/// first line holding one whole number is a count (Leica .pts): the file must
/// then hold that many points ("its first line announces N points..."). A
/// NUL byte, a token that is not a number among the first three, or fewer than
/// three numbers fails with "<path>:<line>: ..."; `points` is set only on
/// success (never a part of the cloud). A file of comments has no points and is
/// read. Run checkCloudFile first: this one does not look for folders or empty files.
Status readTextCloud(const std::string& path, vtkSmartPointer<vtkPoints>& points);

} // namespace vtkbridge
} // namespace sltk

#endif
