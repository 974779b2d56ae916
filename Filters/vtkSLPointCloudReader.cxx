// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSLPointCloudReader.h"

#include "SLTKGuard.h"
#include "SLTKTextCloud.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <numeric>
#include <string>

vtkStandardNewMacro(vtkSLPointCloudReader);

vtkSLPointCloudReader::vtkSLPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkSLPointCloudReader::~vtkSLPointCloudReader()
{
  this->SetFileName(nullptr);
}

namespace
{
/// One vertex cell per point, in the points' order.
void addVertices(vtkPolyData* cloud)
{
  const vtkIdType n = cloud->GetNumberOfPoints();
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(n + 1);
  std::iota(offsets->GetPointer(0), offsets->GetPointer(0) + n + 1, vtkIdType(0));
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(n);
  std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, vtkIdType(0));
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(offsets, connectivity);
  cloud->SetVerts(vertices);
}
} // namespace

int vtkSLPointCloudReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize(); // a refused file leaves it empty, never a part of the cloud
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("no FileName: give the text point cloud to read (x y z per line)");
    return 0;
  }
  const std::string path = this->FileName;
  // An exception (std::bad_alloc on a huge file) becomes the reader's error (SLTKGuard.h).
  return sltk::vtkbridge::guardedRequest(this,
    [&]
    {
      vtkSmartPointer<vtkPoints> points;
      sltk::Status status = sltk::vtkbridge::checkCloudFile(path);
      if (status.isOk())
      {
        status = sltk::vtkbridge::readTextCloud(path, points);
      }
      if (!status.isOk())
      {
        vtkErrorMacro(<< status.message());
        return 0;
      }
      vtkNew<vtkPolyData> cloud;
      cloud->SetPoints(points);
      addVertices(cloud);
      output->ShallowCopy(cloud);
      if (points->GetNumberOfPoints() == 0)
      {
        vtkWarningMacro(<< "'" << path << "' holds no points (only blank, comment or header lines)");
      }
      return 1;
    });
}

void vtkSLPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
