// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file GridPlan.h
/// The uniform grid of each run of Algorithm 1: dx^(r) = C_dx h_P / 2^(r-1)
/// (4.36) over the cloud's bounding box padded by a number of cells per side
/// (Documentation/Numerics.md: the grids of Tables 4.2 and 4.8 have roughly 8-12 cells of padding).
/// Also refuses plans whose finest grid would not fit in memory, naming the
/// node count and a C_dx that would fit.

#include "sltk/cloud/PointCloud.h"
#include "sltk/grid/GridSpec.h"

#include <vector>

namespace sltk
{

struct GridPlanOptions
{
  int Runs = 3;                   ///< number of runs r = 1..Runs
  double CellSizeFactor = 1.0;    ///< C_dx of (4.36); the thesis's default is 1
  int Padding = 10;               ///< empty cells around the bounding box, per side
  int FirstRunPadding = 0;        ///< run 1's padding in its cells when larger (room for the initial surface)
  double BytesPerNode = 48.0;     ///< memory a node costs in the solver (estimate)
  std::uint64_t MemoryBudget = 0; ///< bytes allowed; 0: available memory
};

/// The C_dx whose finest cell (run `runs`) is the cloud's largest extent / 2^L:
/// the thesis's octree levels, (5.1) with (5.10)-(5.11), run 1 at level
/// L0 = L - runs + 1 of the minimal cube around the cloud.
double cellSizeFactorForLevel(int level, int runs, double largestExtent, double cloudSpacing);

/// The finest level L whose C_dx is at least `cellSizeFactor`: the finest
/// level no finer than that C_dx's grid.
int levelForCellSizeFactor(double cellSizeFactor, int runs, double largestExtent, double cloudSpacing);

template <int D>
struct GridPlan
{
  double CloudSpacing = 0.0;     ///< h_P
  std::vector<GridSpec<D>> Runs; ///< one grid per run, coarse to fine
};

/// Plans the run grids for a validated cloud of spacing h_P.
template <int D>
Status planGrids(const Box<D>& bounds, double cloudSpacing, const GridPlanOptions& options, GridPlan<D>& plan);

extern template Status planGrids(const Box<2>&, double, const GridPlanOptions&, GridPlan<2>&);
extern template Status planGrids(const Box<3>&, double, const GridPlanOptions&, GridPlan<3>&);

} // namespace sltk
