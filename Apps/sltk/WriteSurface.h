// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file WriteSurface.h
/// Writes a surface by its file extension: .vtp, .ply, .stl (atomically).

#include "sltk/core/Status.h"

#include <string>

class vtkPolyData;

namespace sltkcli
{

/// Empty when the extension is supported, else a message naming the fix.
std::string surfaceFormatProblem(const std::string& path);

sltk::Status writeSurface(const std::string& path, vtkPolyData* surface);

} // namespace sltkcli
