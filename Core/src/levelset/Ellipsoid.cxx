// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/Ellipsoid.h"

#include <algorithm>
#include <cmath>

namespace sltk
{

namespace
{
/// Root of G(s) = sum_i (r_i z_i / (s + r_i))^2 - 1 by bisection (Eberly's GetRoot);
/// r_{n-1} = 1 is the smallest ratio and z_{n-1} > 0.
double lagrangeRoot(const double* r, const double* z, int n, double g)
{
  double scale = 0.0;
  for (int i = 0; i < n; ++i)
  {
    scale = std::max(scale, std::fabs(r[i] * z[i]));
  }
  double length = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const double t = r[i] * z[i] / scale;
    length += t * t;
  }
  length = scale * std::sqrt(length);
  double s0 = z[n - 1] - 1.0;
  double s1 = g < 0.0 ? 0.0 : length - 1.0;
  double s = s0;
  for (int it = 0; it < 2200; ++it)
  {
    s = 0.5 * (s0 + s1);
    if (s == s0 || s == s1)
    {
      break;
    }
    double value = -1.0;
    for (int i = 0; i < n; ++i)
    {
      const double t = r[i] * z[i] / (s + r[i]);
      value += t * t;
    }
    if (value > 0.0)
    {
      s0 = s;
    }
    else if (value < 0.0)
    {
      s1 = s;
    }
    else
    {
      break;
    }
  }
  return s;
}

/// Squared distance from y (y_i >= 0) to the ellipsoid with semi-axes e sorted
/// descending, n <= 3 (Eberly's SqrDistanceSpecial, recursive on the dimension).
double squaredDistanceSorted(const double* e, const double* y, int n)
{
  if (n == 1)
  {
    return (y[0] - e[0]) * (y[0] - e[0]);
  }
  if (y[n - 1] > 0.0)
  {
    double r[3] = { 0.0, 0.0, 0.0 };
    double z[3] = { 0.0, 0.0, 0.0 };
    double g = -1.0;
    for (int i = 0; i < n; ++i)
    {
      z[i] = y[i] / e[i];
      r[i] = (e[i] / e[n - 1]) * (e[i] / e[n - 1]);
      g += z[i] * z[i];
    }
    if (g == 0.0)
    {
      return 0.0;
    }
    const double s = lagrangeRoot(r, z, n, g);
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
    {
      const double x = r[i] * y[i] / (s + r[i]);
      sum += (x - y[i]) * (x - y[i]);
    }
    return sum;
  }
  // y_{n-1} = 0: the closest point may leave the plane x_{n-1} = 0 (inside, near the medial set).
  bool offPlane = true;
  double xde[3] = { 0.0, 0.0, 0.0 };
  double discr = 1.0;
  for (int i = 0; i < n - 1; ++i)
  {
    const double numer = e[i] * y[i];
    const double denom = e[i] * e[i] - e[n - 1] * e[n - 1];
    if (!(numer < denom))
    {
      offPlane = false;
      break;
    }
    xde[i] = numer / denom;
    discr -= xde[i] * xde[i];
  }
  if (offPlane && discr > 0.0)
  {
    double sum = 0.0;
    for (int i = 0; i < n - 1; ++i)
    {
      const double x = e[i] * xde[i];
      sum += (x - y[i]) * (x - y[i]);
    }
    return sum + e[n - 1] * e[n - 1] * discr;
  }
  return squaredDistanceSorted(e, y, n - 1);
}
} // namespace

template <int D>
double signedDistance(const Ellipsoid<D>& el, const double* x)
{
  // Reduce to the first orthant and semi-axes sorted descending.
  int order[D];
  for (int a = 0; a < D; ++a)
  {
    order[a] = a;
  }
  std::sort(order, order + D, [&](int p, int q) { return el.SemiAxes[p] > el.SemiAxes[q]; });
  double e[3] = { 1.0, 1.0, 1.0 };
  double y[3] = { 0.0, 0.0, 0.0 };
  double level = 0.0;
  for (int k = 0; k < D; ++k)
  {
    e[k] = el.SemiAxes[order[k]];
    y[k] = std::fabs(x[order[k]] - el.Centre[order[k]]);
    level += (y[k] / e[k]) * (y[k] / e[k]);
  }
  const double d = std::sqrt(squaredDistanceSorted(e, y, D));
  return level < 1.0 ? -d : d;
}

template <int D>
Status ellipsoidLevelSet(const Ellipsoid<D>& e, const GridSpec<D>& grid, const Context& ctx,
  GridField<D, double>& phi0, int ghost)
{
  SLTK_RETURN_IF_ERROR(grid.validate());
  for (int a = 0; a < D; ++a)
  {
    if (!(e.SemiAxes[a] > 0.0) || !std::isfinite(e.SemiAxes[a]) || !std::isfinite(e.Centre[a]))
    {
      return Status::invalidArgument("the ellipsoid needs positive finite semi-axes and a finite centre");
    }
  }
  if (ghost < 0)
  {
    return Status::invalidArgument("ghost layers must be >= 0");
  }
  phi0.resize(grid, ghost);
  ctx.parallelFor(0, grid.nodeCount(), [&](Index b, Index end) {
    for (Index k = b; k < end; ++k)
    {
      const auto i = phi0.nodeIndex(k);
      double x[D];
      for (int a = 0; a < D; ++a)
      {
        x[a] = grid.coordinate(a, i[a]);
      }
      phi0(i) = signedDistance(e, x);
    }
  });
  if (ghost > 0)
  {
    phi0.fillGhosts();
  }
  return Status::ok();
}

template double signedDistance(const Ellipsoid<2>&, const double*);
template double signedDistance(const Ellipsoid<3>&, const double*);
template Status ellipsoidLevelSet(const Ellipsoid<2>&, const GridSpec<2>&, const Context&, GridField<2, double>&, int);
template Status ellipsoidLevelSet(const Ellipsoid<3>&, const GridSpec<3>&, const Context&, GridField<3, double>&, int);

} // namespace sltk
