// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReadPointCloud.h
/// Reads a point cloud file into a vtkPointSet that the filters take as it is
/// (one copy of the points), choosing the reader by the file's extension:
/// .ply .obj .vtp .vtu .vtk through VTK readers, .xyz .txt .csv .pts through the
/// filters' text parser, the one of vtkSLPointCloudReader (Filters/Private/SLTKTextCloud.h:
/// first three numbers of each line; extra columns such as normals are ignored;
/// comment and header lines skipped). Every file first passes checkCloudFile
/// (folder, cannot open, 0 bytes).

#include "sltk/core/Status.h"

#include <vtkPointSet.h>
#include <vtkSmartPointer.h>

#include <string>

namespace sltkcli
{

sltk::Status readPointCloud(const std::string& path, vtkSmartPointer<vtkPointSet>& cloud);

/// Whether `extension` (extensionOf's, FileNames.h) names a text cloud: xyz, txt, csv or pts.
bool isTextCloudExtension(const std::string& extension);

} // namespace sltkcli
