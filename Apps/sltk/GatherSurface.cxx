// SPDX-License-Identifier: BSD-3-Clause
#include "GatherSurface.h"

#include <vtkAppendPolyData.h>
#include <vtkCleanPolyData.h>
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
  vtkNew<vtkCleanPolyData> merge; // the blocks' shared boundary points coincide exactly
  merge->SetInputConnection(append->GetOutputPort());
  merge->SetTolerance(0.0);
  merge->ConvertLinesToPointsOff();
  merge->ConvertPolysToLinesOff();
  merge->ConvertStripsToPolysOff();
  merge->Update();
  vtkSmartPointer<vtkPolyData> joined = merge->GetOutput();
  return joined;
}

} // namespace sltkcli
