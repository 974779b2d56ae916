// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PointCloud.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
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

std::array<double, 3> cross(const std::array<double, 3>& x, const std::array<double, 3>& y)
{
  return { x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0] };
}
double norm(const std::array<double, 3>& x)
{
  return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}
template <int D>
std::array<double, 3> from(const std::array<double, D>& p, const std::array<double, D>& origin)
{
  std::array<double, 3> v{};
  for (int a = 0; a < D; ++a)
  {
    v[a] = p[a] - origin[a];
  }
  return v;
}

/// Largest distance of any point from the line through points i0 and i1, and
/// the point that has it: zero for collinear clouds.
template <int D>
double spreadOffLine(const PointCloud<D>& c, size_t i0, size_t i1, size_t& farthest)
{
  const auto& a = c.Points[i0];
  const auto u = from<D>(c.Points[i1], a);
  const double len = norm(u);
  double best = 0.0;
  farthest = i0;
  for (size_t k = 0; k < c.Points.size(); ++k)
  {
    const double d = norm(cross(u, from<D>(c.Points[k], a))) / len;
    if (d > best)
    {
      best = d;
      farthest = k;
    }
  }
  return best;
}

/// Largest distance of any point from the plane through points i0, i1, i2.
double spreadOffPlane(const PointCloud<3>& c, size_t i0, size_t i1, size_t i2)
{
  const auto& a = c.Points[i0];
  const auto n = cross(from<3>(c.Points[i1], a), from<3>(c.Points[i2], a));
  const double nn = norm(n);
  double best = 0.0;
  for (const auto& p : c.Points)
  {
    const auto v = from<3>(p, a);
    best = std::max(best, std::fabs(n[0] * v[0] + n[1] * v[1] + n[2] * v[2]) / nn);
  }
  return best;
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
  // Beyond this, squared distances (h_P, the distance function) overflow double.
  constexpr double LargestCoordinate = 1e150;
  if (!(magnitude <= LargestCoordinate) || !std::isfinite(diameter))
  {
    std::ostringstream m;
    m << "coordinates reach " << magnitude
      << ", beyond what distances in double precision can hold (1e150): rescale the cloud (e.g. divide the "
         "coordinates by its extent) before reconstructing";
    return Status::invalidArgument(m.str());
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
      "): its coordinates carry too few digits for the grid; translate the points near the origin where they are "
      "made, before they are rounded to double");
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
  const std::string closed = D == 2 ? "a closed curve" : "a closed surface";
  size_t i2 = 0;
  if (spreadOffLine(cloud, 0, i1, i2) <= 1e-12 * diameter)
  {
    return Status::invalidArgument("all points lie on one line: " + closed + " cannot be reconstructed from them");
  }
  if constexpr (D == 3)
  {
    if (spreadOffPlane(cloud, 0, i1, i2) <= 1e-12 * diameter)
    {
      return Status::invalidArgument("all points lie on one plane: a closed surface cannot be reconstructed from "
                                     "them; for a planar outline, give the points a constant z (a 2D "
                                     "reconstruction)");
    }
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
