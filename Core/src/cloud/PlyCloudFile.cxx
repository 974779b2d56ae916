// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PlyCloudFile.h"

#include "sltk/exec/FirstError.h"

#include <algorithm>
#include <fstream>
#include <vector>

namespace sltk
{

namespace
{
/// The layout of x, y, z in the vertex element's records; false unless its properties are exactly those three.
bool coordinateLayout(const PlyElement& vertex, PlyVertexLayout& layout)
{
  if (vertex.Name != "vertex" || vertex.Properties.size() != 3)
  {
    return false;
  }
  int offset = 0, found = 0;
  for (const PlyProperty& property : vertex.Properties)
  {
    const int axis = property.Name == "x" ? 0 : property.Name == "y" ? 1 : property.Name == "z" ? 2 : -1;
    if (axis < 0 || (found & (1 << axis)) || property.CountSize > 0)
    {
      return false;
    }
    found |= 1 << axis;
    layout.Offset[axis] = offset;
    layout.Axes[axis] = property;
    offset += property.Size;
  }
  layout.RecordBytes = offset;
  layout.Wide =
    std::any_of(layout.Axes.begin(), layout.Axes.end(), [](const PlyProperty& p) { return p.widerThanFloat(); });
  layout.Vertices = vertex.Count;
  return found == 7;
}

/// The records [share.Begin, share.End) of `in`.
Status readRecords(std::istream& in, const std::string& path, const PlyVertexLayout& layout, FileShare share,
  std::vector<std::array<double, 3>>& points)
{
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
        x[k] = plyScalar(record + layout.Offset[k], layout.Axes[k], layout.BigEndian);
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
  PlyHeader header;
  if (!readPlyHeader(in, "", header).isOk() || header.Format == "ascii" || header.Elements.empty() ||
    !coordinateLayout(header.Elements[0], layout))
  {
    return false;
  }
  layout.BigEndian = header.bigEndian();
  layout.DataOffset = header.DataOffset;
  const auto& elements = header.Elements;
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
