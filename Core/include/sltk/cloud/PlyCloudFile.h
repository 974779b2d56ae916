// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PlyCloudFile.h
/// Binary PLY point clouds read by vertex-record offsets, each rank its share of
/// the records (CloudFileShares.h). Only the PLY files whose records hold the
/// points and nothing else are read so: binary (either byte order), the vertex
/// element first, its properties exactly the scalars x, y and z (any types,
/// any order), and every later element empty. Other PLY files (ASCII, normals,
/// colours, faces) are read whole by the caller's reader (the CLI's vtkPLYReader),
/// which gives the surface their point arrays. The header is read by the
/// parser of the CLI's checks (PlyHeader.h), which run on the file before.

#include "sltk/cloud/CloudFileShares.h"
#include "sltk/cloud/PlyHeader.h"
#include "sltk/core/Status.h"
#include "sltk/exec/Communicator.h"

#include <array>
#include <cstdint>
#include <istream>
#include <string>

namespace sltk
{

/// Where a binary PLY's coordinates are.
struct PlyVertexLayout
{
  std::int64_t DataOffset = 0; ///< the first record's byte (after "end_header\n")
  std::int64_t Vertices = 0;
  std::int64_t RecordBytes = 0;
  std::array<int, 3> Offset{};       ///< x, y and z in a record
  std::array<PlyProperty, 3> Axes{}; ///< their properties (types)
  bool BigEndian = false;
  /// A coordinate is double or a 32-bit integer: the CLI's serial reader keeps such
  /// coordinates in double (Apps/sltk/ReadVtkFile.h), the others in float (vtkPLYReader's).
  bool Wide = false;
};

/// Whether the PLY whose header `in` starts with, of `bytes` bytes, can be read
/// by offsets (the files of this header's rule, holding all their records):
/// then `layout` says where the coordinates are.
bool plyVertexLayout(std::istream& in, std::int64_t bytes, PlyVertexLayout& layout);

/// Collective. This rank's share of the vertex records of the PLY `path` of
/// `layout`, in file order, each coordinate the file's value (exact in double;
/// in float too unless layout.Wide); every rank returns the same status. The
/// caller runs the serial reader's checks of the file first (Apps/sltk/CheckPly.h).
Status readPlyCloudShare(
  const std::string& path, const PlyVertexLayout& layout, const Communicator& comm, CloudShare& share);

} // namespace sltk
