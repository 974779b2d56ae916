// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReadPointCloud.h
/// Reads the points of a file into a Core cloud, choosing the reader by the
/// file's extension: .ply .obj .vtp .vtu .vtk through VTK readers, .xyz .txt
/// .csv .pts through a text parser (first three numbers of each line; extra
/// columns such as normals are ignored; comment and header lines skipped).

#include "sltk/cloud/PointCloud.h"

#include <string>

namespace sltkcli
{

sltk::Status readPointCloud(const std::string& path, sltk::PointCloud<3>& cloud);

} // namespace sltkcli
