// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKTextCloud.h"

#include "sltk/cloud/TextCloudFile.h"

#include "vtkNew.h"
#include "vtkPoints.h"

#include <cstring>

namespace sltk
{
namespace vtkbridge
{

Status checkCloudFile(const std::string& path)
{
  return sltk::checkCloudFile(path);
}

Status readTextCloud(const std::string& path, vtkSmartPointer<vtkPoints>& points)
{
  points = nullptr;
  CloudShare whole; // one rank's share is the whole file (TextCloudFile.h)
  SLTK_RETURN_IF_ERROR(readTextCloudShare(path, serialCommunicator(), whole));
  vtkNew<vtkPoints> read;
  read->SetDataTypeToDouble();
  read->SetNumberOfPoints(static_cast<vtkIdType>(whole.Points.size()));
  if (!whole.Points.empty())
  {
    std::memcpy(read->GetVoidPointer(0), whole.Points.data(), whole.Points.size() * sizeof(whole.Points[0]));
  }
  points = read.GetPointer();
  return Status::ok();
}

} // namespace vtkbridge
} // namespace sltk
