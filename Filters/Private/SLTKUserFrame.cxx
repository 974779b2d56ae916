// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKUserFrame.h"

#include "sltk/cloud/LocalFrame.h"

#include "vtkDataArray.h"
#include "vtkHyperTreeGrid.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

namespace sltk
{
namespace vtkbridge
{

namespace
{
void shiftValues(vtkDataArray* coordinates, double by)
{
  for (vtkIdType i = 0; coordinates && i < coordinates->GetNumberOfTuples(); ++i)
  {
    coordinates->SetTuple1(i, coordinates->GetTuple1(i) + by);
  }
}
} // namespace

void toUserFrame(const std::array<double, 3>& shift, vtkDataObject* field, vtkPolyData* surface)
{
  if (isZeroShift(shift))
  {
    return;
  }
  if (auto* image = vtkImageData::SafeDownCast(field))
  {
    const double* origin = image->GetOrigin();
    image->SetOrigin(origin[0] + shift[0], origin[1] + shift[1], origin[2] + shift[2]);
  }
  if (auto* grid = vtkHyperTreeGrid::SafeDownCast(field)) // its coordinates are doubles (SLTKTiledGrid.h)
  {
    shiftValues(grid->GetXCoordinates(), shift[0]);
    shiftValues(grid->GetYCoordinates(), shift[1]);
    shiftValues(grid->GetZCoordinates(), shift[2]);
  }
  vtkPoints* local = surface ? surface->GetPoints() : nullptr;
  if (!local)
  {
    return;
  }
  vtkNew<vtkPoints> user;
  user->SetDataTypeToDouble();
  user->SetNumberOfPoints(local->GetNumberOfPoints());
  for (vtkIdType i = 0; i < local->GetNumberOfPoints(); ++i)
  {
    double x[3];
    local->GetPoint(i, x);
    user->SetPoint(i, x[0] + shift[0], x[1] + shift[1], x[2] + shift[2]);
  }
  surface->SetPoints(user);
}

} // namespace vtkbridge
} // namespace sltk
