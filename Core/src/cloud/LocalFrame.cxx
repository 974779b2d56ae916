// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/LocalFrame.h"

#include <cmath>

namespace sltk
{

std::array<double, 3> localFrameShift(const Box<3>& box)
{
  std::array<double, 3> shift{};
  const double extent = box.largestExtent();
  if (!(extent > 0.0) || !std::isfinite(extent))
  {
    return shift; // validateCloud() names the problem
  }
  const double unit = std::exp2(std::ceil(std::log2(extent))); // a power of two >= the extent
  for (int a = 0; a < 3; ++a)
  {
    const double centre = 0.5 * (box.Min[a] + box.Max[a]);
    if (std::fabs(centre) > LocalFrameDistance * extent)
    {
      shift[a] = std::nearbyint(centre / unit) * unit;
    }
  }
  return shift;
}

bool isZeroShift(const std::array<double, 3>& shift)
{
  return shift[0] == 0.0 && shift[1] == 0.0 && shift[2] == 0.0;
}

void moveToLocalFrame(PointCloud<3>& cloud, const std::array<double, 3>& shift)
{
  if (isZeroShift(shift))
  {
    return;
  }
  for (std::array<double, 3>& p : cloud.Points)
  {
    for (int a = 0; a < 3; ++a)
    {
      p[a] -= shift[a];
    }
  }
}

} // namespace sltk
