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

/// A box of grid nodes as VTK writes an extent, {i0, i1, j0, j1, k0, k1}
/// (inclusive node indices of the whole grid); empty when an upper index is
/// below its lower one.
using HjbExtent = std::array<long long, 6>;

/// The extent of every node of `grid`.
inline HjbExtent wholeExtent(const HjbGrid& grid)
{
  return { 0, grid.Dims[0] - 1, 0, grid.Dims[1] - 1, 0, grid.Dims[2] - 1 };
}

struct HjbRunResult
{
  HjbGrid Grid;                           ///< the whole grid
  HjbExtent Block{ 0, -1, 0, -1, 0, -1 }; ///< the nodes Value and ReachTime hold
  std::vector<double> Value;              ///< u at t_k on the nodes of Block, x fastest
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
