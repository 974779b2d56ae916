// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/StrayPoints.h"

#include "sltk/cloud/CloudCleaning.h"

#include <sstream>

namespace sltk
{

template <int D>
std::string strayPointAdvice(const PointCloud<D>& cloud, const Context& ctx)
{
  OutlierOptions gross;
  gross.GrossRatio = GrossOutlierRatio;
  PointCloud<D> kept;
  OutlierReport report;
  if (!removeOutliers(cloud, gross, ctx, kept, report).isOk() || report.Removed == 0)
  {
    return {};
  }
  std::ostringstream m;
  m << "the cloud has " << report.Removed << " stray point(s) far from the rest (one is " << report.LargestRatio
    << " times farther from its neighbours than the median point), kept because the automatic cleaning is off: "
    << "remove outliers (sltk reconstruct --remove-outliers; RemoveOutliers in ParaView)";
  return m.str();
}

template std::string strayPointAdvice(const PointCloud<2>&, const Context&);
template std::string strayPointAdvice(const PointCloud<3>&, const Context&);

} // namespace sltk
