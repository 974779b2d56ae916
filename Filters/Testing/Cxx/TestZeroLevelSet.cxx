// SPDX-License-Identifier: BSD-3-Clause
// The zero level set of the reconstruction's image (Filters/Private/
// SLTKReconstructionOutput.h): where phi is exactly 0 at nodes, flying edges
// puts a vertex at the node for every edge that meets it, with zero-area
// triangles between them; the output merges them and drops the degenerate
// triangles, so a surface has the same vertices on any rank count (rank 0
// merges the ranks' pieces the same way).
#include "FilterTestCheck.h"
#include "SLTKReconstructionOutput.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
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
} // namespace

int main()
{
  // phi = x + y + z on integer nodes: 0 exactly at the nodes of the plane x + y + z = 0.
  vtkNew<vtkImageData> image;
  image->SetDimensions(9, 9, 9);
  image->SetOrigin(-4.0, -4.0, -4.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  vtkNew<vtkDoubleArray> phi;
  phi->SetName("SignedDistance");
  phi->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    phi->SetValue(i, x[0] + x[1] + x[2]);
  }
  image->GetPointData()->SetScalars(phi);

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
  return sltktest::failures() == 0 ? 0 : 1;
}
