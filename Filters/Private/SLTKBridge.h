// SPDX-License-Identifier: BSD-3-Clause
#ifndef SLTKBridge_h
#define SLTKBridge_h
/// \file SLTKBridge.h
/// Core <-> VTK bridge (never installed or wrapped): point sets into Core
/// clouds, Core services onto vtkAlgorithm progress/abort and vtkLogger.

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Interrupter.h"
#include "sltk/exec/Logger.h"

#include "vtkSmartPointer.h"

#include <initializer_list>

class vtkAlgorithm;
class vtkPointSet;
class vtkPolyData;

namespace sltk
{
namespace vtkbridge
{

/// Copies the points of a vtkPointSet (cells are ignored) into a 3D cloud;
/// no points (a rank's empty piece) give an empty cloud. Fails only without
/// an input.
Status toCloud(vtkPointSet* input, PointCloud<3>& cloud);
/// The cloud's points as a vtkPolyData without cells or arrays.
vtkSmartPointer<vtkPolyData> pointsOf(const PointCloud<3>& cloud);

/// toCloud() followed by validateCloud(): the check every point-cloud filter
/// runs before it allocates anything.
Status toValidCloud(vtkPointSet* input, PointCloud<3>& cloud);

/// A filter property and its documented range (the plugin XML's domain).
struct PropertyRange
{
  const char* Name;
  double Value, Low, High;
  bool ZeroIsAutomatic = false; ///< 0 is also accepted (the property's "automatic" value)
};

/// The first property outside its range, refused with its name and range
/// (a value is never clamped); ok when all are inside. For enumerations; the
/// ranges of the other options are Core's (checkOptionRanges).
Status checkPropertyRanges(std::initializer_list<PropertyRange> ranges);

/// A filter property's value.
struct PropertyValue
{
  const char* Name;
  double Value;
};

/// The first property outside its row of Core's table (sltk/recon/OptionRanges.h,
/// which the plugin XML's domains are made from), refused with its name and
/// range; ok when all are inside.
Status checkOptionRanges(std::initializer_list<PropertyValue> values);

/// Progress and abort of a vtkAlgorithm: UpdateProgress + AbortExecute.
class AlgorithmInterrupter final : public Interrupter
{
public:
  explicit AlgorithmInterrupter(vtkAlgorithm* algorithm)
    : Algorithm(algorithm)
  {
  }
  void start(const std::string& phase) override;
  bool wasInterrupted(double fraction) override;

private:
  vtkAlgorithm* Algorithm;
};

/// Forwards Core log messages to vtkLogger.
class VTKLogger final : public Logger
{
public:
  void log(LogLevel level, const std::string& message) override;
};

} // namespace vtkbridge
} // namespace sltk

#endif
