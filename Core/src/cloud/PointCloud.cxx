// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PointCloud.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sltk
{

template <int D>
Box<D> boundingBox(const PointCloud<D>& cloud)
{
  Box<D> box;
  box.Min.fill(std::numeric_limits<double>::infinity());
  box.Max.fill(-std::numeric_limits<double>::infinity());
  for (const auto& p : cloud.Points)
  {
    for (int a = 0; a < D; ++a)
    {
      box.Min[a] = std::min(box.Min[a], p[a]);
      box.Max[a] = std::max(box.Max[a], p[a]);
    }
  }
  return box;
}

namespace
{
template <int D>
double distance(const std::array<double, D>& p, const std::array<double, D>& q)
{
  double s = 0.0;
  for (int a = 0; a < D; ++a)
  {
    s += (p[a] - q[a]) * (p[a] - q[a]);
  }
  return std::sqrt(s);
}

/// Largest distance of any point from the line (2D) or plane (3D) through
/// three well-spread points: zero for collinear/coplanar clouds.
double spreadOffLine(const PointCloud<2>& c, size_t i0, size_t i1)
{
  const auto& a = c.Points[i0];
  const auto& b = c.Points[i1];
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len = std::hypot(dx, dy);
  double best = 0.0;
  for (const auto& p : c.Points)
  {
    best = std::max(best, std::fabs((p[0] - a[0]) * dy - (p[1] - a[1]) * dx) / len);
  }
  return best;
}

double spreadOffPlane(const PointCloud<3>& c, size_t i0, size_t i1)
{
  // Third point: farthest from the line (i0, i1).
  const auto& a = c.Points[i0];
  const auto& b = c.Points[i1];
  std::array<double, 3> u{ b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  auto cross = [](const std::array<double, 3>& x, const std::array<double, 3>& y) {
    return std::array<double, 3>{ x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0] };
  };
  auto norm = [](const std::array<double, 3>& x) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); };
  size_t i2 = i0;
  double bestLine = 0.0;
  for (size_t k = 0; k < c.Points.size(); ++k)
  {
    const auto& p = c.Points[k];
    const double d = norm(cross(u, { p[0] - a[0], p[1] - a[1], p[2] - a[2] }));
    if (d > bestLine)
    {
      bestLine = d;
      i2 = k;
    }
  }
  if (bestLine == 0.0)
  {
    return 0.0;
  }
  const auto& q = c.Points[i2];
  auto n = cross(u, { q[0] - a[0], q[1] - a[1], q[2] - a[2] });
  const double nn = norm(n);
  double best = 0.0;
  for (const auto& p : c.Points)
  {
    best = std::max(best, std::fabs(n[0] * (p[0] - a[0]) + n[1] * (p[1] - a[1]) + n[2] * (p[2] - a[2])) / nn);
  }
  return best;
}

double spreadOffFlat(const PointCloud<2>& c, size_t i0, size_t i1)
{
  return spreadOffLine(c, i0, i1);
}
double spreadOffFlat(const PointCloud<3>& c, size_t i0, size_t i1)
{
  return spreadOffPlane(c, i0, i1);
}
} // namespace

template <int D>
Status validateCloud(const PointCloud<D>& cloud)
{
  const std::string dim = std::to_string(D) + "D";
  if (cloud.Points.empty())
  {
    return Status::invalidArgument("the point cloud is empty: give at least " + std::to_string(D + 1) +
      " points that are not all on one " + (D == 2 ? "line" : "plane"));
  }
  for (size_t k = 0; k < cloud.Points.size(); ++k)
  {
    for (int a = 0; a < D; ++a)
    {
      if (!std::isfinite(cloud.Points[k][a]))
      {
        return Status::invalidArgument("point " + std::to_string(k) + " has a non-finite coordinate (" +
          std::to_string(cloud.Points[k][a]) + "): remove NaN/Inf points before reconstructing");
      }
    }
  }
  if (cloud.size() < D + 1)
  {
    return Status::invalidArgument("the point cloud has " + std::to_string(cloud.size()) + " point(s); a " + dim +
      " reconstruction needs at least " + std::to_string(D + 1));
  }
  const Box<D> box = boundingBox(cloud);
  double diameter = 0.0, magnitude = 0.0;
  for (int a = 0; a < D; ++a)
  {
    diameter = std::max(diameter, box.extent(a));
    magnitude = std::max({ magnitude, std::fabs(box.Min[a]), std::fabs(box.Max[a]) });
  }
  if (diameter == 0.0)
  {
    return Status::invalidArgument("all " + std::to_string(cloud.size()) + " points coincide: nothing to reconstruct");
  }
  // A grid of ~1e4 cells per side needs ~1e-8 relative resolution to stay accurate.
  if (diameter < 1e-8 * magnitude)
  {
    return Status::invalidArgument("the cloud's extent (" + std::to_string(diameter) +
      ") is too small against its distance from the origin (" + std::to_string(magnitude) +
      "): translate the points near the origin before reconstructing");
  }
  // Two well-separated points: the first one and the one farthest from it.
  size_t i1 = 0;
  double far = 0.0;
  for (size_t k = 0; k < cloud.Points.size(); ++k)
  {
    const double d = distance<D>(cloud.Points[0], cloud.Points[k]);
    if (d > far)
    {
      far = d;
      i1 = k;
    }
  }
  if (spreadOffFlat(cloud, 0, i1) <= 1e-12 * diameter)
  {
    return Status::invalidArgument(std::string("all points lie on one ") + (D == 2 ? "line" : "plane") + ": a closed " +
      (D == 2 ? "curve" : "surface") + " cannot be reconstructed from them");
  }
  return Status::ok();
}

template Box<2> boundingBox(const PointCloud<2>&);
template Box<3> boundingBox(const PointCloud<3>&);
template Status validateCloud(const PointCloud<2>&);
template Status validateCloud(const PointCloud<3>&);

bool flattenIfPlanar(const PointCloud<3>& cloud, PointCloud<2>& flat, double& z)
{
  if (cloud.Points.empty())
  {
    return false;
  }
  const auto box = boundingBox(cloud);
  if (box.extent(2) != 0.0)
  {
    return false;
  }
  z = box.Min[2];
  flat.Points.resize(cloud.Points.size());
  for (size_t k = 0; k < cloud.Points.size(); ++k)
  {
    flat.Points[k] = { cloud.Points[k][0], cloud.Points[k][1] };
  }
  return true;
}

} // namespace sltk
