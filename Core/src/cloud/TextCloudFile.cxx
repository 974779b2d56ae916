// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/TextCloudFile.h"

#include "sltk/exec/FirstError.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>

namespace sltk
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

/// What the lines before a line decide about it: before the first point, one
/// header line and one count line are allowed; after it, every data line is a point.
struct LineRules
{
  bool PointsBefore = false;
  bool HeaderSeen = false;
  long long Announced = -1; ///< the points a leading count line announces
};

/// One line of the file: `isPoint` and its coordinates in `x` when it holds a
/// point; ok and no point for comments, blank lines, the header and the count.
Status readLine(std::string& line, const std::string& path, long long lineNumber, LineRules& rules,
  std::array<double, 3>& x, bool& isPoint)
{
  isPoint = false;
  if (line.find('\0') != std::string::npos)
  {
    return Status::ioError(lineOf(path, lineNumber) + BinaryData);
  }
  std::replace(line.begin(), line.end(), ',', ' ');
  std::replace(line.begin(), line.end(), ';', ' ');
  const auto first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos || line[first] == '#' || line[first] == '/')
  {
    return Status::ok();
  }
  int got = 0;
  SLTK_RETURN_IF_ERROR(readCoordinates(line, path, lineNumber, x, got));
  if (got == 0 && !rules.PointsBefore && !rules.HeaderSeen)
  {
    rules.HeaderSeen = true; // one header line such as "x,y,z"
    return Status::ok();
  }
  if (got == 1 && !rules.PointsBefore && rules.Announced < 0 && isCount(x[0]))
  {
    rules.Announced = static_cast<long long>(x[0]); // a Leica .pts count line
    return Status::ok();
  }
  if (got < 3)
  {
    return Status::ioError(
      lineOf(path, lineNumber) + ": expected three coordinates per line (x y z), got " + std::to_string(got));
  }
  isPoint = rules.PointsBefore = true;
  return Status::ok();
}

/// The lines before the first point, which every rank reads: `origin` becomes
/// the first point's line's offset (the file's size when it has none) and
/// `linesBefore` the lines before it.
Status readPrologue(std::istream& in, const std::string& path, std::int64_t bytes, LineRules& rules,
  std::int64_t& origin, std::int64_t& linesBefore)
{
  std::string line;
  std::int64_t at = 0;
  linesBefore = 0;
  std::array<double, 3> x{};
  bool isPoint = false;
  while (std::getline(in, line))
  {
    SLTK_RETURN_IF_ERROR(readLine(line, path, linesBefore + 1, rules, x, isPoint));
    if (isPoint)
    {
      origin = at;
      return Status::ok();
    }
    at += static_cast<std::int64_t>(line.size()) + 1;
    ++linesBefore;
  }
  origin = bytes;
  return in.bad() ? Status::ioError("read error in " + path) : Status::ok();
}

/// The points of the lines that start in `share`, the first numbered `firstLine`.
Status readShareLines(std::istream& in, const std::string& path, FileShare share, std::int64_t origin,
  std::int64_t firstLine, LineRules rules, std::vector<std::array<double, 3>>& points)
{
  std::int64_t at = firstLineStart(in, share, origin);
  in.clear();
  in.seekg(at);
  std::string line;
  std::array<double, 3> x{};
  bool isPoint = false;
  for (long long lineNumber = firstLine; at < share.End && std::getline(in, line); ++lineNumber)
  {
    at += static_cast<std::int64_t>(line.size()) + 1;
    SLTK_RETURN_IF_ERROR(readLine(line, path, lineNumber, rules, x, isPoint));
    if (isPoint)
    {
      points.push_back(x);
    }
  }
  return in.bad() ? Status::ioError("read error in " + path) : Status::ok();
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

Status readTextCloudShare(const std::string& path, const Communicator& comm, CloudShare& share)
{
  share = CloudShare();
  std::ifstream in(path, std::ios::binary);
  std::int64_t bytes = 0, origin = 0, linesBefore = 0;
  LineRules rules;
  Status status = in ? Status::ok() : cannotOpen(path);
  if (status.isOk())
  {
    in.seekg(0, std::ios::end);
    bytes = static_cast<std::int64_t>(in.tellg());
    in.seekg(0);
    status = readPrologue(in, path, bytes, rules, origin, linesBefore);
  }
  SLTK_RETURN_IF_ERROR(agreeOnFirstError(comm, status));
  // The lines from the first point on, each rank its share; its line numbers follow the earlier shares' lines.
  rules.PointsBefore = true;
  const FileShare mine = shareOf(origin, bytes, comm.rank(), comm.size());
  std::vector<std::int64_t> lines;
  comm.allGatherV(std::vector<std::int64_t>{ countLineStarts(in, mine, origin) }).swap(lines);
  const std::int64_t firstLine =
    linesBefore + 1 + std::accumulate(lines.begin(), lines.begin() + comm.rank(), std::int64_t(0));
  SLTK_RETURN_IF_ERROR(agreeOnFirstError(comm, readShareLines(in, path, mine, origin, firstLine, rules, share.Points)));
  share.Total = comm.allReduce(static_cast<std::int64_t>(share.Points.size()), ReduceOp::Sum);
  if (rules.Announced >= 0 && rules.Announced != share.Total)
  {
    share.Points.clear();
    return Status::ioError(path + ": its first line announces " + std::to_string(rules.Announced) +
      " points, it holds " + std::to_string(share.Total) + ": is the file cut short (or two scans joined)?");
  }
  return Status::ok();
}

} // namespace sltk
