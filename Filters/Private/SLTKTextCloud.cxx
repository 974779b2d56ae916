// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKTextCloud.h"

#include "vtkNew.h"
#include "vtkPoints.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace sltk
{
namespace vtkbridge
{

namespace
{
const char* const BinaryData = ": binary data in a text point cloud: give a text file of x y z lines (or a .ply/.vtp)";

Status cannotOpen(const std::string& path)
{
  return Status::ioError("cannot open '" + path + "': check the path and the permissions");
}

std::string lineOf(const std::string& path, long long lineNumber)
{
  return path + ":" + std::to_string(lineNumber);
}

/// The first three numbers of a data line (commas and semicolons already
/// blanks) into `x`, `got` of them: fewer at the line's end or at a token that
/// does not start as a number. A number followed by other characters
/// ("0.02abc") fails, quoted when printable, as binary data otherwise.
Status readCoordinates(
  const std::string& line, const std::string& path, long long lineNumber, std::array<double, 3>& x, int& got)
{
  const char* p = line.c_str();
  char* end = nullptr;
  for (got = 0; got < 3; ++got)
  {
    x[got] = std::strtod(p, &end);
    if (end == p)
    {
      break;
    }
    if (*end && !std::isspace(static_cast<unsigned char>(*end)))
    {
      const std::string token(
        static_cast<const char*>(p + std::strspn(p, " \t")), static_cast<const char*>(end + std::strcspn(end, " \t")));
      const bool printable = token.size() <= 40 &&
        std::all_of(token.begin(), token.end(), [](unsigned char c) { return std::isprint(c) != 0; });
      return Status::ioError(lineOf(path, lineNumber) + (printable ? ": '" + token + "' is not a number" : BinaryData));
    }
    p = end;
  }
  return Status::ok();
}

/// A whole number that can count points: the first line of a Leica .pts file.
bool isCount(double v)
{
  return v >= 0.0 && v < 9.0e15 && v == static_cast<double>(static_cast<long long>(v));
}
} // namespace

Status checkCloudFile(const std::string& path)
{
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
  {
    return Status::ioError("'" + path + "' is a folder: give a point-cloud file");
  }
  std::ifstream probe(path, std::ios::binary);
  if (!probe)
  {
    return cannotOpen(path);
  }
  probe.seekg(0, std::ios::end);
  if (probe.tellg() == 0) // in our words, before a reader's ("Premature EOF reading first line")
  {
    return Status::ioError("'" + path + "' is empty (0 bytes): it holds no points");
  }
  return Status::ok();
}

Status readTextCloud(const std::string& path, vtkSmartPointer<vtkPoints>& points)
{
  points = nullptr;
  std::ifstream in(path);
  if (!in)
  {
    return cannotOpen(path);
  }
  vtkNew<vtkPoints> read;
  read->SetDataTypeToDouble();
  std::string line;
  long long lineNumber = 0;
  bool headerSeen = false;
  long long announced = -1; // the points a leading count line announces
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (line.find('\0') != std::string::npos)
    {
      return Status::ioError(lineOf(path, lineNumber) + BinaryData);
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::replace(line.begin(), line.end(), ';', ' ');
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#' || line[first] == '/')
    {
      continue;
    }
    std::array<double, 3> x{};
    int got = 0;
    SLTK_RETURN_IF_ERROR(readCoordinates(line, path, lineNumber, x, got));
    if (got == 0 && read->GetNumberOfPoints() == 0 && !headerSeen)
    {
      headerSeen = true;
      continue; // one header line such as "x,y,z"
    }
    if (got == 1 && read->GetNumberOfPoints() == 0 && announced < 0 && isCount(x[0]))
    {
      announced = static_cast<long long>(x[0]); // a Leica .pts count line
      continue;
    }
    if (got < 3)
    {
      return Status::ioError(
        lineOf(path, lineNumber) + ": expected three coordinates per line (x y z), got " + std::to_string(got));
    }
    read->InsertNextPoint(x.data());
  }
  if (in.bad())
  {
    return Status::ioError("read error in " + path);
  }
  if (announced >= 0 && announced != read->GetNumberOfPoints())
  {
    return Status::ioError(path + ": its first line announces " + std::to_string(announced) + " points, it holds " +
      std::to_string(read->GetNumberOfPoints()) + ": is the file cut short (or two scans joined)?");
  }
  points = read.GetPointer();
  return Status::ok();
}

} // namespace vtkbridge
} // namespace sltk
