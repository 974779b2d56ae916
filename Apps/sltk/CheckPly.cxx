// SPDX-License-Identifier: BSD-3-Clause
#include "CheckPly.h"

#include "sltk/cloud/PlyHeader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace sltkcli
{
namespace
{
using sltk::plyDamaged;
using sltk::PlyElement;
using sltk::PlyProperty;

/// vtkPLYReader asks for these properties by name as numbers (vertex) or as the kind given (face),
/// and stores a list where it asked for a number (or the reverse) through a type it never set: an
/// assertion in vtkPLY::store_item (found by bench/fuzz). A vertex list is never read: refused too.
sltk::Status checkPropertyKind(
  const std::string& path, const std::string& element, const PlyProperty& property, const std::string& where)
{
  const bool list = property.CountSize > 0;
  if (element == "vertex" && list)
  {
    return plyDamaged(path,
      "the vertex property '" + property.Name + "' is a list in " + where +
        ": VTK's PLY reader reads vertex properties as numbers (export the vertices without lists)");
  }
  if (element == "face")
  {
    const std::string& name = property.Name;
    const bool wantsList = name == "vertex_indices" || name == "texcoord";
    const bool wantsNumber = name == "red" || name == "green" || name == "blue" || name == "alpha";
    if ((wantsList && !list) || (wantsNumber && list))
    {
      return plyDamaged(path,
        "the face property '" + name + "' must be " + (wantsList ? "a list" : "a number") +
          " for VTK's PLY reader, in " + where);
    }
  }
  return sltk::Status::ok();
}

/// The header, each property checked for what VTK's reader asks of it.
sltk::Status readHeader(std::istream& in, const std::string& path, sltk::PlyHeader& header)
{
  return sltk::readPlyHeader(in, path, header,
    [&path](const std::string& element, const PlyProperty& property, const std::string& where)
    { return checkPropertyKind(path, element, property, where); });
}

sltk::Status checkVertices(const std::string& path, const std::vector<PlyElement>& elements)
{
  // vtkPLYReader reads the vertex element, then the face element, from the start of the data: an
  // element before them is not skipped but read as vertices (a crash, found by bench/fuzz).
  const bool vertexFirst = !elements.empty() && elements[0].Name == "vertex";
  if (std::none_of(elements.begin(), elements.end(), [](const PlyElement& e) { return e.Name == "vertex"; }))
  {
    return sltk::Status::ioError(path + " has no vertices (no 'vertex' element): it holds no points to reconstruct");
  }
  for (size_t k = 0; k < elements.size(); ++k)
  {
    const std::string& name = elements[k].Name;
    const bool inPlace = name == "vertex" ? k == 0 : name == "face" ? k == 1 && vertexFirst : k >= 1 && vertexFirst;
    if (!inPlace)
    {
      return plyDamaged(path,
        "its element '" + name + "' is out of place: VTK's PLY reader needs the vertex " +
          "element first, then the faces, then any other (export it in that order)");
    }
  }
  for (const PlyElement& element : elements)
  {
    if (element.Name != "vertex")
    {
      continue;
    }
    for (const char* axis : { "x", "y", "z" })
    {
      bool found = false;
      for (const PlyProperty& p : element.Properties)
      {
        found = found || (p.Name == axis && p.CountSize == 0);
      }
      if (!found)
      {
        return plyDamaged(
          path, std::string("its vertices have no scalar '") + axis + "' property (x, y and z are needed)");
      }
    }
    return sltk::Status::ok();
  }
  return plyDamaged(path, "it has no 'vertex' element");
}

std::int64_t vertexCount(const std::vector<PlyElement>& elements)
{
  for (const PlyElement& element : elements)
  {
    if (element.Name == "vertex")
    {
      return element.Count;
    }
  }
  return 0;
}

/// Ok when every face element has the integer list vtkPLYReader reads
/// ('vertex_indices'; without it the reader goes on and reads garbage).
sltk::Status checkIndexLists(const std::string& path, const std::vector<PlyElement>& elements)
{
  for (const PlyElement& element : elements)
  {
    bool hasIndices = false;
    for (const PlyProperty& p : element.Properties)
    {
      if (p.isVertexIndexList() && !p.Integer)
      {
        return plyDamaged(path, "the " + element.Name + " list '" + p.Name + "' does not hold integers");
      }
      hasIndices = hasIndices || p.isVertexIndexList();
    }
    if (element.Name == "face" && element.Count > 0 && !hasIndices)
    {
      return plyDamaged(path, "its faces have no 'vertex_indices' list (the only name VTK's PLY reader reads)");
    }
  }
  return sltk::Status::ok();
}

sltk::Status indexOutOfRange(const std::string& path, const PlyElement& element, std::int64_t item,
  const std::string& index, std::int64_t vertices)
{
  return plyDamaged(path,
    element.Name + " " + std::to_string(item) + " names vertex " + index + ", but there are " +
      std::to_string(vertices) + " vertices");
}

std::string itemText(const PlyElement& element, std::int64_t item)
{
  return std::to_string(item) + " of the " + std::to_string(element.Count) + " " + element.Name + " items";
}

/// Walks the binary data from the current position: every element's items,
/// list counts read, against the file's end.
sltk::Status checkBinary(
  std::istream& in, const std::string& path, bool bigEndian, const std::vector<PlyElement>& elements)
{
  const std::int64_t vertices = vertexCount(elements);
  const std::streamoff start = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  in.seekg(start);
  std::streamoff at = start;
  for (const PlyElement& element : elements)
  {
    bool fixed = true;
    std::streamoff itemBytes = 0;
    for (const PlyProperty& p : element.Properties)
    {
      fixed = fixed && p.CountSize == 0;
      itemBytes += p.Size;
    }
    if (fixed && itemBytes == 0)
    {
      continue;
    }
    if (fixed)
    {
      if (element.Count > 0 && (end - at) / itemBytes < element.Count)
      {
        return plyDamaged(path, "it is truncated: " + itemText(element, (end - at) / itemBytes) + " are there");
      }
      at += itemBytes * element.Count;
      continue;
    }
    for (std::int64_t item = 0; item < element.Count; ++item)
    {
      for (const PlyProperty& p : element.Properties)
      {
        std::streamoff bytes = p.Size;
        if (p.CountSize > 0)
        {
          unsigned char count[4] = { 0, 0, 0, 0 };
          in.seekg(at);
          if (end - at < p.CountSize || !in.read(reinterpret_cast<char*>(count), p.CountSize))
          {
            return plyDamaged(path, "it is truncated: " + itemText(element, item) + " are there");
          }
          at += p.CountSize;
          bytes = static_cast<std::streamoff>(sltk::plyBits(count, p.CountSize, bigEndian)) * p.Size;
        }
        if (end - at < bytes)
        {
          return plyDamaged(path, "it is truncated: " + itemText(element, item) + " are there");
        }
        if (p.isVertexIndexList())
        {
          std::vector<unsigned char> raw(static_cast<size_t>(bytes));
          in.seekg(at);
          in.read(reinterpret_cast<char*>(raw.data()), bytes);
          for (std::streamoff k = 0; k < bytes; k += p.Size)
          {
            std::uint64_t value = sltk::plyBits(raw.data() + k, p.Size, bigEndian);
            std::int64_t index = static_cast<std::int64_t>(value);
            if (p.Signed && p.Size < 8 && (value >> (8 * p.Size - 1)) != 0)
            {
              index = static_cast<std::int64_t>(value) - (std::int64_t(1) << (8 * p.Size)); // sign extension
            }
            if (index < 0 || index >= vertices)
            {
              return indexOutOfRange(path, element, item, std::to_string(index), vertices);
            }
          }
        }
        at += bytes;
      }
    }
  }
  return sltk::Status::ok();
}

/// The words of an ASCII line, split as VTK's PLY parser splits them (blanks).
std::vector<std::string> wordsOf(const std::string& line)
{
  std::vector<std::string> words;
  size_t at = 0;
  while ((at = line.find_first_not_of(" \t\r", at)) != std::string::npos)
  {
    const size_t end = line.find_first_of(" \t\r", at);
    words.push_back(line.substr(at, end == std::string::npos ? std::string::npos : end - at));
    at = end;
  }
  return words;
}

/// A whole word that is a number (what atof/atoi in VTK's parser would read without loss).
bool isNumber(const std::string& word, double& value)
{
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

/// One line per item (no blank line), holding every property's words (a list: its count, then
/// that many), each a whole number: VTK's parser reads a missing word as a null
/// pointer (a crash, found by bench/fuzz) and garbage as 0. Vertex indices are
/// checked against the vertex count.
sltk::Status checkAscii(std::istream& in, const std::string& path, const std::vector<PlyElement>& elements)
{
  const std::int64_t vertices = vertexCount(elements);
  std::string line;
  for (const PlyElement& element : elements)
  {
    for (std::int64_t item = 0; item < element.Count; ++item)
    {
      if (!std::getline(in, line))
      {
        return plyDamaged(path, "it is truncated: " + itemText(element, item) + " are there");
      }
      if (in.eof())
      {
        // VTK's parser takes a last line without a line end for the end of the file, and aborts.
        return plyDamaged(path, "the line of " + element.Name + " " + std::to_string(item) + " has no line end");
      }
      const std::string odd = sltk::plyOddLine(line);
      if (!odd.empty())
      {
        return plyDamaged(path, odd + ", in " + element.Name + " " + std::to_string(item));
      }
      if (line.find_first_not_of(" \t\r") == std::string::npos)
      {
        // VTK's parser takes a blank line as an item without words, then aborts at the end of the file.
        return plyDamaged(path, "a blank line where " + element.Name + " " + std::to_string(item) + " was expected");
      }
      const std::vector<std::string> words = wordsOf(line);
      const std::string what = element.Name + " " + std::to_string(item);
      size_t next = 0;
      double value = 0.0;
      for (const PlyProperty& p : element.Properties)
      {
        if (next >= words.size())
        {
          return plyDamaged(path,
            what + " has only " + std::to_string(words.size()) + " numbers, too few for its properties ('" + line +
              "')");
        }
        if (!isNumber(words[next], value))
        {
          return plyDamaged(path, "'" + words[next] + "' is not a number, in " + what + " ('" + line + "')");
        }
        ++next;
        if (p.CountSize == 0)
        {
          continue;
        }
        if (!(value >= 0.0) || value > static_cast<double>(words.size() - next) || value != std::floor(value))
        {
          return plyDamaged(path, what + " is incomplete: its list count is " + words[next - 1] + " ('" + line + "')");
        }
        for (std::int64_t k = 0, count = static_cast<std::int64_t>(value); k < count; ++k, ++next)
        {
          if (!isNumber(words[next], value))
          {
            return plyDamaged(path, "'" + words[next] + "' is not a number, in " + what + " ('" + line + "')");
          }
          if (p.isVertexIndexList() && !(value >= 0.0 && value < static_cast<double>(vertices)))
          {
            return indexOutOfRange(path, element, item, words[next], vertices);
          }
        }
      }
    }
  }
  return sltk::Status::ok();
}
/// The x, y, z of the binary vertices that follow the header, read in chunks.
sltk::Status binaryCoordinates(std::istream& in, const std::string& path, bool bigEndian, const PlyElement& vertex,
  const int* axis, std::vector<double>& xyz)
{
  std::streamoff itemBytes = 0;
  std::vector<std::streamoff> at;
  for (const PlyProperty& p : vertex.Properties)
  {
    at.push_back(itemBytes);
    itemBytes += p.Size;
  }
  constexpr std::int64_t Chunk = 1 << 16;
  std::vector<unsigned char> raw(static_cast<size_t>(itemBytes * std::min<std::int64_t>(Chunk, vertex.Count)));
  for (std::int64_t first = 0; first < vertex.Count; first += Chunk)
  {
    const std::int64_t n = std::min(Chunk, vertex.Count - first);
    if (!in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(n * itemBytes)))
    {
      return plyDamaged(path, "it is truncated in its vertices");
    }
    for (std::int64_t i = 0; i < n; ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        const PlyProperty& p = vertex.Properties[static_cast<size_t>(axis[a])];
        xyz[static_cast<size_t>(3 * (first + i) + a)] =
          sltk::plyScalar(raw.data() + i * itemBytes + at[static_cast<size_t>(axis[a])], p, bigEndian);
      }
    }
  }
  return sltk::Status::ok();
}
} // namespace

