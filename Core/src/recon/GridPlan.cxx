// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/GridPlan.h"

#include "sltk/exec/Memory.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sltk
{

double cellSizeFactorForLevel(int level, int runs, double largestExtent, double cloudSpacing)
{
  return largestExtent * std::ldexp(1.0, runs - 1 - level) / cloudSpacing; // dx^(1) / h_P, (4.36)
}

int levelForCellSizeFactor(double cellSizeFactor, int runs, double largestExtent, double cloudSpacing)
{
  // A level's own C_dx gives the level back despite the rounding of log2.
  const double level = std::log2(largestExtent * std::ldexp(1.0, runs - 1) / (cloudSpacing * cellSizeFactor));
  return static_cast<int>(std::floor(level + 1e-9));
}

namespace
{
template <int D>
GridSpec<D> runGrid(const Box<D>& bounds, double dx, int padding)
{
  GridSpec<D> g;
  for (int a = 0; a < D; ++a)
  {
    const double cells = std::ceil(bounds.extent(a) / dx);
    g.Dims[a] = static_cast<Index>(cells) + 1 + 2 * padding;
    g.Spacing[a] = dx;
    // Centre the cloud in the padded grid.
    g.Origin[a] = 0.5 * (bounds.Min[a] + bounds.Max[a]) - 0.5 * dx * static_cast<double>(g.Dims[a] - 1);
    g.Bounds[a] = Boundary::Extrapolate;
  }
  return g;
}
} // namespace

template <int D>
Status planGrids(const Box<D>& bounds, double cloudSpacing, const GridPlanOptions& options, GridPlan<D>& plan)
{
  plan = GridPlan<D>{};
  if (!(cloudSpacing > 0.0) || !std::isfinite(cloudSpacing))
  {
    return Status::invalidArgument("the cloud spacing h_P must be positive and finite");
  }
  if (options.Runs < 1 || !(options.CellSizeFactor > 0.0) || options.Padding < 0)
  {
    return Status::invalidArgument("runs must be >= 1, C_dx > 0 and padding >= 0");
  }
  plan.CloudSpacing = cloudSpacing;
  const double finestDx = options.CellSizeFactor * cloudSpacing / std::ldexp(1.0, options.Runs - 1);
  for (int a = 0; a < D; ++a)
  {
    // Integer node counts must stay far from overflow before any GridSpec is built.
    if (bounds.extent(a) / finestDx > 1e9)
    {
      std::ostringstream m;
      m << "the finest grid (run " << options.Runs << ") would have more than 1e9 nodes along axis " << a
        << ": use a larger C_dx or fewer runs";
      return Status::outOfMemory(m.str());
    }
  }
  for (int r = 1; r <= options.Runs; ++r)
  {
    // (4.36): dx^(r) = C_dx h_P / 2^(r-1)
    const double dx = options.CellSizeFactor * cloudSpacing / std::ldexp(1.0, r - 1);
    const int padding = r == 1 ? std::max(options.Padding, options.FirstRunPadding) : options.Padding;
    plan.Runs.push_back(runGrid(bounds, dx, padding));
  }
  // The largest grid (the finest, unless run 1's padding for its initial surface is wide).
  double nodes = 0.0;
  for (const GridSpec<D>& run : plan.Runs)
  {
    double runNodes = 1.0;
    for (int a = 0; a < D; ++a)
    {
      runNodes *= static_cast<double>(run.Dims[a]);
    }
    nodes = std::max(nodes, runNodes);
  }
  const double budget =
    options.MemoryBudget ? static_cast<double>(options.MemoryBudget) : static_cast<double>(availableMemoryBytes());
  const double need = nodes * options.BytesPerNode;
  if (budget > 0.0 && need > budget)
  {
    // The node count scales as C_dx^-D: the factor that fits with 10% headroom.
    const double fit = options.CellSizeFactor * std::pow(need / (0.9 * budget), 1.0 / D);
    std::ostringstream m;
    m << "the largest grid (of " << options.Runs << " runs) would have " << nodes << " nodes, about " << need / 1e9
      << " GB, more than the " << budget / 1e9 << " GB available: use C_dx >= " << fit << " or fewer runs";
    plan.Runs.clear();
    return Status::outOfMemory(m.str());
  }
  return Status::ok();
}

template Status planGrids(const Box<2>&, double, const GridPlanOptions&, GridPlan<2>&);
template Status planGrids(const Box<3>&, double, const GridPlanOptions&, GridPlan<3>&);

} // namespace sltk
