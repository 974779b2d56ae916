// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/LocalFrame.h"

#include <algorithm>
#include <cmath>
#include <sstream>

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

int positionDigits(double largest, double extent)
{
  const double detail = PositionResolution * extent;
  if (!(detail > 0.0) || !std::isfinite(largest) || !std::isfinite(detail))
  {
    return 6;
  }
  const double digits = std::ceil(std::log10(std::max(std::fabs(largest), detail) / detail));
  return static_cast<int>(std::clamp(digits, 6.0, 17.0));
}

std::string formatPosition(const double* p, int dims, double extent)
{
  double largest = 0.0;
  for (int a = 0; a < dims; ++a)
  {
    largest = std::max(largest, std::fabs(p[a]));
  }
  std::ostringstream text;
  text.precision(positionDigits(largest, extent));
  text << "(";
  for (int a = 0; a < dims; ++a)
  {
    text << (a ? ", " : "") << p[a];
  }
  text << ")";
  return text.str();
}

} // namespace sltk
