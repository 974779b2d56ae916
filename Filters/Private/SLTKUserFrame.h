// SPDX-License-Identifier: BSD-3-Clause
#ifndef SLTKUserFrame_h
#define SLTKUserFrame_h
/// \file SLTKUserFrame.h
/// The reconstruction's outputs, computed in the cloud's local frame
/// (sltk/cloud/LocalFrame.h), put back in the user's coordinates.

#include <array>

class vtkDataObject;
class vtkPolyData;

namespace sltk
{
namespace vtkbridge
{

/// Adds `shift` to the coordinates of the outputs: the image's origin or the hyper
/// tree grid's coordinates (`field`), and the surface's points, which become doubles
/// (a float resolves 1 at 1e7). Nothing changes when the shift is zero.
void toUserFrame(const std::array<double, 3>& shift, vtkDataObject* field, vtkPolyData* surface);

} // namespace vtkbridge
} // namespace sltk

#endif
