// SPDX-License-Identifier: BSD-3-Clause
#include "ReadPointCloud.h"

#include "FileNames.h"
#include "ReadVtkFile.h"

#include <vtkDataSetReader.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sltkcli
{

namespace
{
sltk::Status readText(const std::string& path, vtkSmartPointer<vtkPointSet>& cloud)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::ifstream in(path);
  std::string line;
  long long lineNumber = 0;
  bool headerSeen = false;
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (line.find('\0') != std::string::npos)
    {
      return sltk::Status::ioError(path + ":" + std::to_string(lineNumber) +
        ": binary data in a text point cloud: give a text file of x y z lines (or a .ply/.vtp)");
    }
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
      if (*end && !std::isspace(static_cast<unsigned char>(*end)))
      {
        const std::string token(static_cast<const char*>(p + std::strspn(p, " \t")),
          static_cast<const char*>(end + std::strcspn(end, " \t")));
        const bool printable = token.size() <= 40 &&
          std::all_of(token.begin(), token.end(), [](unsigned char c) { return std::isprint(c) != 0; });
        return sltk::Status::ioError(path + ":" + std::to_string(lineNumber) +
          (printable ? ": '" + token + "' is not a number"
                     : ": binary data in a text point cloud: give a text file of x y z lines (or a .ply/.vtp)"));
      }
      p = end;
    }
    if (got == 0 && points->GetNumberOfPoints() == 0 && !headerSeen)
    {
      headerSeen = true;
      continue; // one header line such as "x,y,z"
    }
    if (got < 3)
    {
      return sltk::Status::ioError(path + ":" + std::to_string(lineNumber) +
        ": expected three coordinates per line (x y z), got " + std::to_string(got));
    }
    points->InsertNextPoint(x.data());
  }
  if (in.bad())
  {
    return sltk::Status::ioError("read error in " + path);
  }
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

sltk::Status readPointCloud(const std::string& path, vtkSmartPointer<vtkPointSet>& cloud)
{
  cloud = nullptr;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
  {
    return sltk::Status::ioError("'" + path + "' is a folder: give a point-cloud file");
  }
  std::ifstream probe(path, std::ios::binary);
  if (!probe)
  {
    return sltk::Status::ioError("cannot open '" + path + "': check the path and the permissions");
  }
  probe.seekg(0, std::ios::end);
  if (probe.tellg() == 0) // in our words, before a reader's ("Premature EOF reading first line")
  {
    return sltk::Status::ioError("'" + path + "' is empty (0 bytes): it holds no points");
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
  return sltk::Status::ioError(
    "unsupported file type '." + ext + "' of " + path + ": use .ply .xyz .txt .csv .pts .obj .vtp .vtu or .vtk");
}

} // namespace sltkcli
