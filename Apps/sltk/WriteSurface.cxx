// SPDX-License-Identifier: BSD-3-Clause
#include "WriteSurface.h"

#include "FileNames.h"

#include "WriteAtomically.h"
#include "XmlDataSettings.h"

#include "sltk/cloud/LocalFrame.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkHyperTreeGrid.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkXMLHyperTreeGridWriter.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <type_traits>

namespace sltkcli
{

namespace
{
template <class Writer>
bool writeWith(vtkDataObject* data, const std::string& path)
{
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  if constexpr (std::is_base_of<vtkXMLWriter, Writer>::value)
  {
    useFastXmlData(writer);
  }
  return writer->Write() == 1;
}

/// True when a float would not hold coordinates within `bounds` to 1e-6 of their extent:
/// the cloud is reconstructed in its local frame then (LocalFrame.h).
bool farFromOrigin(const double bounds[6])
{
  sltk::Box<3> box;
  box.Min = { bounds[0], bounds[2], bounds[4] };
  box.Max = { bounds[1], bounds[3], bounds[5] };
  return !sltk::isZeroShift(sltk::localFrameShift(box));
}

/// Binary little-endian PLY with double vertices: what vtkPLYWriter writes of our
/// surfaces (float normals, the polygons as faces), the coordinates in double.
bool writeDoublePly(vtkPolyData* surface, const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  const vtkIdType vertices = surface->GetNumberOfPoints();
  vtkCellArray* polys = surface->GetPolys();
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  out << "ply\nformat binary_little_endian 1.0\ncomment SLTK: double vertices (survey coordinates)\n"
      << "element vertex " << vertices << "\nproperty double x\nproperty double y\nproperty double z\n"
      << (normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "") << "element face "
      << polys->GetNumberOfCells() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (vtkIdType i = 0; i < vertices; ++i) // x86-64 and aarch64 are little endian
  {
    double x[3];
    surface->GetPoint(i, x);
    out.write(reinterpret_cast<const char*>(x), sizeof(x));
    if (normals)
    {
      const double* n = normals->GetTuple3(i);
      const float normal[3] = { static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]) };
      out.write(reinterpret_cast<const char*>(normal), sizeof(normal));
    }
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    const auto corners = static_cast<std::uint8_t>(count);
    out.write(reinterpret_cast<const char*>(&corners), 1);
    for (vtkIdType k = 0; k < count; ++k)
    {
      const auto id = static_cast<std::int32_t>(ids[k]);
      out.write(reinterpret_cast<const char*>(&id), sizeof(id));
    }
  }
  return static_cast<bool>(out.flush());
}
} // namespace

std::string surfacePrecisionProblem(const std::string& path, const double bounds[6])
{
  if (extensionOf(path) != "stl" || !farFromOrigin(bounds))
  {
    return "";
  }
  std::ostringstream m;
  m.precision(12);
  m << "the cloud lies far from the origin for its size (x " << bounds[0] << " to " << bounds[1] << ", y " << bounds[2]
    << " to " << bounds[3] << ", z " << bounds[4] << " to " << bounds[5]
    << "): STL stores 32-bit floats, which would round its vertices by more than 1e-6 of its extent; write the "
       "surface as .vtp or .ply (double precision), or translate the cloud near the origin";
  return m.str();
}

std::string surfaceFormatProblem(const std::string& path)
{
  const std::string ext = extensionOf(path);
  if (ext == "vtp" || ext == "ply" || ext == "stl")
  {
    return "";
  }
  return "unsupported surface format '." + ext + "' for " + path + ": use .vtp, .ply or .stl";
}

sltk::Status writeSurface(const std::string& path, vtkPolyData* surface)
{
  const std::string ext = extensionOf(path);
  return writeAtomically(path,
    [&](const std::string& temporary)
    {
      if (ext == "ply" && farFromOrigin(surface->GetBounds()))
      {
        return writeDoublePly(surface, temporary);
      }
      if (ext == "ply")
      {
        return writeWith<vtkPLYWriter>(surface, temporary);
      }
      if (ext == "stl")
      {
        return writeWith<vtkSTLWriter>(surface, temporary);
      }
      return writeWith<vtkXMLPolyDataWriter>(surface, temporary);
    });
}

sltk::Status writeImage(const std::string& path, vtkImageData* image)
{
  return writeAtomically(
    path, [&](const std::string& temporary) { return writeWith<vtkXMLImageDataWriter>(image, temporary); });
}

sltk::Status writeHyperTreeGrid(const std::string& path, vtkHyperTreeGrid* grid)
{
  if (!grid)
  {
    return sltk::Status::invalidArgument("no hyper tree grid to write to " + path);
  }
  return writeAtomically(path,
    [&](const std::string& temporary)
    {
      vtkNew<vtkXMLHyperTreeGridWriter> writer;
      writer->SetInputData(grid);
      writer->SetFileName(temporary.c_str());
      writer->SetDataModeToBinary();
      useFastXmlData(writer, false);
      return writer->Write() == 1;
    });
}

} // namespace sltkcli
