// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKMergePoints.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <unordered_map>
#include <vector>

namespace sltk
{
namespace vtkbridge
{
namespace
{
/// A point's coordinates as the key of its group: equal coordinates (as ==
/// compares them, so -0 and +0 alike) give one key.
struct Coordinates
{
  std::array<double, 3> X;
  bool operator==(const Coordinates& other) const { return this->X == other.X; }
};

struct HashCoordinates
{
  size_t operator()(const Coordinates& c) const
  {
    size_t h = 0;
    for (double v : c.X)
    {
      const double positive = v + 0.0; // -0 hashes as +0
      std::uint64_t bits = 0;
      std::memcpy(&bits, &positive, sizeof bits);
      h = h * 0x9E3779B97F4A7C15ull ^ std::hash<std::uint64_t>()(bits);
    }
    return h;
  }
};

/// For each point, the first point (in id order) with its coordinates; false
/// (for vtkCleanPolyData) at a coordinate that is not finite (NaN is equal to nothing).
bool coincidenceGroups(vtkPoints* points, std::vector<vtkIdType>& group)
{
  const vtkIdType n = points->GetNumberOfPoints();
  group.resize(static_cast<size_t>(n));
  std::unordered_map<Coordinates, vtkIdType, HashCoordinates> first;
  first.reserve(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    Coordinates c;
    points->GetPoint(i, c.X.data());
    if (!std::isfinite(c.X[0]) || !std::isfinite(c.X[1]) || !std::isfinite(c.X[2]))
    {
      return false;
    }
    group[static_cast<size_t>(i)] = first.emplace(c, i).first->second;
  }
  return true;
}

/// The fewest points a line (2) or a polygon (3) keeps after the merge.
vtkIdType fewestPoints(bool polygons)
{
  return polygons ? 3 : 2;
}

/// Whether every cell has at least fewestPoints(polygons) points:
/// vtkCleanPolyData keeps a shorter one as a vertex or a line, which this
/// merge does not make.
bool noShortCells(vtkCellArray* cells, bool polygons)
{
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
  {
    if (cells->GetCellSize(c) < fewestPoints(polygons))
    {
      return false;
    }
  }
  return true;
}

/// The cells of `cells` with their points renumbered by first use (`number`
/// of each group, `source`: the input point whose data an output point
/// takes, its first use), consecutive repeats dropped (and a polygon's last
/// point when it repeats its first); the cells left with fewestPoints() or more.
vtkSmartPointer<vtkCellArray> renumberCells(vtkCellArray* cells, bool polygons, const std::vector<vtkIdType>& group,
  std::vector<vtkIdType>& number, std::vector<vtkIdType>& source)
{
  auto kept = vtkSmartPointer<vtkCellArray>::New();
  if (polygons)
  {
    kept->AllocateExact(cells->GetNumberOfCells(), cells->GetNumberOfConnectivityIds());
  }
  else
  {
    kept->AllocateEstimate(cells->GetNumberOfCells(), 2);
  }
  const vtkIdType fewest = fewestPoints(polygons);
  std::vector<vtkIdType> ids;
  vtkIdType count = 0;
  const vtkIdType* pts = nullptr;
  for (cells->InitTraversal(); cells->GetNextCell(count, pts);)
  {
    ids.clear();
    for (vtkIdType k = 0; k < count; ++k)
    {
      vtkIdType& id = number[static_cast<size_t>(group[static_cast<size_t>(pts[k])])];
      if (id < 0) // its first use: the point and its data
      {
        id = static_cast<vtkIdType>(source.size());
        source.push_back(pts[k]);
      }
      if (ids.empty() || ids.back() != id)
      {
        ids.push_back(id);
      }
    }
    if (polygons && ids.size() > 2 && ids.front() == ids.back())
    {
      ids.pop_back();
    }
    if (static_cast<vtkIdType>(ids.size()) >= fewest)
    {
      kept->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
  }
  kept->Squeeze();
  return kept;
}

void cleanByVtk(vtkPolyData* input, vtkPolyData* output)
{
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputData(input);
  merge->SetTolerance(0.0);
  merge->ConvertLinesToPointsOff();
  merge->ConvertPolysToLinesOff();
  merge->ConvertStripsToPolysOff();
  merge->Update();
  output->ShallowCopy(merge->GetOutput());
}
} // namespace

bool mergeCoincidentPoints(vtkPolyData* input, vtkPolyData* output)
{
  vtkPoints* points = input->GetPoints();
  std::vector<vtkIdType> group;
  if (!points || input->GetNumberOfPoints() == 0 || input->GetNumberOfVerts() > 0 || input->GetNumberOfStrips() > 0 ||
    input->GetCellData()->GetNumberOfArrays() > 0 || input->HasAnyGhostPoints() ||
    input->GetPointData()->GetGlobalIds() || !noShortCells(input->GetLines(), false) ||
    !noShortCells(input->GetPolys(), true) || !coincidenceGroups(points, group))
  {
    cleanByVtk(input, output);
    return false;
  }
  std::vector<vtkIdType> number(group.size(), -1), source;
  source.reserve(group.size());
  vtkSmartPointer<vtkCellArray> lines, polys;
  if (input->GetNumberOfLines() > 0)
  {
    lines = renumberCells(input->GetLines(), false, group, number, source);
  }
  if (input->GetNumberOfPolys() > 0)
  {
    polys = renumberCells(input->GetPolys(), true, group, number, source);
  }
  vtkNew<vtkPoints> merged;
  merged->SetDataType(points->GetDataType());
  merged->SetNumberOfPoints(static_cast<vtkIdType>(source.size()));
  vtkNew<vtkIdList> from, to;
  from->SetNumberOfIds(static_cast<vtkIdType>(source.size()));
  to->SetNumberOfIds(static_cast<vtkIdType>(source.size()));
  for (vtkIdType k = 0; k < static_cast<vtkIdType>(source.size()); ++k)
  {
    merged->GetData()->SetTuple(k, source[static_cast<size_t>(k)], points->GetData());
    from->SetId(k, source[static_cast<size_t>(k)]);
    to->SetId(k, k);
  }
  vtkNew<vtkPolyData> result;
  result->GetPointData()->CopyAllocate(input->GetPointData(), static_cast<vtkIdType>(source.size()));
  result->GetPointData()->CopyData(input->GetPointData(), from, to);
  result->SetPoints(merged);
  if (lines)
  {
    result->SetLines(lines);
  }
  if (polys)
  {
    result->SetPolys(polys);
  }
  output->ShallowCopy(result);
  return true;
}

} // namespace vtkbridge
} // namespace sltk
