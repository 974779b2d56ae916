// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/SyntheticClouds.h"

#include <algorithm>
#include <map>

namespace sltk
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double GoldenAngle = 2.399963229728653; // pi (3 - sqrt 5)

using Point2 = std::array<double, 2>;
using Point3 = std::array<double, 3>;

/// The corners of the diamond |x| + |y| = 1, counter-clockwise from (1, 0).
const Point2 DiamondCorners[4] = { { 1.0, 0.0 }, { 0.0, 1.0 }, { -1.0, 0.0 }, { 0.0, -1.0 } };

/// The start points of n equal parts of the segment [a, b).
void appendSide(PointCloud<2>& cloud, const Point2& a, const Point2& b, int n)
{
  for (int k = 0; k < n; ++k)
  {
    const double t = static_cast<double>(k) / n;
    cloud.Points.push_back({ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) });
  }
}

double squaredDistance(const Point3& p, const Point3& q)
{
  return std::pow(p[0] - q[0], 2) + std::pow(p[1] - q[1], 2) + std::pow(p[2] - q[2], 2);
}
} // namespace

double circleSdf(const std::array<double, 2>& x, double r, const std::array<double, 2>& c)
{
  return std::hypot(x[0] - c[0], x[1] - c[1]) - r;
}

double sphereSdf(const std::array<double, 3>& x, double r, const std::array<double, 3>& c)
{
  const double y[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
  return std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]) - r;
}

PointCloud<2> polygonCloud(const std::vector<std::array<double, 2>>& corners, double h)
{
  PointCloud<2> cloud;
  for (size_t k = 0; k < corners.size(); ++k)
  {
    const Point2& a = corners[k];
    const Point2& b = corners[(k + 1) % corners.size()];
    appendSide(cloud, a, b, static_cast<int>(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]) / h)));
  }
  return cloud;
}

PointCloud<2> rotatedSquareCloud(int segmentsPerSide)
{
  PointCloud<2> cloud;
  for (int s = 0; s < 4; ++s)
  {
    appendSide(cloud, DiamondCorners[s], DiamondCorners[(s + 1) % 4], segmentsPerSide);
  }
  return cloud;
}

double rotatedSquareSdf(const std::array<double, 2>& x)
{
  const double h = 1.0 / std::sqrt(2.0);
  const double u = std::fabs((x[0] + x[1]) * h) - h;
  const double v = std::fabs((x[0] - x[1]) * h) - h;
  return std::hypot(std::max(u, 0.0), std::max(v, 0.0)) + std::min(std::max(u, v), 0.0);
}

PointCloud<2> heartCloud(int n)
{
  constexpr double twoPi = 6.283185307179586;
  const auto at = [](double t) -> Point2
  {
    const double s = std::sin(t);
    return { 16.0 * s * s * s, 13.0 * std::cos(t) - 5.0 * std::cos(2 * t) - 2.0 * std::cos(3 * t) - std::cos(4 * t) };
  };
  // Arc length on a fine polyline, then the points at n equal steps of it.
  constexpr int Fine = 1 << 16;
  std::vector<double> length(Fine + 1, 0.0);
  for (int k = 1; k <= Fine; ++k)
  {
    const Point2 a = at(twoPi * (k - 1) / Fine), b = at(twoPi * k / Fine);
    length[static_cast<size_t>(k)] = length[static_cast<size_t>(k) - 1] + std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  PointCloud<2> cloud;
  for (int j = 0; j < n; ++j)
  {
    const double goal = length.back() * j / n;
    const auto k = static_cast<size_t>(std::upper_bound(length.begin(), length.end(), goal) - length.begin());
    // Polyline segment k - 1 holds the goal: [length[k - 1], length[k]).
    const double fraction = (goal - length[k - 1]) / (length[k] - length[k - 1]);
    cloud.Points.push_back(at(twoPi * (static_cast<double>(k - 1) + fraction) / Fine));
  }
  return cloud;
}

PointCloud<3> icosphereCloud(int levels)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Point3> v = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
    { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  std::vector<std::array<int, 3>> f = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 },
    { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  auto normalise = [](Point3& p)
  {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (double& c : p)
    {
      c /= n;
    }
  };
  for (auto& p : v)
  {
    normalise(p);
  }
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b)
    {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      const auto it = midpoint.find(key);
      if (it != midpoint.end())
      {
        return it->second;
      }
      Point3 m = { 0.5 * (v[a][0] + v[b][0]), 0.5 * (v[a][1] + v[b][1]), 0.5 * (v[a][2] + v[b][2]) };
      normalise(m);
      v.push_back(m);
      midpoint[key] = static_cast<int>(v.size()) - 1;
      return static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& tri : f)
    {
      const int ab = mid(tri[0], tri[1]);
      const int bc = mid(tri[1], tri[2]);
      const int ca = mid(tri[2], tri[0]);
      g.push_back({ tri[0], ab, ca });
      g.push_back({ tri[1], bc, ab });
      g.push_back({ tri[2], ca, bc });
      g.push_back({ ab, bc, ca });
    }
    f = std::move(g);
  }
  PointCloud<3> cloud;
  cloud.Points = v;
  return cloud;
}

