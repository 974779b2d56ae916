// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file WriteSurface.h
/// Writes the CLI's VTK outputs atomically: a surface by its file extension
/// (.vtp, .ply, .stl), an image as .vti and a hyper tree grid as .htg.

#include "sltk/core/Status.h"

#include <string>

class vtkHyperTreeGrid;
class vtkImageData;
class vtkPolyData;

namespace sltkcli
{

/// Empty when the extension is supported, else a message naming the fix.
std::string surfaceFormatProblem(const std::string& path);

/// Empty when `path`'s format holds the surface of a cloud with these bounds (xmin,
/// xmax, ymin, ...) to 1e-6 of its extent; for STL (32-bit floats by definition) far
/// from the origin (sltk/cloud/LocalFrame.h), the problem and the formats that work.
std::string surfacePrecisionProblem(const std::string& path, const double bounds[6]);

/// .vtp, .ply or .stl by extension. A surface far from the origin for its size goes to
/// PLY with double vertices (vtkPLYWriter writes floats, which resolve 1 at 1e7).
sltk::Status writeSurface(const std::string& path, vtkPolyData* surface);

/// XML image data (.vti).
sltk::Status writeImage(const std::string& path, vtkImageData* image);

/// XML hyper tree grid (.htg), binary (VTK 9.2's appended mode corrupts hyper
/// tree grids with several cell arrays, Documentation/Toolchain.md).
sltk::Status writeHyperTreeGrid(const std::string& path, vtkHyperTreeGrid* grid);

} // namespace sltkcli
