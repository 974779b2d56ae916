// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file WriteSurface.h
/// Writes the CLI's VTK outputs atomically: a surface by its file extension
/// (.vtp, .ply, .stl) and an image as .vti.

#include "sltk/core/Status.h"

#include <string>

class vtkImageData;
class vtkPolyData;

namespace sltkcli
{

/// Empty when the extension is supported, else a message naming the fix.
std::string surfaceFormatProblem(const std::string& path);

sltk::Status writeSurface(const std::string& path, vtkPolyData* surface);

/// XML image data (.vti).
sltk::Status writeImage(const std::string& path, vtkImageData* image);

} // namespace sltkcli
