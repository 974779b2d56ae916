// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PlyCloudFile.h"

#include "sltk/exec/FirstError.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace sltk
{

namespace
{
/// The bytes of a PLY scalar type ('c' int8 ... 'd' double), its letter in `letter`; 0 when unknown.
int plyTypeBytes(const std::string& name, char& letter)
{
  static const struct
  {
    const char* Name;
    const char* Alias;
    char Letter;
    int Bytes;
  } types[] = { { "char", "int8", 'c', 1 }, { "uchar", "uint8", 'C', 1 }, { "short", "int16", 's', 2 },
    { "ushort", "uint16", 'S', 2 }, { "int", "int32", 'i', 4 }, { "uint", "uint32", 'I', 4 },
    { "float", "float32", 'f', 4 }, { "double", "float64", 'd', 8 } };
  for (const auto& t : types)
  {
    if (name == t.Name || name == t.Alias)
    {
      letter = t.Letter;
      return t.Bytes;
    }
  }
  return 0;
}

/// One element of the header: its name, count, and whether its records have one size (no list property).
struct PlyElement
{
  std::string Name;
  std::int64_t Count = 0;
  std::vector<std::string> Properties;
  std::int64_t RecordBytes = 0;
  bool Fixed = true;
};

/// The header's elements and the data's offset; false when `in` holds no binary PLY header.
bool readPlyHeader(std::istream& in, std::vector<PlyElement>& elements, bool& bigEndian, std::int64_t& dataOffset)
{
  std::string line;
  const auto next = [&]
  {
    if (!std::getline(in, line) || line.size() > 4096)
    {
      return false;
    }
    line.erase(line.find_last_not_of(" \t\r") + 1);
    return true;
  };
  if (!next() || line != "ply" || !next())
  {
    return false;
  }
  bigEndian = line.rfind("format binary_big_endian", 0) == 0;
  if (!bigEndian && line.rfind("format binary_little_endian", 0) != 0)
  {
    return false; // ASCII
  }
  for (int lines = 0; lines < 10000 && next(); ++lines)
  {
    std::istringstream words(line);
    std::string keyword, type, name;
    words >> keyword;
    if (keyword == "end_header")
    {
      dataOffset = static_cast<std::int64_t>(in.tellg());
      return !elements.empty();
    }
    if (keyword == "element")
    {
      elements.emplace_back();
      words >> elements.back().Name >> elements.back().Count;
    }
    else if (keyword == "property" && !elements.empty())
    {
      words >> type >> name;
      char letter = 0;
      const int bytes = plyTypeBytes(type, letter);
      elements.back().Fixed = elements.back().Fixed && bytes > 0; // a list, or an unknown type
      elements.back().RecordBytes += bytes;
      elements.back().Properties.push_back(type + " " + name);
    }
  }
  return false;
}

/// The layout of x, y, z in the vertex element's records; false unless its properties are exactly those three.
bool coordinateLayout(const PlyElement& vertex, PlyVertexLayout& layout)
{
  if (vertex.Name != "vertex" || !vertex.Fixed || vertex.Properties.size() != 3)
  {
    return false;
  }
  int offset = 0, found = 0;
  for (const std::string& property : vertex.Properties)
  {
    const std::string type = property.substr(0, property.find(' ')), name = property.substr(property.find(' ') + 1);
    const int axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
    if (axis < 0 || (found & (1 << axis)))
    {
      return false;
    }
    found |= 1 << axis;
    layout.Offset[axis] = offset;
    offset += plyTypeBytes(type, layout.Type[axis]);
  }
  layout.RecordBytes = offset;
  layout.Wide =
    std::any_of(layout.Type.begin(), layout.Type.end(), [](char t) { return t == 'd' || t == 'i' || t == 'I'; });
  layout.Vertices = vertex.Count;
  return found == 7;
}

template <class T>
double valueOf(const unsigned char* bytes)
{
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return static_cast<double>(value);
}

/// One coordinate of a record, the file's value.
double coordinate(const unsigned char* at, char type, bool swap)
{
  unsigned char b[8];
  const int bytes = type == 'd'                   ? 8
    : (type == 'f' || type == 'i' || type == 'I') ? 4
    : (type == 's' || type == 'S')                ? 2
                                                  : 1;
  std::memcpy(b, at, static_cast<size_t>(bytes));
  if (swap)
  {
    std::reverse(b, b + bytes);
  }
  return type == 'c' ? valueOf<std::int8_t>(b)
    : type == 'C'    ? valueOf<std::uint8_t>(b)
    : type == 's'    ? valueOf<std::int16_t>(b)
    : type == 'S'    ? valueOf<std::uint16_t>(b)
    : type == 'i'    ? valueOf<std::int32_t>(b)
    : type == 'I'    ? valueOf<std::uint32_t>(b)
    : type == 'f'    ? valueOf<float>(b)
                     : valueOf<double>(b);
}

bool littleEndianHost()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// The records [share.Begin, share.End) of `in`.
Status readRecords(std::istream& in, const std::string& path, const PlyVertexLayout& layout, FileShare share,
  std::vector<std::array<double, 3>>& points)
{
  const bool swap = layout.BigEndian == littleEndianHost();
  const std::int64_t perBlock = std::max<std::int64_t>(1, (std::int64_t(1) << 20) / layout.RecordBytes);
  std::vector<unsigned char> block(static_cast<size_t>(perBlock * layout.RecordBytes));
  in.seekg(layout.DataOffset + share.Begin * layout.RecordBytes);
  points.reserve(static_cast<size_t>(share.End - share.Begin));
  for (std::int64_t first = share.Begin; first < share.End; first += perBlock)
  {
    const std::int64_t records = std::min(perBlock, share.End - first);
    if (!in.read(reinterpret_cast<char*>(block.data()), records * layout.RecordBytes))
    {
      return Status::ioError("read error in " + path + " (its vertex records end early)");
    }
    for (std::int64_t r = 0; r < records; ++r)
    {
      const unsigned char* record = block.data() + r * layout.RecordBytes;
      std::array<double, 3> x{};
      for (int k = 0; k < 3; ++k)
      {
        x[k] = coordinate(record + layout.Offset[k], layout.Type[k], swap);
      }
      points.push_back(x);
    }
  }
  return Status::ok();
}
} // namespace

bool plyVertexLayout(std::istream& in, std::int64_t bytes, PlyVertexLayout& layout)
{
  layout = PlyVertexLayout();
  std::vector<PlyElement> elements;
  if (!readPlyHeader(in, elements, layout.BigEndian, layout.DataOffset) || !coordinateLayout(elements[0], layout))
  {
    return false;
  }
  const bool laterEmpty =
    std::all_of(elements.begin() + 1, elements.end(), [](const PlyElement& e) { return e.Count == 0; });
  return laterEmpty && layout.Vertices >= 0 && layout.DataOffset + layout.Vertices * layout.RecordBytes <= bytes;
}

Status readPlyCloudShare(
  const std::string& path, const PlyVertexLayout& layout, const Communicator& comm, CloudShare& share)
{
  share = CloudShare();
  std::ifstream in(path, std::ios::binary);
  const Status read = in
    ? readRecords(in, path, layout, shareOf(0, layout.Vertices, comm.rank(), comm.size()), share.Points)
    : Status::ioError("read error in " + path + " (it cannot be opened)");
  const Status agreed = agreeOnFirstError(comm, read);
  share.Total = agreed.isOk() ? layout.Vertices : 0;
  if (!agreed.isOk())
  {
    share.Points.clear();
  }
  return agreed;
}

} // namespace sltk
