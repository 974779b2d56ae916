// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKBridge.h"

#include "sltk/recon/OptionRanges.h"

#include <sstream>

#include "vtkAlgorithm.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

namespace sltk
{
namespace vtkbridge
{

Status toCloud(vtkPointSet* input, PointCloud<3>& cloud)
{
  cloud.Points.clear();
  if (!input)
  {
    return Status::invalidArgument("no input: connect a point set (vtkPolyData, vtkUnstructuredGrid, ...)");
  }
  vtkPoints* points = input->GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  cloud.Points.resize(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, cloud.Points[static_cast<size_t>(i)].data());
  }
  return Status::ok();
}

vtkSmartPointer<vtkPolyData> pointsOf(const PointCloud<3>& cloud)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(cloud.size()));
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(cloud.size()); ++i)
  {
    points->SetPoint(i, cloud.Points[static_cast<size_t>(i)].data());
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  return poly;
}

Status toValidCloud(vtkPointSet* input, PointCloud<3>& cloud)
{
  SLTK_RETURN_IF_ERROR(toCloud(input, cloud));
  return validateCloud(cloud);
}

Status checkPropertyRanges(std::initializer_list<PropertyRange> ranges)
{
  for (const PropertyRange& r : ranges)
  {
    if (!(r.Value >= r.Low && r.Value <= r.High) && !(r.ZeroIsAutomatic && r.Value == 0.0))
    {
      std::ostringstream m;
      m << r.Name << " = " << r.Value << " is outside its range [" << r.Low << ", " << r.High << "]: set a value in it"
        << (r.ZeroIsAutomatic ? ", or 0 for automatic" : "");
      return Status::invalidArgument(m.str());
    }
  }
  return Status::ok();
}

Status checkOptionRanges(std::initializer_list<PropertyValue> values)
{
  for (const PropertyValue& v : values)
  {
    const OptionRange* range = findOptionRange(v.Name);
    SLTK_RETURN_IF_ERROR(range ? checkOptionRange(*range, v.Value, v.Name)
                               : Status::invalidArgument(std::string("the property ") + v.Name +
                                   " has no range in Core's table (OptionRanges.h): a defect, please report it"));
  }
  return Status::ok();
}

void AlgorithmInterrupter::start(const std::string& phase)
{
  this->Algorithm->SetProgressText(phase.c_str());
  this->Algorithm->UpdateProgress(0.0);
}

bool AlgorithmInterrupter::wasInterrupted(double fraction)
{
  if (fraction >= 0.0)
  {
    this->Algorithm->UpdateProgress(fraction);
  }
  return this->Algorithm->GetAbortExecute() != 0;
}

void VTKLogger::log(LogLevel level, const std::string& message)
{
  switch (level)
  {
    case LogLevel::Error:
      vtkLogF(ERROR, "%s", message.c_str());
      break;
    case LogLevel::Warning:
      vtkLogF(WARNING, "%s", message.c_str());
      break;
    case LogLevel::Info:
      vtkLogF(INFO, "%s", message.c_str());
      break;
    case LogLevel::Debug:
      vtkLogF(TRACE, "%s", message.c_str());
      break;
  }
}

} // namespace vtkbridge
} // namespace sltk
