// SPDX-License-Identifier: BSD-3-Clause
#include "SurfacePieces.h"

#include <vtkCellArray.h>
#include <vtkExtractEdges.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>

namespace sltkcli
{

SurfaceTopology surfaceTopology(vtkPolyData* surface)
{
  SurfaceTopology t;
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    return t;
  }
  vtkNew<vtkPolyDataConnectivityFilter> connectivity;
  connectivity->SetInputData(surface);
  connectivity->SetExtractionModeToAllRegions();
  connectivity->Update();
  t.Pieces = connectivity->GetNumberOfExtractedRegions();
  vtkNew<vtkExtractEdges> edges;
  edges->SetInputData(surface);
  edges->Update();
  t.Euler = static_cast<long long>(surface->GetNumberOfPoints()) -
    static_cast<long long>(edges->GetOutput()->GetNumberOfLines()) +
    static_cast<long long>(surface->GetNumberOfPolys());
  return t;
}

} // namespace sltkcli
