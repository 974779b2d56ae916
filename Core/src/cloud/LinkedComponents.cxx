// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/LinkedComponents.h"

#include "sltk/core/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace sltk
{

template <int D>
void linkWithinRadii(const PointLocator<D>& locator, const std::vector<double>& radius,
  const std::vector<std::uint8_t>* mine, std::vector<std::int64_t>& parent)
{
  const PointCloud<D>& cloud = locator.cloud();
  std::vector<std::int64_t> found;
  for (std::int64_t i = 0; i < cloud.size(); ++i)
  {
    if (mine && !(*mine)[static_cast<size_t>(i)])
    {
      continue;
    }
    // From each point out to its own radius: every pair is seen from its end with the larger one.
    locator.within(cloud.Points[static_cast<size_t>(i)], radius[static_cast<size_t>(i)], i, found);
    for (const std::int64_t j : found)
    {
      unite(parent, i, j);
    }
  }
}

namespace
{
constexpr std::int64_t NoLabel = std::numeric_limits<std::int64_t>::max();

/// Two components that hold one point: the labels of its owner's and of a rank holding it in its halo.
struct Meeting
{
  std::int64_t Low, High;
  bool operator<(const Meeting& o) const { return this->Low != o.Low ? this->Low < o.Low : this->High < o.High; }
  bool operator==(const Meeting& o) const { return this->Low == o.Low && this->High == o.High; }
};

/// `points` again with the halo `halo` (its owned points sent to their owners once more), and
/// `radius` carried to the new held points (read at the owned ones, the same set). Collective.
template <int D>
Status widenHalo(const OwnedPoints<D>& points, const std::vector<double>& radius, double halo, const Communicator& comm,
  OwnedPoints<D>& wider, std::vector<double>& widerRadius)
{
  std::vector<std::array<double, D>> own;
  std::vector<std::int64_t> ids;
  for (size_t j = 0; j < points.Mine.size(); ++j)
  {
    if (points.Mine[j])
    {
      own.push_back(points.Cloud.Points[j]);
      ids.push_back(points.Ids[j]);
    }
  }
  SLTK_RETURN_IF_ERROR(sendToOwners<D>(own, ids, points.Cuts, halo, comm, wider));
  widerRadius.assign(static_cast<size_t>(wider.held()), 0.0);
  for (size_t j = 0; j < wider.Mine.size(); ++j)
  {
    const std::int64_t was = wider.Mine[j] ? points.ownedLocal(wider.Ids[j]) : -1;
    widerRadius[j] = was >= 0 ? radius[static_cast<size_t>(was)] : 0.0;
  }
  return Status::ok();
}

/// The components' meetings across the ranks (pairs of local labels, every rank's)
/// joined: a forest over the labels they name, sorted ascending.
struct Meetings
{
  std::vector<std::int64_t> Labels; ///< every label an edge names, ascending
  std::vector<std::int64_t> Parent; ///< over Labels' positions
  std::vector<std::int64_t> Least;  ///< at each root: the position of its smallest label
  std::int64_t Joins = 0;           ///< the edges that joined two sets

  explicit Meetings(const std::vector<Meeting>& edges)
  {
    for (const Meeting& e : edges)
    {
      this->Labels.push_back(e.Low);
      this->Labels.push_back(e.High);
    }
    std::sort(this->Labels.begin(), this->Labels.end());
    this->Labels.erase(std::unique(this->Labels.begin(), this->Labels.end()), this->Labels.end());
    this->Parent = singletonForest<std::int64_t>(this->Labels.size());
    for (const Meeting& e : edges)
    {
      const std::int64_t a = findRoot(this->Parent, this->position(e.Low));
      const std::int64_t b = findRoot(this->Parent, this->position(e.High));
      if (a != b)
      {
        this->Parent[static_cast<size_t>(a)] = b;
        ++this->Joins;
      }
    }
    this->Least = singletonForest<std::int64_t>(this->Labels.size());
    for (std::int64_t j = static_cast<std::int64_t>(this->Labels.size()) - 1; j >= 0; --j)
    {
      this->Least[static_cast<size_t>(findRoot(this->Parent, j))] = j; // ascending labels: the last written is least
    }
  }

  /// The label of the joined component of a local component labelled `label`.
  std::int64_t joined(std::int64_t label)
  {
    const auto it = std::lower_bound(this->Labels.begin(), this->Labels.end(), label);
    if (it == this->Labels.end() || *it != label)
    {
      return label; // met no other rank's component
    }
    const std::int64_t root = findRoot(this->Parent, static_cast<std::int64_t>(it - this->Labels.begin()));
    return this->Labels[static_cast<size_t>(this->Least[static_cast<size_t>(root)])];
  }

private:
  std::int64_t position(std::int64_t label) const
  {
    return std::lower_bound(this->Labels.begin(), this->Labels.end(), label) - this->Labels.begin();
  }
};

/// The components of `points` linked by `radius` when the halo covers every radius.
template <int D>
Status componentsWithinHalo(
  const OwnedPoints<D>& points, const std::vector<double>& radius, const Communicator& comm, LinkedComponents& out)
{
  const size_t held = static_cast<size_t>(points.held());
  std::vector<std::int64_t> parent = singletonForest<std::int64_t>(held);
  if (held > 0)
  {
    const PointLocator<D> locator(points.Cloud);
    linkWithinRadii(locator, radius, &points.Mine, parent);
  }
  // A local component's label: the smallest global index among its own points.
  std::vector<std::int64_t> least(held, NoLabel);
  for (size_t j = 0; j < held; ++j)
  {
    if (points.Mine[j])
    {
      std::int64_t& l = least[static_cast<size_t>(findRoot(parent, static_cast<std::int64_t>(j)))];
      l = std::min(l, points.Ids[j]);
    }
  }
  std::int64_t local = 0;
  std::vector<double> heldLabel(held, 0.0);
  std::vector<NeighbourCandidate<D>> met; // halo points in a component with own points
  std::vector<std::int64_t> metLabel;
  for (size_t j = 0; j < held; ++j)
  {
    const std::int64_t label = least[static_cast<size_t>(findRoot(parent, static_cast<std::int64_t>(j)))];
    local += parent[j] == static_cast<std::int64_t>(j) && least[j] != NoLabel ? 1 : 0;
    heldLabel[j] = static_cast<double>(label); // exact: global indices below 2^53
    if (!points.Mine[j] && label != NoLabel)
    {
      met.push_back({ static_cast<std::int64_t>(met.size()), points.Ids[j], points.Cloud.Points[j] });
      metLabel.push_back(label);
    }
  }
  std::vector<double> theirs; // each met point's label on its owner
  SLTK_RETURN_IF_ERROR(valuesFromOwners(points, heldLabel, met, comm, theirs));
  std::vector<Meeting> edges;
  for (size_t m = 0; m < met.size(); ++m)
  {
    const std::int64_t other = static_cast<std::int64_t>(theirs[m]);
    if (other != metLabel[m])
    {
      edges.push_back({ std::min(other, metLabel[m]), std::max(other, metLabel[m]) });
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  auto all = comm.allGatherV(edges);
  std::sort(all.begin(), all.end()); // the same joins in the same order on every rank
  Meetings meetings(all);
  out.Count = comm.allReduce(local, ReduceOp::Sum) - meetings.Joins;
  out.Label.assign(held, -1);
  for (size_t j = 0; j < held; ++j)
  {
    if (points.Mine[j])
    {
      out.Label[j] = meetings.joined(static_cast<std::int64_t>(heldLabel[j]));
    }
  }
  return Status::ok();
}
} // namespace

template <int D>
Status linkedComponentsOnRanks(const OwnedPoints<D>& points, const std::vector<double>& radius,
  const Communicator& comm, const Context& /*ctx*/, LinkedComponents& out)
{
  out = LinkedComponents{};
  double largest = 0.0;
  std::int64_t bad = radius.size() == static_cast<size_t>(points.held()) ? 0 : 1;
  for (size_t j = 0; bad == 0 && j < radius.size(); ++j)
  {
    const bool usable = !points.Mine[j] || (std::isfinite(radius[j]) && radius[j] >= 0.0);
    bad += usable ? 0 : 1;
    largest = points.Mine[j] ? std::max(largest, radius[j]) : largest;
  }
  if (comm.allReduce(bad, ReduceOp::Sum) > 0)
  {
    return Status::invalidArgument(
      "the linked components need one finite radius >= 0 per held point: check the cloud's spacing");
  }
  // The halo must hold every point a link can reach, with the rounding of the
  // coordinates the exchange compared (a few units in the last place of the largest).
  double magnitude = 0.0;
  std::int64_t largestId = 0;
  for (size_t j = 0; j < points.Cloud.Points.size(); ++j)
  {
    const double x = std::fabs(points.Cloud.Points[j][static_cast<size_t>(points.Cuts.Axis)]);
    magnitude = std::isfinite(x) ? std::max(magnitude, x) : magnitude; // a non-finite point links nothing
    largestId = std::max(largestId, points.Ids[j]);
  }
  if (comm.allReduce(largestId, ReduceOp::Max) >= (std::int64_t(1) << 53))
  {
    return Status::invalidArgument("the linked components carry global indices as doubles: a cloud of more than "
                                   "2^53 points is not supported");
  }
  const double reach = comm.allReduce(largest, ReduceOp::Max) * (1.0 + 1e-9) +
    8.0 * std::numeric_limits<double>::epsilon() * comm.allReduce(magnitude, ReduceOp::Max);
  if (points.Halo >= reach)
  {
    return componentsWithinHalo(points, radius, comm, out);
  }
  OwnedPoints<D> wider;
  std::vector<double> widerRadius;
  SLTK_RETURN_IF_ERROR(widenHalo(points, radius, reach, comm, wider, widerRadius));
  LinkedComponents widened;
  SLTK_RETURN_IF_ERROR(componentsWithinHalo(wider, widerRadius, comm, widened));
  out.Count = widened.Count;
  out.Label.assign(static_cast<size_t>(points.held()), -1);
  for (size_t j = 0; j < wider.Mine.size(); ++j)
  {
    const std::int64_t was = wider.Mine[j] ? points.ownedLocal(wider.Ids[j]) : -1;
    if (was >= 0)
    {
      out.Label[static_cast<size_t>(was)] = widened.Label[j];
    }
  }
  return Status::ok();
}

template <int D>
Status groupBoxesOnRanks(const OwnedPoints<D>& points, double link, std::int64_t maxGroups, const Communicator& comm,
  const Context& ctx, std::vector<Box<D>>& boxes)
{
  boxes.clear();
  LinkedComponents groups;
  SLTK_RETURN_IF_ERROR(
    linkedComponentsOnRanks(points, std::vector<double>(static_cast<size_t>(points.held()), link), comm, ctx, groups));
  if (groups.Count < 2 || groups.Count > maxGroups)
  {
    return Status::ok(); // no rank holds more than maxGroups labels below
  }
  struct Labelled
  {
    std::int64_t Label;
    Box<D> Around;
  };
  std::map<std::int64_t, Box<D>> mine;
  const auto grow = [&mine](std::int64_t label, const Box<D>& b)
  {
    auto [it, created] = mine.try_emplace(label, b);
    for (int a = 0; a < D && !created; ++a)
    {
      it->second.Min[a] = std::min(it->second.Min[a], b.Min[a]);
      it->second.Max[a] = std::max(it->second.Max[a], b.Max[a]);
    }
  };
  for (size_t j = 0; j < points.Mine.size(); ++j)
  {
    if (points.Mine[j])
    {
      grow(groups.Label[j], Box<D>{ points.Cloud.Points[j], points.Cloud.Points[j] });
    }
  }
  std::vector<Labelled> local;
  for (const auto& [label, b] : mine)
  {
    local.push_back({ label, b });
  }
  mine.clear();
  for (const Labelled& l : comm.allGatherV(local))
  {
    grow(l.Label, l.Around);
  }
  for (const auto& entry : mine)
  {
    boxes.push_back(entry.second);
  }
  return Status::ok();
}

template <int D>
OwnedPoints<D> ownedOnOneRank(const PointCloud<D>& cloud)
{
  OwnedPoints<D> owned;
  owned.Cloud = cloud;
  owned.Ids.resize(static_cast<size_t>(cloud.size()));
  for (size_t j = 0; j < owned.Ids.size(); ++j)
  {
    owned.Ids[j] = static_cast<std::int64_t>(j);
  }
  owned.Mine.assign(owned.Ids.size(), 1);
  owned.Owned = cloud.size();
  owned.Halo = std::numeric_limits<double>::infinity();
  owned.Cuts.Lower = { -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity() };
  return owned;
}

template void linkWithinRadii(
  const PointLocator<2>&, const std::vector<double>&, const std::vector<std::uint8_t>*, std::vector<std::int64_t>&);
template void linkWithinRadii(
  const PointLocator<3>&, const std::vector<double>&, const std::vector<std::uint8_t>*, std::vector<std::int64_t>&);
template Status linkedComponentsOnRanks(
  const OwnedPoints<2>&, const std::vector<double>&, const Communicator&, const Context&, LinkedComponents&);
template Status linkedComponentsOnRanks(
  const OwnedPoints<3>&, const std::vector<double>&, const Communicator&, const Context&, LinkedComponents&);
template Status groupBoxesOnRanks(
  const OwnedPoints<2>&, double, std::int64_t, const Communicator&, const Context&, std::vector<Box<2>>&);
template Status groupBoxesOnRanks(
  const OwnedPoints<3>&, double, std::int64_t, const Communicator&, const Context&, std::vector<Box<3>>&);
template OwnedPoints<2> ownedOnOneRank(const PointCloud<2>&);
template OwnedPoints<3> ownedOnOneRank(const PointCloud<3>&);

} // namespace sltk