sltk::Status plyCoordinatesInDouble(const std::string& path, std::vector<double>& xyz)
{
  xyz.clear();
  std::ifstream in(path, std::ios::binary);
  sltk::PlyHeader header;
  SLTK_RETURN_IF_ERROR(readHeader(in, path, header));
  const std::string& format = header.Format;
  const std::vector<PlyElement>& elements = header.Elements;
  SLTK_RETURN_IF_ERROR(checkVertices(path, elements)); // the vertex element comes first, with x, y and z
  const PlyElement& vertex = elements[0];
  int axis[3] = { -1, -1, -1 };
  bool wide = false; // the declared type decides, in ASCII too ("property float": the file holds floats)
  for (size_t k = 0; k < vertex.Properties.size(); ++k)
  {
    const PlyProperty& p = vertex.Properties[k];
    for (int a = 0; a < 3; ++a)
    {
      if (axis[a] < 0 && p.Name == std::string(1, static_cast<char>('x' + a)))
      {
        axis[a] = static_cast<int>(k);
        wide = wide || p.widerThanFloat();
      }
    }
  }
  if (!wide)
  {
    return sltk::Status::ok(); // float (or a short integer) declared: the reader's floats are the file's values
  }
  xyz.resize(static_cast<size_t>(3 * vertex.Count));
  if (format != "ascii")
  {
    return binaryCoordinates(in, path, format == "binary_big_endian", vertex, axis, xyz);
  }
  std::string line;
  for (std::int64_t i = 0; i < vertex.Count; ++i)
  {
    std::getline(in, line);
    const std::vector<std::string> words = wordsOf(line);
    for (int a = 0; a < 3; ++a)
    {
      double value = 0.0;
      if (static_cast<size_t>(axis[a]) >= words.size() || !isNumber(words[static_cast<size_t>(axis[a])], value))
      {
        return plyDamaged(path, "vertex " + std::to_string(i) + " has no number for its coordinate " + "xyz"[a]);
      }
      xyz[static_cast<size_t>(3 * i + a)] = value;
    }
  }
  return sltk::Status::ok();
}

sltk::Status checkPlyFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return sltk::Status::ioError("cannot open '" + path + "': check the path and the permissions");
  }
  sltk::PlyHeader header;
  SLTK_RETURN_IF_ERROR(readHeader(in, path, header));
  const std::string& format = header.Format;
  const std::vector<PlyElement>& elements = header.Elements;
  SLTK_RETURN_IF_ERROR(checkVertices(path, elements));
  SLTK_RETURN_IF_ERROR(checkIndexLists(path, elements));
  return format == "ascii" ? checkAscii(in, path, elements)
                           : checkBinary(in, path, format == "binary_big_endian", elements);
}

} // namespace sltkcli
