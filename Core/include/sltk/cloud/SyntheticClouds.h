// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SyntheticClouds.h
/// The synthetic clouds of the thesis's tests (4.5.3, 4.5.4) with their exact
/// signed distances (negative inside) and fine quadratures of the exact
/// curves/surfaces, so that errors against the exact shape can be measured:
///  - circle (4.5.3): n points evenly spaced; exact SDF circleSdf;
///  - square rotated by 45 degrees (4.5.3): the diamond |x| + |y| = 1; rotatedSquareSdf;
///  - sphere: Fibonacci points (sphereCloud) or a subdivided icosahedron
///    (icosphereCloud, 4.5.4's 2562-point sphere); sphereSdf;
///  - Cube&Spheres (4.5.4): CubeSpheres, cloud and SDF;
///  - any closed polygon sampled every h (polygonCloud);
///  - a disc with a thin fin (discWithFinCloud), a part coarse runs lose; a circle with a
///    needle of points (circleWithNeedleCloud);
///  - Gaussian noise on a cloud (the "10% noise" tests, Fig. 4.8, Fig. 4.11).
/// Used by tests, benchmarks and examples.

#include "sltk/cloud/PointCloud.h"

#include <array>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

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

/// circleCloud(400) with a needle of `points` points (no thickness) from it along +x, `length`
/// long (its last point at x = 1 + length): a part whose points the surface of coarse cells
/// misses nearly all of (recon/MissedPlaces.h, lostPart).
inline PointCloud<2> circleWithNeedleCloud(int points, double length)
{
  PointCloud<2> cloud = circleCloud(400);
  for (int k = 1; k <= points; ++k)
  {
    cloud.Points.push_back({ 1.0 + length * k / points, 0.0 });
  }
  return cloud;
}

