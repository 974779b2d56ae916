// SPDX-License-Identifier: BSD-3-Clause
// A cloud of a few groups of points far apart (two objects in one file): whether its grid
// spans mostly empty space, and the advice of their own runs (ReconstructionPlan.h).
#include "sltk/recon/ReconstructionPlan.h"

#include "sltk/recon/PointClusters.h"
#include "sltk/recon/StoppingRule.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>

namespace sltk
{

namespace
{
/// The nodes of the largest grid of the plan's runs over `box` at C_dx = cellSizeFactor, whatever the budget.
template <int D>
double largestGridNodes(const ReconstructionPlan<D>& plan, const Box<D>& box, double cellSizeFactor)
{
  GridPlanOptions po = runGridOptions(plan, plan.Options.Runs, cellSizeFactor);
  po.MemoryBudget = std::numeric_limits<std::uint64_t>::max();
  GridPlan<D> grids;
  double nodes = 0.0;
  if (planGrids(box, plan.CloudSpacing, po, grids).isOk())
  {
    for (const GridSpec<D>& run : grids.Runs)
    {
      nodes = std::max(nodes, static_cast<double>(run.nodeCount()));
    }
  }
  return nodes;
}
} // namespace

template <int D>
std::string separateGroupsAdvice(const ReconstructionPlan<D>& plan, double cellSizeFactor, const std::string& why)
{
  constexpr size_t MaxSeparateGroups = 16;
  std::vector<OutsidePoint> all(static_cast<size_t>(plan.Cloud.size()));
  for (size_t i = 0; i < all.size(); ++i)
  {
    all[i].Point = static_cast<Index>(i);
  }
  const double link = PieceLinkFactor * plan.CloudSpacing;
  const std::vector<Index> group = pointGroups(plan.Cloud, all, link);
  std::map<Index, Box<D>> boxes;
  for (size_t i = 0; i < group.size() && boxes.size() <= MaxSeparateGroups; ++i)
  {
    const auto& p = plan.Cloud.Points[i];
    auto [it, created] = boxes.try_emplace(group[i]);
    for (int a = 0; a < D; ++a)
    {
      it->second.Min[a] = created ? p[a] : std::min(it->second.Min[a], p[a]);
      it->second.Max[a] = created ? p[a] : std::max(it->second.Max[a], p[a]);
    }
  }
  if (boxes.size() < 2 || boxes.size() > MaxSeparateGroups)
  {
    return {};
  }
  double own = 0.0, largest = 0.0;
  for (const auto& entry : boxes)
  {
    const double nodes = largestGridNodes(plan, entry.second, cellSizeFactor);
    own += nodes;
    largest = std::max(largest, nodes);
  }
  const double whole = largestGridNodes(plan, boundingBox(plan.Cloud), cellSizeFactor);
  if (!(own < 0.25 * whole))
  {
    return {};
  }
  std::ostringstream m;
  m.precision(3);
  m << "The cloud is " << boxes.size() << " groups of points more than " << PieceLinkFactor << " h_P ("
    << link * plan.Box.Scale << ") apart, and the grid spans the empty space between them (their own grids would "
    << "hold " << 100.0 * own / whole << "% of its nodes); " << why << ": reconstruct each group in its own run "
    << "(split the file), the largest group's grid " << largest << " nodes, about "
    << largest * ReconstructionBytesPerNode / 1e9 << " GB, at C_dx = " << cellSizeFactor;
  return m.str();
}

template std::string separateGroupsAdvice(const ReconstructionPlan<2>&, double, const std::string&);
template std::string separateGroupsAdvice(const ReconstructionPlan<3>&, double, const std::string&);

} // namespace sltk
