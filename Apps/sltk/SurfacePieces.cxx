// SPDX-License-Identifier: BSD-3-Clause
#include "SurfacePieces.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>

#include <algorithm>
#include <utility>
#include <vector>

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
  // Undirected polygon edges, counted once each (sorted pairs: cheaper than vtkExtractEdges).
  std::vector<std::pair<vtkIdType, vtkIdType>> edges;
  const auto polys = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    polys->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % n];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  const auto unique = std::unique(edges.begin(), edges.end()) - edges.begin();
  t.Euler = static_cast<long long>(surface->GetNumberOfPoints()) - static_cast<long long>(unique) +
    static_cast<long long>(surface->GetNumberOfPolys());
  return t;
}

} // namespace sltkcli
