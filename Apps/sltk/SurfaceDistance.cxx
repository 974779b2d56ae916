// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceDistance.h"

#include "FileNames.h"
#include "ReadVtkFile.h"

#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace sltkcli
{

namespace
{
/// OFF (the format of the scanned data sets' ground-truth meshes): "OFF", counts, vertices, faces.
sltk::Status readOff(const std::string& path, vtkPolyData* mesh)
{
  std::ifstream in(path);
  std::string header;
  in >> header;
  long long nv = 0, nf = 0, ne = 0;
  if (header != "OFF" || !(in >> nv >> nf >> ne) || nv <= 0)
  {
    return sltk::Status::ioError(path + " is not an OFF file with vertices");
  }
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(nv);
  for (long long i = 0; i < nv; ++i)
  {
    double x[3];
    if (!(in >> x[0] >> x[1] >> x[2]))
    {
      return sltk::Status::ioError(path + ": truncated vertex list");
    }
    points->SetPoint(i, x);
  }
  vtkNew<vtkCellArray> polys;
  for (long long f = 0; f < nf; ++f)
  {
    int n = 0;
    in >> n;
    std::vector<vtkIdType> ids(static_cast<size_t>(std::max(n, 0)));
    for (auto& id : ids)
    {
      in >> id;
    }
    if (!in || n < 3)
    {
      return sltk::Status::ioError(path + ": bad face " + std::to_string(f));
    }
    polys->InsertNextCell(n, ids.data());
  }
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return sltk::Status::ok();
}

template <class Reader>
sltk::Status readWith(const std::string& path, vtkPolyData* mesh)
{
  vtkSmartPointer<vtkDataObject> data;
  SLTK_RETURN_IF_ERROR(readVtkFile<Reader>(path, data));
  auto* read = vtkPolyData::SafeDownCast(data);
  if (!read)
  {
    return sltk::Status::ioError("could not read a surface mesh from " + path);
  }
  mesh->ShallowCopy(read);
  return sltk::Status::ok();
}

/// Mean and max over the vertices of `from` of the distance to the triangles of `to`.
void oneWay(vtkPolyData* from, vtkPolyData* to, double& mean, double& maximum)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double sum = 0.0;
  maximum = 0.0;
  const vtkIdType n = from->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3], closest[3], d2 = 0.0;
    vtkIdType cellId = -1;
    int subId = 0;
    from->GetPoint(i, x);
    locator->FindClosestPoint(x, closest, cell, cellId, subId, d2);
    const double d = std::sqrt(d2);
    sum += d;
    maximum = std::max(maximum, d);
  }
  mean = n ? sum / static_cast<double>(n) : 0.0;
}
} // namespace

sltk::Status readMesh(const std::string& path, vtkPolyData* mesh)
{
  if (!std::ifstream(path))
  {
    return sltk::Status::ioError("cannot open reference mesh '" + path + "'");
  }
  const std::string ext = extensionOf(path);
  vtkNew<vtkPolyData> raw;
  sltk::Status status;
  if (ext == "off")
    status = readOff(path, raw);
  else if (ext == "ply")
    status = readWith<vtkPLYReader>(path, raw);
  else if (ext == "obj")
    status = readWith<vtkOBJReader>(path, raw);
  else if (ext == "stl")
    status = readWith<vtkSTLReader>(path, raw);
  else if (ext == "vtp")
    status = readWith<vtkXMLPolyDataReader>(path, raw);
  else if (ext == "vtk")
    status = readWith<vtkPolyDataReader>(path, raw);
  else
    return sltk::Status::ioError("unsupported reference mesh '." + ext + "': use .off .ply .obj .stl .vtp .vtk");
  SLTK_RETURN_IF_ERROR(status);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(raw);
  triangles->Update();
  mesh->ShallowCopy(triangles->GetOutput());
  if (mesh->GetNumberOfPolys() == 0)
  {
    return sltk::Status::ioError("reference mesh '" + path + "' has no faces: give a surface mesh, not points");
  }
  return sltk::Status::ok();
}

sltk::Status surfaceDistances(vtkPolyData* result, vtkPolyData* reference, SurfaceDistances& out)
{
  if (result->GetNumberOfPolys() == 0 || reference->GetNumberOfPolys() == 0)
  {
    return sltk::Status::invalidArgument("surface distances need triangles on both surfaces");
  }
  double maxTo = 0.0, maxFrom = 0.0;
  oneWay(result, reference, out.MeanToReference, maxTo);
  oneWay(reference, result, out.MeanFromReference, maxFrom);
  out.Chamfer = 0.5 * (out.MeanToReference + out.MeanFromReference);
  out.Hausdorff = std::max(maxTo, maxFrom);
  return sltk::Status::ok();
}

} // namespace sltkcli
