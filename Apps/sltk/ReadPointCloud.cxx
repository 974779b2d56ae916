// SPDX-License-Identifier: BSD-3-Clause
#include "ReadPointCloud.h"

#include "FileNames.h"
#include "ReadVtkFile.h"
#include "SLTKTextCloud.h"

#include <vtkDataSetReader.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <string>

namespace sltkcli
{

namespace
{
/// The text formats through the filters' reader of them (SLTKTextCloud.h),
/// the one that vtkSLPointCloudReader runs in ParaView.
sltk::Status readText(const std::string& path, vtkSmartPointer<vtkPointSet>& cloud)
{
  vtkSmartPointer<vtkPoints> points;
  SLTK_RETURN_IF_ERROR(sltk::vtkbridge::readTextCloud(path, points));
  cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  return sltk::Status::ok();
}

template <class Reader>
sltk::Status readWith(const std::string& path, vtkSmartPointer<vtkPointSet>& cloud)
{
  vtkSmartPointer<vtkDataObject> object;
  SLTK_RETURN_IF_ERROR(readVtkFile<Reader>(path, object));
  auto* data = vtkPointSet::SafeDownCast(object);
  if (!data || !data->GetPoints())
  {
    return sltk::Status::ioError("could not read points from " + path + " (is it a valid file of its type?)");
  }
  cloud = data;
  return sltk::Status::ok();
}
} // namespace

bool isTextCloudExtension(const std::string& extension)
{
  return extension == "xyz" || extension == "txt" || extension == "csv" || extension == "pts";
}

sltk::Status readPointCloud(const std::string& path, vtkSmartPointer<vtkPointSet>& cloud)
{
  cloud = nullptr;
  SLTK_RETURN_IF_ERROR(sltk::vtkbridge::checkCloudFile(path));
  const std::string ext = extensionOf(path);
  if (isTextCloudExtension(ext))
  {
    return readText(path, cloud);
  }
  if (ext == "ply")
  {
    return readWith<vtkPLYReader>(path, cloud);
  }
  if (ext == "obj")
  {
    return readWith<vtkOBJReader>(path, cloud);
  }
  if (ext == "vtp")
  {
    return readWith<vtkXMLPolyDataReader>(path, cloud);
  }
  if (ext == "vtu")
  {
    return readWith<vtkXMLUnstructuredGridReader>(path, cloud);
  }
  if (ext == "vtk")
  {
    return readWith<vtkDataSetReader>(path, cloud);
  }
  return sltk::Status::ioError(
    "unsupported file type '." + ext + "' of " + path + ": use .ply .xyz .txt .csv .pts .obj .vtp .vtu or .vtk");
}

} // namespace sltkcli
