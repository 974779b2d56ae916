// SPDX-License-Identifier: BSD-3-Clause
#include "SurfacePieces.h"

#include "sltk/core/DisjointSets.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace sltkcli
{
namespace
{
/// Visits every cell of one of the surface's cell arrays as (count, ids).
template <class Visit>
void forEachCell(vtkCellArray* cells, Visit&& visit)
{
  if (!cells)
  {
    return;
  }
  const auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    visit(n, ids);
  }
}

/// The connected pieces of the cells (two cells sharing a point are one piece),
/// as vtkPolyDataConnectivityFilter's "all regions" counts them, by a
/// disjoint-set forest over the points instead of a copy of every region.
long long countPieces(vtkPolyData* surface)
{
  std::vector<vtkIdType> parent = sltk::singletonForest<vtkIdType>(static_cast<size_t>(surface->GetNumberOfPoints()));
  std::vector<char> used(parent.size(), 0);
  const auto join = [&](vtkIdType n, const vtkIdType* ids)
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      used[static_cast<size_t>(ids[k])] = 1;
      sltk::unite(parent, ids[k], ids[0]);
    }
  };
  for (vtkCellArray* cells : { surface->GetVerts(), surface->GetLines(), surface->GetPolys(), surface->GetStrips() })
  {
    forEachCell(cells, join);
  }
  long long pieces = 0;
  for (size_t k = 0; k < parent.size(); ++k)
  {
    pieces += used[k] && parent[k] == static_cast<vtkIdType>(k) ? 1 : 0;
  }
  return pieces;
}

/// The polygons' undirected edges, each counted once: every edge listed at its
/// smaller end (a compressed adjacency), each end's short list sorted.
long long countPolygonEdges(vtkPolyData* surface)
{
  const size_t points = static_cast<size_t>(surface->GetNumberOfPoints());
  std::vector<vtkIdType> first(points + 1, 0);
  const auto eachEdge = [&](auto&& edge)
  {
    forEachCell(surface->GetPolys(),
      [&](vtkIdType n, const vtkIdType* ids)
      {
        for (vtkIdType k = 0; k < n; ++k)
        {
          const vtkIdType a = ids[k], b = ids[(k + 1) % n];
          edge(std::min(a, b), std::max(a, b));
        }
      });
  };
  eachEdge([&](vtkIdType low, vtkIdType) { ++first[static_cast<size_t>(low) + 1]; });
  for (size_t k = 0; k < points; ++k)
  {
    first[k + 1] += first[k];
  }
  std::vector<vtkIdType> other(static_cast<size_t>(first[points]));
  std::vector<vtkIdType> fill(first.begin(), first.end() - 1);
  eachEdge([&](vtkIdType low, vtkIdType high) { other[static_cast<size_t>(fill[static_cast<size_t>(low)]++)] = high; });
  long long edges = 0;
  for (size_t k = 0; k < points; ++k)
  {
    const auto begin = other.begin() + first[k], end = other.begin() + first[k + 1];
    std::sort(begin, end);
    edges += std::unique(begin, end) - begin;
  }
  return edges;
}
} // namespace

SurfaceTopology surfaceTopology(vtkPolyData* surface)
{
  SurfaceTopology t;
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    return t;
  }
  t.Pieces = countPieces(surface);
  t.Euler = static_cast<long long>(surface->GetNumberOfPoints()) - countPolygonEdges(surface) +
    static_cast<long long>(surface->GetNumberOfPolys());
  return t;
}

} // namespace sltkcli
