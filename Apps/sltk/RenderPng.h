// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file RenderPng.h
/// `sltk reconstruct --png`: a picture of the reconstructed surface (and the
/// cloud as dots), rendered off screen by VTK. ParaView's VTK on Debian draws
/// through X: without a display, use `xvfb-run -a sltk ...`.

#include "sltk/core/Status.h"

#include <string>

class vtkPointSet;
class vtkPolyData;

namespace sltkcli
{

/// "" when `path` ends in .png and an X display can be opened, else the problem and its fix
/// (checked before the reconstruction, so that a long run does not end in this error).
std::string pngProblem(const std::string& path);

/// Renders `surface` (and `cloud`'s points when given) to `path`, atomically.
sltk::Status renderPng(const std::string& path, vtkPolyData* surface, vtkPointSet* cloud);

} // namespace sltkcli
