// SPDX-License-Identifier: BSD-3-Clause
#include "WriteSurface.h"

#include "FileNames.h"

#include "WriteAtomically.h"
#include "XmlDataSettings.h"

#include <vtkHyperTreeGrid.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkXMLHyperTreeGridWriter.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

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
} // namespace

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
