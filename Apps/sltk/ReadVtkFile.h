// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReadVtkFile.h
/// The one path by which the CLI reads a file through a VTK reader (clouds and
/// reference meshes): PLY files are checked first (CheckPly.h), and the error a
/// reader reports (its ErrorEvent) becomes the Status instead of a console line
/// followed by an empty or partial data set.

#include "CheckPly.h"
#include "ErrorCollector.h"

#include "sltk/core/Status.h"

#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <string>

namespace sltkcli
{

template <class Reader>
sltk::Status readVtkFile(const std::string& path, vtkSmartPointer<vtkDataObject>& data)
{
  data = nullptr;
  if (Reader::IsTypeOf("vtkPLYReader"))
  {
    SLTK_RETURN_IF_ERROR(checkPlyFile(path));
  }
  vtkNew<Reader> reader;
  vtkNew<ErrorCollector> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!errors->Message.empty())
  {
    return sltk::Status::ioError("could not read " + path + ": " + errors->Message);
  }
  data = reader->GetOutputDataObject(0);
  return sltk::Status::ok();
}

} // namespace sltkcli
