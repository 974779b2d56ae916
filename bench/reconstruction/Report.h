// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Report.h
/// Table cells of the reconstruction benchmark: numbers in a fixed width, "-"
/// for what is missing, and the ours/thesis ratio with its factor-1.5 verdict.

#include "sltk/grid/GridSpec.h"

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace sltkbench
{

/// v[i], or NaN / "-" past the end (the thesis's tables are shorter than some runs).
double at(const std::vector<double>& v, size_t i);
std::string at(const std::vector<std::string>& v, size_t i);

/// ours/thesis and the factor-1.5 verdict: "within" (1/1.5 <= ratio <= 1.5),
/// "better"/"worse" for errors, "lower"/"higher" for energies.
std::string compare(double ours, double thesis, bool energy);

/// %9.3e, or "-" in the same width.
std::string sci(double v);

/// %g.
std::string fmt(double v);

/// Seconds since t0.
double seconds(std::chrono::steady_clock::time_point t0);

/// "42x42": the grid's nodes per axis.
template <int D>
std::string gridText(const sltk::GridSpec<D>& g)
{
  std::string s;
  for (int a = 0; a < D; ++a)
  {
    s += (a ? "x" : "") + std::to_string(g.Dims[a]);
  }
  return s;
}

} // namespace sltkbench
