// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Chapter5.h
/// What the benchmarks of the thesis's chapter 5 tests share: run 1's level
/// from (5.10)-(5.11) and the verdicts against the thesis's numbers.

#include "common/ThesisTables.h"

#include <cmath>
#include <string>

namespace sltkbench
{

/// (5.10)-(5.11): the level of run 1 and the C_dx (4.36) that gives its cell,
/// Delta_P / 2^L0, on a cloud of spacing `spacing` and box edge `edge`.
struct Chapter5Grid
{
  int Level = 0;
  double CellSizeFactor = 0.0;
};

inline Chapter5Grid chapter5Grid(double edge, double spacing)
{
  constexpr double Cdx = 0.5; // (5.11): "C_dx usually equal to 0.5"
  Chapter5Grid g;
  g.Level = static_cast<int>(std::ceil(std::log2(edge / (Cdx * spacing))));
  g.CellSizeFactor = edge / (std::ldexp(1.0, g.Level) * spacing);
  return g;
}

/// "within +-50%" when value / reference lies in [0.5, 1.5], "OUTSIDE +-50%"
/// when not, "" without a reference (issue 14's tolerance on iterations).
inline std::string verdictWithinHalf(double value, double reference)
{
  if (std::isnan(reference))
  {
    return "";
  }
  const double ratio = value / reference;
  return ratio >= 0.5 && ratio <= 1.5 ? "within +-50%" : "OUTSIDE +-50%";
}

/// An error against the thesis's: "0.42 of it" (lower) or "2.10 times it" (higher).
inline std::string errorRatio(double value, double reference)
{
  const double ratio = value / reference;
  return formatValue(ratio, "%.2f") + (ratio <= 1.0 ? " of it" : " times it");
}

} // namespace sltkbench
