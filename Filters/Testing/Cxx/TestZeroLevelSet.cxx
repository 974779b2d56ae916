// SPDX-License-Identifier: BSD-3-Clause
// The zero level set of the reconstruction's image (Filters/Private/
// SLTKReconstructionOutput.h): where phi is exactly 0 at nodes, flying edges
// puts a vertex at the node for every edge that meets it, with zero-area
// triangles between them; the output merges them and drops the degenerate
// triangles, so a surface has the same vertices on any rank count (rank 0
// merges the ranks' pieces the same way). The merge (SLTKMergePoints.h) gives
// vtkCleanPolyData's output bit for bit: on triangles and on lines with
// vertices repeated at such nodes, and on two pieces that share their border.
#include "FilterTestCheck.h"
#include "SLTKMergePoints.h"
#include "SLTKReconstructionOutput.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFlyingEdges2D.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>
#include <set>
#include <string>

using sltktest::check;

namespace
{
/// Points sharing their coordinates with an earlier point.
vtkIdType coincidentPoints(vtkPolyData* surface)
{
  std::set<std::array<double, 3>> seen;
  vtkIdType repeated = 0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> x;
    surface->GetPoint(i, x.data());
    repeated += seen.insert(x).second ? 0 : 1;
  }
  return repeated;
}

/// Triangles with two corners at the same coordinates.
vtkIdType degenerateTriangles(vtkPolyData* surface)
{
  vtkIdType degenerate = 0;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  auto polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    std::set<std::array<double, 3>> corners;
    for (vtkIdType k = 0; k < count; ++k)
    {
      std::array<double, 3> x;
      surface->GetPoint(ids[k], x.data());
      corners.insert(x);
    }
    degenerate += static_cast<vtkIdType>(corners.size()) < count ? 1 : 0;
  }
  return degenerate;
}
/// The same values, bit for bit, in two arrays (null: absent).
bool sameArray(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b)
  {
    return !a && !b;
  }
  if (a->GetNumberOfTuples() != b->GetNumberOfTuples() || a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
    a->GetDataType() != b->GetDataType())
  {
    return false;
  }
  for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      if (a->GetComponent(t, c) != b->GetComponent(t, c))
      {
        return false;
      }
    }
  }
  return true;
}

/// mergeCoincidentPoints(input) against vtkCleanPolyData (tolerance 0, no conversions):
/// the points, the lines and polygons (offsets and connectivity) and every point array.
void checkSameAsCleanPolyData(vtkPolyData* input, const std::string& what)
{
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(input);
  clean->SetTolerance(0.0);
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOff();
  clean->ConvertStripsToPolysOff();
  clean->Update();
  vtkPolyData* expected = clean->GetOutput();
  vtkNew<vtkPolyData> merged;
  const bool byHash = sltk::vtkbridge::mergeCoincidentPoints(input, merged);
  check(byHash, what + ": merged by the hash, not left to vtkCleanPolyData");
  bool same = sameArray(merged->GetPoints()->GetData(), expected->GetPoints()->GetData());
  for (auto cells : { &vtkPolyData::GetLines, &vtkPolyData::GetPolys })
  {
    same = same && sameArray((merged->*cells)()->GetOffsetsArray(), (expected->*cells)()->GetOffsetsArray()) &&
      sameArray((merged->*cells)()->GetConnectivityArray(), (expected->*cells)()->GetConnectivityArray());
  }
  vtkPointData* pd = expected->GetPointData();
  same = same && merged->GetPointData()->GetNumberOfArrays() == pd->GetNumberOfArrays();
  for (int a = 0; same && a < pd->GetNumberOfArrays(); ++a)
  {
    same = sameArray(merged->GetPointData()->GetArray(pd->GetArrayName(a)), pd->GetArray(a));
  }
  check(same && expected->GetNumberOfPoints() < input->GetNumberOfPoints(),
    what + ": the merge is vtkCleanPolyData's output (" + std::to_string(input->GetNumberOfPoints()) + " -> " +
      std::to_string(merged->GetNumberOfPoints()) + " points, " + std::to_string(expected->GetNumberOfPoints()) +
      " by vtkCleanPolyData)");
}

