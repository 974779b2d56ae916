// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PlyHeader.h"

#include <cstring>
#include <sstream>

namespace sltk
{

namespace
{
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

/// Whether a PLY scalar type is an integer type, and a signed one.
void integerKind(const std::string& type, bool& integer, bool& isSigned)
{
  isSigned = type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" || type == "int32";
  integer = isSigned || type == "uchar" || type == "uint8" || type == "ushort" || type == "uint16" || type == "uint" ||
    type == "uint32";
}

} // namespace

Status plyDamaged(const std::string& path, const std::string& what)
{
  return Status::ioError(
    "damaged PLY file '" + path + "': " + what + "; export it again (or convert it, e.g. to .vtp or a text .xyz file)");
}

std::string plyOddLine(const std::string& line)
{
  if (line.size() > 4000)
  {
    return "a line of " + std::to_string(line.size()) + " characters (at most 4000 are read as one line)";
  }
  for (const char c : line)
  {
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\r')
    {
      return c == '\0' ? std::string("binary data (a NUL byte) in a text line")
                       : "a control character (code " + std::to_string(static_cast<int>(c)) + ") in a text line";
    }
  }
  return {};
}

Status readPlyHeader(std::istream& in, const std::string& path, PlyHeader& header, const PlyPropertyCheck& check)
{
  header = PlyHeader();
  std::string& format = header.Format;
  std::vector<PlyElement>& elements = header.Elements;
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0)
  {
    return plyDamaged(path, "it does not start with the line 'ply'");
  }
  for (int number = 2; std::getline(in, line); ++number)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    const std::string odd = plyOddLine(line);
    if (!odd.empty())
    {
      return plyDamaged(path, odd + " at header line " + std::to_string(number));
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header")
    {
      if (!elements.empty() && elements.back().Properties.empty())
      {
        return plyDamaged(path, "the element '" + elements.back().Name + "' has no property");
      }
      header.DataOffset = static_cast<std::int64_t>(in.tellg());
      return format.empty() ? plyDamaged(path, "its header has no 'format' line") : Status::ok();
    }
    const std::string where = "header line " + std::to_string(number) + " ('" + line + "')";
    // VTK's header parser takes "element face 0Jproperty ..." as a face element with no
    // properties and crashes later (found by bench/fuzz): every line must be exactly its words.
    const auto endsHere = [&words] { return (words >> std::ws).eof(); };
    if (keyword == "format")
    {
      if (!format.empty())
      {
        return plyDamaged(path, "a second 'format' line in " + where); // VTK would read the data as the last one says
      }
      std::string version;
      words >> format >> version;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
      {
        return plyDamaged(path, "unknown format in " + where);
      }
      if (version != "1.0" || !endsHere())
      {
        return plyDamaged(path, "bad format line (version 1.0 expected) in " + where);
      }
    }
    else if (keyword == "element")
    {
      PlyElement element;
      std::string count;
      if (!(words >> element.Name >> count) || !endsHere() ||
        count.find_first_not_of("0123456789") != std::string::npos || count.size() > 15)
      {
        return plyDamaged(path, "bad element in " + where);
      }
      element.Count = std::stoll(count);
      if (!elements.empty() && elements.back().Properties.empty())
      {
        return plyDamaged(path, "the element '" + elements.back().Name + "' has no property, before " + where);
      }
      for (const PlyElement& before : elements)
      {
        if (before.Name == element.Name)
        {
          return plyDamaged(path, "the element '" + element.Name + "' is declared twice, again in " + where);
        }
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
        integerKind(itemType, property.Integer, property.Signed);
        if (property.CountSize == 0 || property.CountSize == 8)
        {
          return plyDamaged(path, "bad list count type in " + where);
        }
      }
      else
      {
        property.Size = typeSize(type);
        integerKind(type, property.Integer, property.Signed);
      }
      if (property.Size == 0 || !(words >> property.Name) || !endsHere() || elements.empty())
      {
        return plyDamaged(path, "bad property in " + where);
      }
      for (const PlyProperty& before : elements.back().Properties)
      {
        if (before.Name == property.Name)
        {
          return plyDamaged(path,
            "the property '" + property.Name + "' of the element '" + elements.back().Name +
              "' is declared twice, again in " + where);
        }
      }
      if (check)
      {
        SLTK_RETURN_IF_ERROR(check(elements.back().Name, property, where));
      }
      elements.back().Properties.push_back(property);
    }
    else if (keyword.empty())
    {
      return plyDamaged(
        path, "a blank line in the header, at line " + std::to_string(number)); // VTK reads a word there
    }
    else if (keyword != "comment" && keyword != "obj_info")
    {
      return plyDamaged(path, "unknown keyword in " + where);
    }
  }
  return plyDamaged(path, "its header has no 'end_header' line");
}

std::uint64_t plyBits(const unsigned char* bytes, int size, bool bigEndian)
{
  std::uint64_t value = 0;
  for (int k = 0; k < size; ++k)
  {
    value = (value << 8) | bytes[bigEndian ? k : size - 1 - k];
  }
  return value;
}

double plyScalar(const unsigned char* bytes, const PlyProperty& p, bool bigEndian)
{
  const std::uint64_t value = plyBits(bytes, p.Size, bigEndian); // the bits, whatever the host's order
  if (!p.Integer && p.Size == 4)
  {
    const std::uint32_t bits = static_cast<std::uint32_t>(value);
    float f = 0.0f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  if (!p.Integer)
  {
    double d = 0.0;
    std::memcpy(&d, &value, 8);
    return d;
  }
  if (p.Signed && (value >> (8 * p.Size - 1)) != 0)
  {
    return p.Size < 8 ? static_cast<double>(static_cast<std::int64_t>(value) - (std::int64_t(1) << (8 * p.Size)))
                      : static_cast<double>(static_cast<std::int64_t>(value));
  }
  return static_cast<double>(value);
}

} // namespace sltk
