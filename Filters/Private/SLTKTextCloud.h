// SPDX-License-Identifier: BSD-3-Clause
#ifndef SLTKTextCloud_h
#define SLTKTextCloud_h
/// \file SLTKTextCloud.h
/// The one reading of text point clouds (.xyz .txt .csv .pts), Core's
/// (sltk/cloud/TextCloudFile.h) on one rank into vtkPoints, shared by
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

/// sltk::checkCloudFile (TextCloudFile.h): a folder, a file that cannot be opened, an empty file.
Status checkCloudFile(const std::string& path);

/// The points of a text cloud, in double, on this process alone: the rules and
/// messages of sltk::readTextCloudShare (TextCloudFile.h) on one rank; `points`
/// is set only on success (never a part of the cloud). Run checkCloudFile first.
Status readTextCloud(const std::string& path, vtkSmartPointer<vtkPoints>& points);

} // namespace vtkbridge
} // namespace sltk

#endif
