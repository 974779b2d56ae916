// SPDX-License-Identifier: BSD-3-Clause
#include "ReadPointCloud.h"

#include <vtkDataSetReader.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sltkcli
{

namespace
{
std::string extensionOf(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos)
  {
    return "";
  }
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

sltk::Status readText(const std::string& path, sltk::PointCloud<3>& cloud)
{
  std::ifstream in(path);
  std::string line;
  long long lineNumber = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::replace(line.begin(), line.end(), ';', ' ');
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#' || line[first] == '/')
    {
      continue;
    }
    const char* p = line.c_str();
    char* end = nullptr;
    std::array<double, 3> x{};
    int got = 0;
    for (; got < 3; ++got)
    {
      x[got] = std::strtod(p, &end);
      if (end == p)
      {
        break;
      }
      p = end;
    }
    if (got == 0 && cloud.Points.empty())
    {
      continue; // a header line such as "x,y,z"
    }
    if (got < 3)
    {
      return sltk::Status::ioError(path + ":" + std::to_string(lineNumber) +
        ": expected three coordinates per line (x y z), got " + std::to_string(got));
    }
    cloud.Points.push_back(x);
  }
  if (in.bad())
  {
    return sltk::Status::ioError("read error in " + path);
  }
  return sltk::Status::ok();
}

template <class Reader>
sltk::Status readWith(const std::string& path, sltk::PointCloud<3>& cloud)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto* data = vtkPointSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!data || !data->GetPoints())
  {
    return sltk::Status::ioError("could not read points from " + path + " (is it a valid file of its type?)");
  }
  vtkPoints* points = data->GetPoints();
  cloud.Points.resize(static_cast<size_t>(points->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->GetPoint(i, cloud.Points[static_cast<size_t>(i)].data());
  }
  return sltk::Status::ok();
}
} // namespace

sltk::Status readPointCloud(const std::string& path, sltk::PointCloud<3>& cloud)
{
  cloud.Points.clear();
  std::ifstream probe(path, std::ios::binary);
  if (!probe)
  {
    return sltk::Status::ioError("cannot open '" + path + "': check the path and the permissions");
  }
  probe.close();
  const std::string ext = extensionOf(path);
  if (ext == "xyz" || ext == "txt" || ext == "csv" || ext == "pts")
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
  return sltk::Status::ioError("unsupported file type '." + ext + "' of " + path +
    ": use .ply .xyz .txt .csv .pts .obj .vtp .vtu or .vtk");
}

} // namespace sltkcli
