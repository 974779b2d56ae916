// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbResult.h
/// What every HJB solver of HjbSolver.h reports, whatever the problem (a
/// thesis preset or user formulas): the grid as three axes and the state u^k
/// at t_k with the reachable set (3.40), the errors against an exact solution
/// and the work counters.

#include "sltk/core/Index.h"

#include <array>
#include <limits>
#include <vector>

namespace sltk
{

/// The grid of a solver as three axes (unused axes: one node).
struct HjbGrid
{
  int Dimension = 2;
  std::array<long long, 3> Dims{ 1, 1, 1 };
  std::array<double, 3> Origin{ 0.0, 0.0, 0.0 };
  std::array<double, 3> Spacing{ 1.0, 1.0, 1.0 };
};

struct HjbRunResult
{
  HjbGrid Grid;
  std::vector<double> Value; ///< u at t_k, x fastest
  std::vector<double>
    ReachTime; ///< first t_k with u <= 0 (+inf: never) when the reachable set (3.40) is kept; else empty
  double FinalTime = 0.0;
  double L1Error = std::numeric_limits<double>::quiet_NaN(); ///< when an exact solution is known
  double LinfError = std::numeric_limits<double>::quiet_NaN();
  /// Where the exact solution first is not a finite number (NaN or +-inf), with
  /// its value; empty when it is finite at every node (or unknown).
  std::vector<double> ExactNotFiniteAt;
  Index Steps = 0;
  double EvaluationsPerNode = 0.0;
};

} // namespace sltk
