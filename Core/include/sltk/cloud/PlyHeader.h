// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PlyHeader.h
/// The header of a PLY file (http://paulbourke.net/dataformats/ply/), read
/// strictly: every line exactly its words, known types and keywords, no
/// element or property declared twice, one format line. One parser for the
/// CLI's checks of what VTK's reader would read (Apps/sltk/CheckPly.h) and for
/// the ranks' reads of binary vertex records (PlyCloudFile.h).

#include "sltk/core/Status.h"

#include <cstdint>
#include <functional>
#include <istream>
#include <string>
#include <vector>

namespace sltk
{

struct PlyProperty
{
  std::string Name;
  int Size = 0;         ///< bytes of a scalar, or of a list's items
  int CountSize = 0;    ///< bytes of a list's count; 0 for a scalar
  bool Integer = false; ///< the (item) type is an integer type
  bool Signed = false;  ///< ... and a signed one
  /// A scalar that float does not hold exactly: double, or a 32-bit integer (the
  /// CLI reads such coordinates again in double, Apps/sltk/ReadVtkFile.h).
  bool widerThanFloat() const { return this->Size == 8 || (this->Integer && this->Size == 4); }
  /// A list of vertex indices (a face's or a strip's).
  bool isVertexIndexList() const { return this->CountSize > 0 && this->Name == "vertex_indices"; }
};

struct PlyElement
{
  std::string Name;
  std::int64_t Count = 0;
  std::vector<PlyProperty> Properties;
};

struct PlyHeader
{
  std::string Format; ///< "ascii", "binary_little_endian" or "binary_big_endian"
  std::vector<PlyElement> Elements;
  std::int64_t DataOffset = 0; ///< the byte after the "end_header" line
  bool bigEndian() const { return this->Format == "binary_big_endian"; }
};

/// A further check of each property as it is declared: `element` its element's
/// name, `where` the header line ("header line N ('...')") for the message.
using PlyPropertyCheck =
  std::function<Status(const std::string& element, const PlyProperty& property, const std::string& where)>;

/// Reads the header from the start of `in` (left after it). Errors are I/O
/// errors that name `path`, the line and the fix (plyDamaged()).
Status readPlyHeader(std::istream& in, const std::string& path, PlyHeader& header, const PlyPropertyCheck& check = {});

/// "damaged PLY file 'path': what; export it again (...)".
Status plyDamaged(const std::string& path, const std::string& what);

/// What in a header or ASCII data line VTK's parser reads differently from its
/// words (found by bench/fuzz): it reads lines with fgets into 4096 bytes (a
/// longer line is cut in two, a NUL ends it) and splits words at spaces, tabs
/// and carriage returns only. Empty when the line is plain.
std::string plyOddLine(const std::string& line);

/// The unsigned integer of `size` bytes in the file's byte order (a list count, or a scalar's bits).
std::uint64_t plyBits(const unsigned char* bytes, int size, bool bigEndian);

/// A binary scalar of property `p` (its item type for a list) as a double: the
/// file's value, exactly.
double plyScalar(const unsigned char* bytes, const PlyProperty& p, bool bigEndian);

} // namespace sltk
