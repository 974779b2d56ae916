// SPDX-License-Identifier: BSD-3-Clause
#include "GatherSurface.h"

#include "SLTKMergePoints.h"

#include <vtkAppendPolyData.h>
#include <vtkDataObject.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <vector>

namespace sltkcli
{

vtkSmartPointer<vtkPolyData> gatherSurface(vtkPolyData* piece, vtkMultiProcessController* controller)
{
  vtkSmartPointer<vtkPolyData> mine = piece;
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return mine;
  }
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->Gather(piece, pieces, 0);
  if (controller->GetLocalProcessId() != 0)
  {
    return mine;
  }
  vtkNew<vtkAppendPolyData> append;
  for (const auto& object : pieces)
  {
    if (auto* p = vtkPolyData::SafeDownCast(object))
    {
      append->AddInputData(p);
    }
  }
  append->Update();
  auto joined = vtkSmartPointer<vtkPolyData>::New();
  sltk::vtkbridge::mergeCoincidentPoints(
    append->GetOutput(), joined); // the blocks' shared boundary points coincide exactly
  return joined;
}

} // namespace sltkcli
