// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file InitialData.h
/// Closed-form initial data v0 of the thesis's HJB tests (3.5). These are the
/// exact solutions at t = 0 and, for rigid transport (Test 1), at every full
/// revolution; the closed-form exact solutions of Tests 2-4 follow them.

#include <algorithm>
#include <cmath>

namespace sltk
{

/// Test 1 (3.5.1): the globally C2 bump
/// v0(r) = M (1 + r^3/R^3 (-1 + 3 (r-R)/R (1 - 2 (r-R)/R))) for r < R, 0 outside,
/// r = |x - (0.3, 0.7)|, M = R = 0.15.
inline double rotatingBump(double x, double y)
{
  constexpr double M = 0.15, R = 0.15;
  const double r = std::hypot(x - 0.3, y - 0.7);
  if (r >= R)
  {
    return 0.0;
  }
  const double s = (r - R) / R;
  return M * (1.0 + (r * r * r) / (R * R * R) * (-1.0 + 3.0 * s * (1.0 - 2.0 * s)));
}

/// Test 2 (3.5.2), (3.32): v0(x) = min(-cos(pi x / 2), 0).
inline double semiConcaveCosine(double x)
{
  const double v = -std::cos(1.5707963267948966 * x);
  return v < 0.0 ? v : 0.0;
}

/// Test 2 exact solution (3.33)-(3.35): the optimal control a* solves
/// a = x/t - (2 / (pi t)) arcsin(2a / pi) on |a| <= pi/2 (3.34)-(3.35), and
/// v(t, x) = min(0, t a*^2 / 2 - cos(pi (x - t a*) / 2)).
/// The thesis iterates (3.34) as a fixed point from a_0 = x^2 t / 2; we solve
/// the same equation by bisection: h(a) = t a + (2/pi) arcsin(2a/pi) - x is
/// increasing, so the root is unique and found to machine precision. (3.33)
/// prints a*^2 / 2 without the factor t; the two agree at T = 1, where the
/// thesis measures the error, and the Hopf-Lax formula has the t.
inline double semiConcaveCosineExact(double t, double x)
{
  constexpr double halfPi = 1.5707963267948966;
  if (!(t > 0.0))
  {
    return semiConcaveCosine(x);
  }
  auto h = [&](double a) { return t * a + std::asin(a / halfPi) / halfPi - x; };
  double lo = -halfPi, hi = halfPi;
  double a = 0.0;
  if (h(lo) >= 0.0)
  {
    a = lo;
  }
  else if (h(hi) <= 0.0)
  {
    a = hi;
  }
  else
  {
    for (int k = 0; k < 200 && hi - lo > 0.0; ++k)
    {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi)
      {
        break;
      }
      (h(mid) < 0.0 ? lo : hi) = mid;
    }
    a = 0.5 * (lo + hi);
  }
  const double v = 0.5 * t * a * a - std::cos(halfPi * (x - t * a));
  return v < 0.0 ? v : 0.0;
}

/// Test 3 (3.5.3), (3.36): the source f(t, x) = -sin x + (9/8 + (t^2 - 3t)/2) cos^2 x.
inline double eikonalSource(double t, double x)
{
  const double c = std::cos(x);
  return -std::sin(x) + (1.125 + 0.5 * (t * t - 3.0 * t)) * c * c;
}

/// Test 3 exact solution v(t, x) = (3/2 - t) sin x (v0 = 3/2 sin x).
inline double eikonalExact(double t, double x)
{
  return (1.5 - t) * std::sin(x);
}

/// Test 4 (3.5.4), (3.37): v0(x) = max(1 - |x|^2, 0).
inline double semiConvexCap(double x, double y)
{
  const double v = 1.0 - (x * x + y * y);
  return v > 0.0 ? v : 0.0;
}

/// Test 4 exact solution (3.38), valid for t >= 1/2: (|x| - 1)^2 / (2t) for |x| <= 1, 0 outside.
inline double semiConvexCapExact(double t, double x, double y)
{
  const double r = std::hypot(x, y);
  return r <= 1.0 ? (r - 1.0) * (r - 1.0) / (2.0 * t) : 0.0;
}

/// Test 5 (3.5.5): the target, v0(x) = C min(|(x1 - 1, x2)| - r, r), r = 0.25, C = 20.
inline double zermeloTarget(double x, double y)
{
  constexpr double r = 0.25, C = 20.0;
  const double d = std::hypot(x - 1.0, y) - r;
  return C * (d < r ? d : r);
}

/// Test 5 state constraint g(x) = max(-gamma, g1, g2), the two square obstacles
/// g1 = C (gamma - max(|x1 - 0.3|, |x2 - 0.4|)), g2 = C (gamma - max(|x1 + 1|, |x2 + 1.5|)),
/// C = 20, gamma = 0.2; K = { g <= 0 }.
inline double zermeloObstacles(double x, double y)
{
  constexpr double gamma = 0.2, C = 20.0;
  const double g1 = C * (gamma - std::max(std::fabs(x - 0.3), std::fabs(y - 0.4)));
  const double g2 = C * (gamma - std::max(std::fabs(x + 1.0), std::fabs(y + 1.5)));
  return std::max(-gamma, std::max(g1, g2));
}

} // namespace sltk
