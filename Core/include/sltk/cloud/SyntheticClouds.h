// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SyntheticClouds.h
/// The synthetic clouds of the thesis's tests (4.5.3): n points evenly spaced
/// on a circle, and an about-uniform (Fibonacci) sampling of a sphere. Used by
/// tests, benchmarks and examples.

#include "sltk/cloud/PointCloud.h"

#include <cmath>

namespace sltk
{

/// n points at angles 2 pi k / n on the circle of radius r centred at c.
inline PointCloud<2> circleCloud(int n, double r = 1.0, std::array<double, 2> c = { 0.0, 0.0 })
{
  constexpr double twoPi = 6.283185307179586;
  PointCloud<2> cloud;
  for (int k = 0; k < n; ++k)
  {
    const double t = twoPi * k / n;
    cloud.Points.push_back({ c[0] + r * std::cos(t), c[1] + r * std::sin(t) });
  }
  return cloud;
}

/// n Fibonacci (golden-angle) points on the sphere of radius r centred at c.
inline PointCloud<3> sphereCloud(int n, double r = 1.0, std::array<double, 3> c = { 0.0, 0.0, 0.0 })
{
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  PointCloud<3> cloud;
  for (int k = 0; k < n; ++k)
  {
    const double z = 1.0 - 2.0 * (k + 0.5) / n;
    const double s = std::sqrt(1.0 - z * z);
    cloud.Points.push_back({ c[0] + r * s * std::cos(golden * k), c[1] + r * s * std::sin(golden * k), c[2] + r * z });
  }
  return cloud;
}

} // namespace sltk