// --- Cube&Spheres (4.5.4) ------------------------------------------------------------------------

CubeSpheres::CubeSpheres()
{
  const double a = 30.0 * Pi / 180.0, b = 25.0 * Pi / 180.0, c = 15.0 * Pi / 180.0;
  const double rz[3][3] = { { std::cos(a), -std::sin(a), 0 }, { std::sin(a), std::cos(a), 0 }, { 0, 0, 1 } };
  const double ry[3][3] = { { std::cos(b), 0, std::sin(b) }, { 0, 1, 0 }, { -std::sin(b), 0, std::cos(b) } };
  const double rx[3][3] = { { 1, 0, 0 }, { 0, std::cos(c), -std::sin(c) }, { 0, std::sin(c), std::cos(c) } };
  double t[3][3]{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        t[i][j] += rz[i][k] * ry[k][j];
      }
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        this->Rot[i][j] += t[i][k] * rx[k][j];
      }
    }
  }
}

/// Signed distance in the object frame: min of the cube's and the three balls'.
double CubeSpheres::objectSdf(const std::array<double, 3>& p) const
{
  double q[3];
  for (int a = 0; a < 3; ++a)
  {
    q[a] = std::fabs(p[a]) - 0.4;
  }
  const double outside =
    std::sqrt(std::pow(std::max(q[0], 0.0), 2) + std::pow(std::max(q[1], 0.0), 2) + std::pow(std::max(q[2], 0.0), 2));
  double s = outside + std::min(std::max(q[0], std::max(q[1], q[2])), 0.0);
  for (const Ball& b : this->Balls)
  {
    s = std::min(s, std::sqrt(squaredDistance(p, b.C)) - b.R);
  }
  return s;
}

std::array<double, 3> CubeSpheres::toWorld(const std::array<double, 3>& p) const
{
  Point3 w{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      w[i] += this->Rot[i][j] * p[j];
    }
    w[i] = (w[i] - this->Centre[i]) / this->Scale;
  }
  return w;
}

double CubeSpheres::sdf(const std::array<double, 3>& x) const
{
  Point3 w, p{};
  for (int i = 0; i < 3; ++i)
  {
    w[i] = x[i] * this->Scale + this->Centre[i];
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      p[i] += this->Rot[j][i] * w[j]; // R^T
    }
  }
  return this->objectSdf(p) / this->Scale;
}

/// Quasi-uniform samples of the union's surface with spacing s, object frame:
/// cell-centred k x k lattices on the cube faces, Fibonacci points on the
/// spheres (counts proportional to area, the first sphere's count adjusted by
/// `extra`), keeping only the points on the union's boundary.
std::vector<std::array<double, 3>> CubeSpheres::sample(double s, int extra) const
{
  std::vector<Point3> out;
  const int k = std::max(1, static_cast<int>(std::lround(0.8 / s)));
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = -1; side <= 1; side += 2)
    {
      for (int i = 0; i < k; ++i)
      {
        for (int j = 0; j < k; ++j)
        {
          Point3 p{};
          p[axis] = 0.4 * side;
          p[(axis + 1) % 3] = -0.4 + (i + 0.5) * 0.8 / k;
          p[(axis + 2) % 3] = -0.4 + (j + 0.5) * 0.8 / k;
          bool hidden = false;
          for (const Ball& b : this->Balls)
          {
            hidden = hidden || squaredDistance(p, b.C) < b.R * b.R;
          }
          if (!hidden)
          {
            out.push_back(p);
          }
        }
      }
    }
  }
  for (int bi = 0; bi < 3; ++bi)
  {
    const Ball& b = this->Balls[bi];
    const int n = std::max(4, static_cast<int>(std::lround(4.0 * Pi * b.R * b.R / (s * s))) + (bi == 0 ? extra : 0));
    for (int m = 0; m < n; ++m)
    {
      const double z = 1.0 - 2.0 * (m + 0.5) / n;
      const double r = std::sqrt(1.0 - z * z);
      const double phi = GoldenAngle * m;
      const Point3 p = { b.C[0] + b.R * r * std::cos(phi), b.C[1] + b.R * r * std::sin(phi), b.C[2] + b.R * z };
      // Drop points inside the cube or another ball (strictly).
      bool hidden = std::fabs(p[0]) < 0.4 && std::fabs(p[1]) < 0.4 && std::fabs(p[2]) < 0.4;
      for (int bj = 0; bj < 3; ++bj)
      {
        const Ball& o = this->Balls[bj];
        hidden = hidden || (bj != bi && squaredDistance(p, o.C) < o.R * o.R);
      }
      if (!hidden)
      {
        out.push_back(p);
      }
    }
  }
  return out;
}

