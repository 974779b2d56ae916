// SPDX-License-Identifier: BSD-3-Clause
#include "CheckPly.h"

#include <cstdint>
#include <fstream>
#include <sstream>
#include <vector>

namespace sltkcli
{
namespace
{
struct PlyProperty
{
  std::string Name;
  int Size = 0;      ///< bytes of a scalar, or of a list's items
  int CountSize = 0; ///< bytes of a list's count; 0 for a scalar
};

struct PlyElement
{
  std::string Name;
  std::int64_t Count = 0;
  std::vector<PlyProperty> Properties;
};

/// Bytes of a PLY scalar type, 0 when unknown.
int typeSize(const std::string& type)
{
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
    return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
    return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
    return 4;
  if (type == "double" || type == "float64")
    return 8;
  return 0;
}

sltk::Status damaged(const std::string& path, const std::string& what)
{
  return sltk::Status::ioError(
    "damaged PLY file '" + path + "': " + what + "; export it again (or convert it, e.g. to .vtp or a text .xyz file)");
}

/// The header; `format` is "ascii", "binary_little_endian" or "binary_big_endian".
sltk::Status readHeader(
  std::istream& in, const std::string& path, std::string& format, std::vector<PlyElement>& elements)
{
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0)
  {
    return damaged(path, "it does not start with the line 'ply'");
  }
  for (int number = 2; std::getline(in, line); ++number)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header")
    {
      return format.empty() ? damaged(path, "its header has no 'format' line") : sltk::Status::ok();
    }
    const std::string where = "header line " + std::to_string(number) + " ('" + line + "')";
    if (keyword == "format")
    {
      words >> format;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
      {
        return damaged(path, "unknown format in " + where);
      }
    }
    else if (keyword == "element")
    {
      PlyElement element;
      if (!(words >> element.Name >> element.Count) || element.Count < 0)
      {
        return damaged(path, "bad element in " + where);
      }
      elements.push_back(element);
    }
    else if (keyword == "property")
    {
      PlyProperty property;
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string countType, itemType;
        words >> countType >> itemType;
        property.CountSize = typeSize(countType);
        property.Size = typeSize(itemType);
        if (property.CountSize == 0 || property.CountSize == 8)
        {
          return damaged(path, "bad list count type in " + where);
        }
      }
      else
      {
        property.Size = typeSize(type);
      }
      if (property.Size == 0 || !(words >> property.Name) || elements.empty())
      {
        return damaged(path, "bad property in " + where);
      }
      elements.back().Properties.push_back(property);
    }
    else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty())
    {
      return damaged(path, "unknown keyword in " + where);
    }
  }
  return damaged(path, "its header has no 'end_header' line");
}

sltk::Status checkVertices(const std::string& path, const std::vector<PlyElement>& elements)
{
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
        return damaged(
          path, std::string("its vertices have no scalar '") + axis + "' property (x, y and z are needed)");
      }
    }
    return sltk::Status::ok();
  }
  return damaged(path, "it has no 'vertex' element");
}

std::uint64_t listCount(const unsigned char* bytes, int size, bool bigEndian)
{
  std::uint64_t value = 0;
  for (int k = 0; k < size; ++k)
  {
    value = (value << 8) | bytes[bigEndian ? k : size - 1 - k];
  }
  return value;
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
        return damaged(path, "it is truncated: " + itemText(element, (end - at) / itemBytes) + " are there");
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
            return damaged(path, "it is truncated: " + itemText(element, item) + " are there");
          }
          at += p.CountSize;
          bytes = static_cast<std::streamoff>(listCount(count, p.CountSize, bigEndian)) * p.Size;
        }
        if (end - at < bytes)
        {
          return damaged(path, "it is truncated: " + itemText(element, item) + " are there");
        }
        at += bytes;
      }
    }
  }
  return sltk::Status::ok();
}

/// One non-empty line per item; vertex lines hold at least the vertex's properties.
sltk::Status checkAscii(std::istream& in, const std::string& path, const std::vector<PlyElement>& elements)
{
  std::string line;
  for (const PlyElement& element : elements)
  {
    for (std::int64_t item = 0; item < element.Count; ++item)
    {
      bool read = false;
      while ((read = static_cast<bool>(std::getline(in, line))) && line.find_first_not_of(" \t\r") == std::string::npos)
      {
      }
      if (!read)
      {
        return damaged(path, "it is truncated: " + itemText(element, item) + " are there");
      }
      if (element.Name == "vertex")
      {
        std::istringstream numbers(line);
        double value = 0.0;
        size_t found = 0;
        while (numbers >> value)
        {
          ++found;
        }
        if (found < element.Properties.size())
        {
          return damaged(path,
            "vertex " + std::to_string(item) + " has " + std::to_string(found) + " numbers, " +
              std::to_string(element.Properties.size()) + " expected ('" + line + "')");
        }
      }
    }
  }
  return sltk::Status::ok();
}
} // namespace

sltk::Status checkPlyFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return sltk::Status::ioError("cannot open '" + path + "': check the path and the permissions");
  }
  std::string format;
  std::vector<PlyElement> elements;
  SLTK_RETURN_IF_ERROR(readHeader(in, path, format, elements));
  SLTK_RETURN_IF_ERROR(checkVertices(path, elements));
  return format == "ascii" ? checkAscii(in, path, elements)
                           : checkBinary(in, path, format == "binary_big_endian", elements);
}

} // namespace sltkcli