/// The circle of radius r centred at c, its upper half (y >= c_y) sampled every `dense`
/// and its lower half every `sparse` (arc lengths, rounded to whole parts of each half):
/// one object sampled unevenly, as a CAD mesh's vertices are (recon/PointClusters.h).
inline PointCloud<2> unevenHalvesCircleCloud(double r, std::array<double, 2> c, double dense, double sparse)
{
  constexpr double pi = 3.14159265358979323846;
  PointCloud<2> cloud;
  for (const auto& [from, step] : { std::pair<double, double>{ 0.0, dense }, std::pair<double, double>{ pi, sparse } })
  {
    const int n = static_cast<int>(std::ceil(pi * r / step));
    for (int k = 0; k < n; ++k)
    {
      const double t = from + pi * k / n;
      cloud.Points.push_back({ c[0] + r * std::cos(t), c[1] + r * std::sin(t) });
    }
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

/// The circle of radius 0.5 (314 points) with a fin along +x to x = 1 of the
/// given thickness: its two sides and its end sampled every 0.01, the circle's
/// points inside the fin left out. h_P is about 0.01, so a fin of 0.016 is 1.6
/// h_P thick: run 1 at C_dx = 1 loses it (recon/FarPointSeeds.h).
PointCloud<2> discWithFinCloud(double thickness);

/// Signed distance to the circle of radius r centred at c.
double circleSdf(const std::array<double, 2>& x, double r = 1.0, const std::array<double, 2>& c = { 0.0, 0.0 });

/// Signed distance to the sphere of radius r centred at c.
double sphereSdf(const std::array<double, 3>& x, double r = 1.0, const std::array<double, 3>& c = { 0.0, 0.0, 0.0 });

/// Points on the closed polygon `corners`: each side of length L is cut into
/// ceil(L / h) equal parts, whose start points are kept (corners included once).
PointCloud<2> polygonCloud(const std::vector<std::array<double, 2>>& corners, double h);

/// 4.5.3's square rotated by 45 degrees, in [-1, 1]^2: the diamond |x| + |y| = 1,
/// each side cut into `segmentsPerSide` equal parts (4 * segmentsPerSide points,
/// corners included; the thesis's 24 points are segmentsPerSide = 6, h_P = sqrt(2) / 6).
PointCloud<2> rotatedSquareCloud(int segmentsPerSide = 6);

/// The heart of the thesis's chapter 5 (5.3.1: "a heart-shaped point cloud
/// composed by 24 points", with rounded, straight and sharp parts; the thesis
/// gives no formula): the classic heart curve x = 16 sin^3 t, y = 13 cos t -
/// 5 cos 2t - 2 cos 3t - cos 4t (a cusp at the top, a point at the bottom,
/// nearly straight flanks), n points at equal arc length from the cusp.
PointCloud<2> heartCloud(int n = 24);

/// Exact signed distance to the diamond |x| + |y| = 1: a box of half-side
/// 1/sqrt(2) in the coordinates rotated by 45 degrees.
double rotatedSquareSdf(const std::array<double, 2>& x);

/// Icosahedron subdivided `levels` times (edge midpoints), vertices projected on
/// the unit sphere: 10 * 4^levels + 2 points (4.5.4's sphere: levels = 4, 2562 points).
PointCloud<3> icosphereCloud(int levels);

/// Every coordinate of every point plus an independent N(0, sigma^2) draw
/// (mt19937_64 seeded with `seed`: reproducible). The thesis's "10% of normally
/// distributed noise" (4.5.3 Fig. 4.8, 4.5.4 Fig. 4.11) gives no formula; on the
/// unit circle / sphere we read it as sigma = 0.1.
template <int D>
PointCloud<D> withGaussianNoise(PointCloud<D> cloud, double sigma, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  for (auto& p : cloud.Points)
  {
    for (double& x : p)
    {
      x += normal(rng);
    }
  }
  return cloud;
}

/// 4.5.4 Cube&Spheres. In the object's own frame: the cube [-0.4, 0.4]^3 (edge
/// 0.8), a sphere of radius 0.25 at the middle (0, 0.4, 0.4) of an edge and
/// spheres of radius 0.15 at the vertices (+-0.4, -0.4, -0.4) of the opposite
/// edge. The object is rotated (about z by 30, y by 25, x by 15 degrees, so that
/// no face or edge is aligned with a grid); cloud() then centres and scales it so
/// that the cloud's bounding box has half-extent 1, and sdf() is the exact
/// signed distance in that unit-box frame.
class CubeSpheres
{
public:
  CubeSpheres();

  /// Quasi-uniform samples of the union's surface, `target` points where
  /// possible (4.5.4: 2346), mapped to the unit box; fixes the frame of sdf().
  PointCloud<3> cloud(int target);

  /// Signed distance at a point of the unit-box frame (exact outside the union;
  /// inside, near the junction curves, an under-estimate of |phi*|).
  double sdf(const std::array<double, 3>& x) const;

private:
  struct Ball
  {
    std::array<double, 3> C;
    double R;
  };
  double objectSdf(const std::array<double, 3>& p) const;
  std::array<double, 3> toWorld(const std::array<double, 3>& p) const;
  std::vector<std::array<double, 3>> sample(double spacing, int extra) const;

  Ball Balls[3] = { { { 0.0, 0.4, 0.4 }, 0.25 }, { { 0.4, -0.4, -0.4 }, 0.15 }, { { -0.4, -0.4, -0.4 }, 0.15 } };
  double Rot[3][3]{};             ///< object frame -> world
  std::array<double, 3> Centre{}; ///< world bounding-box centre (before scaling)
  double Scale = 1.0;             ///< world half-extent
};

/// Quadrature nodes and weights of a curve (D = 2) or surface (D = 3).
template <int D>
using ShapeQuadrature = std::vector<std::pair<std::array<double, D>, double>>;

/// Midpoint rule with n equal arcs of the unit circle.
ShapeQuadrature<2> circleQuadrature(int n);

/// Midpoint rule with `perSide` equal parts on each side of the diamond |x| + |y| = 1.
ShapeQuadrature<2> rotatedSquareQuadrature(int perSide);

/// n Fibonacci points on the unit sphere, equal weights 4 pi / n.
ShapeQuadrature<3> sphereQuadrature(int n);

/// E_2 of a shape (4.1) with p = 2: sqrt(sum w d_P(x)^2) over a quadrature
/// (x, w) of it, d_P the distance to the cloud by brute force. The thesis quotes
/// about 7.10e-2 for the unit circle and 64 points (4.5.3, dashed line of Fig. 4.7).
template <int D>
double shapeEnergy(const PointCloud<D>& cloud, const ShapeQuadrature<D>& quadrature);

extern template double shapeEnergy<2>(const PointCloud<2>&, const ShapeQuadrature<2>&);
extern template double shapeEnergy<3>(const PointCloud<3>&, const ShapeQuadrature<3>&);

} // namespace sltk