PointCloud<3> CubeSpheres::cloud(int target)
{
  // Bisection on the spacing for a count just above the target, then trim
  // the first sphere's Fibonacci count to hit it exactly where possible.
  double lo = 0.005, hi = 0.2;
  for (int it = 0; it < 60; ++it)
  {
    const double mid = 0.5 * (lo + hi);
    (static_cast<int>(this->sample(mid, 0).size()) > target ? lo : hi) = mid;
  }
  std::vector<Point3> pts = this->sample(lo, 0);
  for (int extra = 0; extra > -200 && static_cast<int>(pts.size()) > target; --extra)
  {
    pts = this->sample(lo, extra - 1);
  }
  this->Centre = { 0, 0, 0 };
  this->Scale = 1.0;
  std::vector<Point3> world;
  for (const auto& p : pts)
  {
    world.push_back(this->toWorld(p));
  }
  Point3 mn = world[0], mx = world[0];
  for (const auto& w : world)
  {
    for (int a = 0; a < 3; ++a)
    {
      mn[a] = std::min(mn[a], w[a]);
      mx[a] = std::max(mx[a], w[a]);
    }
  }
  double half = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    this->Centre[a] = 0.5 * (mn[a] + mx[a]);
    half = std::max(half, 0.5 * (mx[a] - mn[a]));
  }
  this->Scale = half;
  PointCloud<3> c;
  for (const auto& p : pts)
  {
    c.Points.push_back(this->toWorld(p));
  }
  return c;
}

// --- quadratures of the exact shapes and E_2 (4.1) -----------------------------------------------

ShapeQuadrature<2> circleQuadrature(int n)
{
  ShapeQuadrature<2> q;
  for (int k = 0; k < n; ++k)
  {
    const double t = 2.0 * Pi * (k + 0.5) / n;
    q.push_back({ { std::cos(t), std::sin(t) }, 2.0 * Pi / n });
  }
  return q;
}

ShapeQuadrature<2> rotatedSquareQuadrature(int perSide)
{
  ShapeQuadrature<2> q;
  for (int s = 0; s < 4; ++s)
  {
    const Point2& a = DiamondCorners[s];
    const Point2& b = DiamondCorners[(s + 1) % 4];
    for (int k = 0; k < perSide; ++k)
    {
      const double t = (k + 0.5) / perSide;
      q.push_back({ { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) }, std::sqrt(2.0) / perSide });
    }
  }
  return q;
}

ShapeQuadrature<3> sphereQuadrature(int n)
{
  ShapeQuadrature<3> q;
  for (int k = 0; k < n; ++k)
  {
    const double z = 1.0 - 2.0 * (k + 0.5) / n;
    const double r = std::sqrt(1.0 - z * z);
    q.push_back({ { r * std::cos(GoldenAngle * k), r * std::sin(GoldenAngle * k), z }, 4.0 * Pi / n });
  }
  return q;
}

template <int D>
double shapeEnergy(const PointCloud<D>& cloud, const ShapeQuadrature<D>& quadrature)
{
  double sum = 0.0;
  for (const auto& q : quadrature)
  {
    double best = 1e300;
    for (const auto& p : cloud.Points)
    {
      double d2 = 0.0;
      for (int a = 0; a < D; ++a)
      {
        d2 += (q.first[a] - p[a]) * (q.first[a] - p[a]);
      }
      best = std::min(best, d2);
    }
    sum += q.second * best;
  }
  return std::sqrt(sum);
}

template double shapeEnergy<2>(const PointCloud<2>&, const ShapeQuadrature<2>&);
template double shapeEnergy<3>(const PointCloud<3>&, const ShapeQuadrature<3>&);

PointCloud<2> discWithFinCloud(double thickness)
{
  constexpr double pi = 3.14159265358979323846;
  const double half = 0.5 * thickness, step = 0.01;
  PointCloud<2> cloud;
  for (int k = 0; k < 314; ++k)
  {
    const double a = 2.0 * pi * k / 314.0;
    const std::array<double, 2> p{ 0.5 * std::cos(a), 0.5 * std::sin(a) };
    if (!(p[0] > 0.0 && std::fabs(p[1]) < half))
    {
      cloud.Points.push_back(p);
    }
  }
  for (double x = 0.5; x < 1.0; x += step)
  {
    cloud.Points.push_back({ x, half });
    cloud.Points.push_back({ x, -half });
  }
  for (double y = -half; y <= half; y += step)
  {
    cloud.Points.push_back({ 1.0, y });
  }
  return cloud;
}

} // namespace sltk
