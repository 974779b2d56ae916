// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file InitialData.h
/// Closed-form initial data v0 of the thesis's HJB tests (3.5). These are the
/// exact solutions at t = 0 and, for rigid transport (Test 1), at every full
/// revolution.

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

} // namespace sltk