/// phi = x + y (+ z), or with `sphere` x^2 + y^2 (+ z^2) - 9, on integer nodes
/// from -4 to 4 (z from `zFirst`, `zNodes` of them): 0 exactly at nodes of a
/// plane (a line) or a sphere (a circle), where flying edges repeats vertices.
/// On the sphere the normals of a repeated vertex differ in their last bits
/// from edge to edge (the gradients interpolated from either end).
vtkSmartPointer<vtkImageData> zerosAtNodes(int dimensions, bool sphere, double zFirst = -4.0, int zNodes = 9)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(9, 9, dimensions == 3 ? zNodes : 1);
  image->SetOrigin(-4.0, -4.0, dimensions == 3 ? zFirst : 0.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  vtkNew<vtkDoubleArray> phi;
  phi->SetName("SignedDistance");
  phi->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    phi->SetValue(i, sphere ? x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 9.0 : x[0] + x[1] + x[2]);
  }
  image->GetPointData()->SetScalars(phi);
  return image;
}

/// The merge on flying edges' output (with normals in 3D) and on two halves of
/// the image contoured apart and appended (the ranks' pieces rank 0 joins).
void checkMergeAgainstVtk()
{
  vtkNew<vtkFlyingEdges3D> triangles;
  triangles->SetInputData(zerosAtNodes(3, true));
  triangles->SetValue(0, 0.0);
  triangles->ComputeNormalsOn();
  triangles->Update();
  checkSameAsCleanPolyData(triangles->GetOutput(), "triangles with vertices repeated at zero nodes");
  vtkNew<vtkFlyingEdges2D> lines;
  lines->SetInputData(zerosAtNodes(2, false));
  lines->SetValue(0, 0.0);
  lines->Update();
  checkSameAsCleanPolyData(lines->GetOutput(), "lines with vertices repeated at zero nodes");
  vtkNew<vtkAppendPolyData> pieces;
  for (const double zFirst : { -4.0, 0.0 }) // the two halves share the plane z = 0
  {
    vtkNew<vtkFlyingEdges3D> contour;
    contour->SetInputData(zerosAtNodes(3, true, zFirst, 5));
    contour->SetValue(0, 0.5); // off the nodes: only the halves' shared border repeats vertices
    contour->ComputeNormalsOn();
    contour->Update();
    vtkNew<vtkPolyData> piece;
    piece->DeepCopy(contour->GetOutput());
    pieces->AddInputData(piece);
  }
  pieces->Update();
  checkSameAsCleanPolyData(pieces->GetOutput(), "two pieces sharing their border");
}
} // namespace

int main()
{
  // phi = x + y + z on integer nodes: 0 exactly at the nodes of the plane x + y + z = 0.
  const vtkSmartPointer<vtkImageData> image = zerosAtNodes(3, false);
  vtkNew<vtkFlyingEdges3D> raw;
  raw->SetInputData(image);
  raw->SetValue(0, 0.0);
  raw->Update();
  check(coincidentPoints(raw->GetOutput()) > 0 && degenerateTriangles(raw->GetOutput()) > 0,
    "the case has what it tests: flying edges repeats the vertices at nodes where phi = 0 (" +
      std::to_string(coincidentPoints(raw->GetOutput())) + " repeated)");

  vtkNew<vtkPolyData> surface;
  sltk::vtkbridge::zeroLevelSet(image, surface);
  check(surface->GetNumberOfPolys() > 0, "the zero level set has triangles");
  check(coincidentPoints(surface) == 0,
    "no two vertices at the same place (" + std::to_string(coincidentPoints(surface)) + " repeated)");
  check(degenerateTriangles(surface) == 0,
    "no degenerate triangles (" + std::to_string(degenerateTriangles(surface)) + ")");
  check(surface->GetPointData()->GetNormals() != nullptr, "the normals are kept");
  checkMergeAgainstVtk();
  return sltktest::failures() == 0 ? 0 : 1;
}
