// SPDX-License-Identifier: BSD-3-Clause
// A cloud of a few groups of points far apart (two objects in one file): whether its grid
// spans mostly empty space, and the advice of their own runs (ReconstructionPlan.h).
#include "sltk/recon/ReconstructionPlan.h"

#include "sltk/cloud/LinkedComponents.h"
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
constexpr std::int64_t MaxSeparateGroups = 16; ///< more groups than this: not "a few objects in one file"

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
  std::vector<Box<D>> boxes;
  const Status grouped = groupBoxesOnRanks(ownedOnOneRank(plan.Cloud), PieceLinkFactor * plan.CloudSpacing,
    MaxSeparateGroups, serialCommunicator(), Context{}, boxes);
  return grouped.isOk() && !boxes.empty()
    ? separateGroupsAdvice(plan, boxes, boundingBox(plan.Cloud), cellSizeFactor, why)
    : std::string{};
}

template <int D>
std::string separateGroupsAdvice(const ReconstructionPlan<D>& plan, const std::vector<Box<D>>& boxes,
  const Box<D>& cloudBox, double cellSizeFactor, const std::string& why)
{
  if (boxes.size() < 2)
  {
    return {};
  }
  const double link = PieceLinkFactor * plan.CloudSpacing;
  double own = 0.0, largest = 0.0;
  for (const Box<D>& box : boxes)
  {
    const double nodes = largestGridNodes(plan, box, cellSizeFactor);
    own += nodes;
    largest = std::max(largest, nodes);
  }
  const double whole = largestGridNodes(plan, cloudBox, cellSizeFactor);
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
template std::string separateGroupsAdvice(
  const ReconstructionPlan<2>&, const std::vector<Box<2>>&, const Box<2>&, double, const std::string&);
template std::string separateGroupsAdvice(
  const ReconstructionPlan<3>&, const std::vector<Box<3>>&, const Box<3>&, double, const std::string&);

} // namespace sltk
