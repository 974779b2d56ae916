// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReadVtkFile.h
/// The one path by which the CLI reads a file through a VTK reader (clouds and
/// reference meshes): PLY files are checked first (CheckPly.h), and the error a
/// reader reports (its ErrorEvent) becomes the Status instead of a console line
/// followed by an empty or partial data set. A PLY's coordinates stored wider
/// than float are read again in double (vtkPLYReader stores float).

#include "CheckPly.h"
#include "ErrorCollector.h"

#include "sltk/core/Status.h"

#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <string>
#include <vector>

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
  if (Reader::IsTypeOf("vtkPLYReader"))
  {
    // vtkPLYReader stores float: survey coordinates (1e7 with millimetres) stored in double lose
    // their digits, so the coordinates are read again in double where the file holds more.
    std::vector<double> xyz;
    SLTK_RETURN_IF_ERROR(plyCoordinatesInDouble(path, xyz));
    auto* points = vtkPointSet::SafeDownCast(data);
    if (!xyz.empty() && points && points->GetNumberOfPoints() * 3 == static_cast<vtkIdType>(xyz.size()))
    {
      vtkNew<vtkPoints> exact;
      exact->SetDataTypeToDouble();
      exact->SetNumberOfPoints(points->GetNumberOfPoints());
      std::copy(xyz.begin(), xyz.end(), static_cast<double*>(exact->GetVoidPointer(0)));
      points->SetPoints(exact);
    }
  }
  return sltk::Status::ok();
}

} // namespace sltkcli
