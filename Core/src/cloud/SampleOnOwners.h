// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SampleOnOwners.h
/// A statistic of a sample of the cloud's points computed where the points
/// live (PointOwners.h): the owner of each sampled point answers a neighbour
/// query about it among the points it holds, and every rank receives the
/// answers in the sample's order, as one rank holding the whole cloud computes
/// them. The clouds' statistics without the whole cloud on every rank
/// (Documentation/Distributed.md, "Points to their owners").

#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Context.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace sltk
{

/// A query's answer about one point, and the farthest neighbour it read: the
/// answer is exact when the ball of that radius around the point stays short
/// of the halo's end along the axis (then no point held elsewhere could have
/// been as near); else the ranks it may reach answer it again.
struct OwnedAnswer
{
  double Value = 0.0;
  double Reach = 0.0; ///< +inf: too few points held to answer
};

/// Fails on every rank alike unless the ranks own `total` points together (a
/// sample index nobody owns would otherwise read as a duplicate). Collective.
template <int D>
Status checkTotal(const OwnedPoints<D>& points, std::int64_t total, const Communicator& comm)
{
  const std::int64_t owned = comm.allReduce(points.Owned, ReduceOp::Sum);
  if (owned != total)
  {
    return Status::invalidArgument("the ranks own " + std::to_string(owned) + " points together, not the " +
      std::to_string(total) + " of the cloud given");
  }
  return Status::ok();
}

/// The diameter of the box around every rank's points: a radius that reaches every point.
template <int D>
double cloudDiameter(const OwnedPoints<D>& points, const Communicator& comm)
{
  const Box<D> box = boundingBoxOverRanks(points.Cloud, comm);
  double d2 = 0.0;
  for (int a = 0; a < D; ++a)
  {
    d2 += box.extent(a) * box.extent(a);
  }
  return std::sqrt(d2) * 1.001 + std::numeric_limits<double>::min();
}

/// The query about request i's point, asked again among its nearest points
/// on every rank (`candidates`, from nearestOwnedOnRanks): the point and
/// them in increasing global index, as the whole cloud orders them. With
/// `found`, the first `neighbours` hits the query left, as candidates.
template <int D, class Query>
OwnedAnswer answerAmongCandidates(const NeighbourRequest<D>& request, const NeighbourCandidate<D>* first,
  const NeighbourCandidate<D>* last, Query& query, NeighbourCandidate<D>* found = nullptr)
{
  PointCloud<D> near;
  std::int64_t self = 0;
  for (const NeighbourCandidate<D>* c = first; c != last; ++c)
  {
    self += c->Id < request.Id ? 1 : 0;
  }
  near.Points.reserve(static_cast<size_t>(last - first) + 1);
  for (const NeighbourCandidate<D>* c = first; c != last; ++c)
  {
    if (static_cast<std::int64_t>(near.Points.size()) == self)
    {
      near.Points.push_back(request.X);
    }
    near.Points.push_back(c->X);
  }
  if (static_cast<std::int64_t>(near.Points.size()) == self)
  {
    near.Points.push_back(request.X);
  }
  const PointLocator<D> locator(near);
  std::vector<typename PointLocator<D>::Hit> hits;
  const OwnedAnswer answer = query(locator, self, hits);
  for (int j = 0; found && j < request.Neighbours && j < static_cast<int>(hits.size()); ++j)
  {
    const std::int64_t at = hits[static_cast<size_t>(j)].Index; // the point itself is at `self`
    found[j] = first[at < self ? at : at - 1];
  }
  return answer;
}

/// The answers of `query(locator, local, hits)` (an OwnedAnswer about held
/// point `local`, reading its `neighbours` nearest) about this rank's own
/// points at positions `locals` of points.Cloud, in their order, exactly as one rank holding
/// the whole cloud answers: a query that read beyond the halo is asked again
/// among the nearest points of every rank whose slab it reaches
/// (nearestOwnedOnRanks); `remote` counts those over every rank. With `found`,
/// also the `neighbours` nearest hits each query left (nearest first, the
/// point itself excluded by the query): `neighbours` candidates a point, their
/// Request its position in `locals`. `heldLocator`: one already built on
/// points.Cloud (else one is built here). Collective.
template <int D, class Query>
Status answerOnOwners(const OwnedPoints<D>& points, const std::vector<std::int64_t>& locals, int neighbours,
  const Communicator& comm, const Context& ctx, Query query, std::vector<double>& values, std::int64_t& remote,
  std::vector<NeighbourCandidate<D>>* found = nullptr, const PointLocator<D>* heldLocator = nullptr)
{
  values.assign(locals.size(), 0.0);
  std::vector<double> reach(locals.size(), 0.0);
  if (found)
  {
    found->assign(locals.size() * static_cast<size_t>(neighbours), NeighbourCandidate<D>{});
  }
  const auto keep = [&](size_t s, const std::vector<typename PointLocator<D>::Hit>& hits)
  {
    for (int j = 0; found && j < neighbours && j < static_cast<int>(hits.size()); ++j)
    {
      const size_t at = static_cast<size_t>(hits[static_cast<size_t>(j)].Index);
      (*found)[s * static_cast<size_t>(neighbours) + static_cast<size_t>(j)] = { static_cast<std::int64_t>(s),
        points.Ids[at], points.Cloud.Points[at] };
    }
  };
  if (!locals.empty())
  {
    std::unique_ptr<const PointLocator<D>> own;
    if (!heldLocator)
    {
      own = std::make_unique<const PointLocator<D>>(points.Cloud);
    }
    const PointLocator<D>& locator = heldLocator ? *heldLocator : *own;
    ctx.parallelFor(0, static_cast<Index>(locals.size()),
      [&](Index b, Index e)
      {
        std::vector<typename PointLocator<D>::Hit> hits;
        for (Index s = b; s < e; ++s)
        {
          const OwnedAnswer a = query(locator, locals[static_cast<size_t>(s)], hits);
          values[static_cast<size_t>(s)] = a.Value;
          reach[static_cast<size_t>(s)] = a.Reach;
          keep(static_cast<size_t>(s), hits);
        }
      });
  }
  // Exact when the ball the query read stays short of the halo's ends along the
  // axis, computed with the exchange's rounding (holdersOf): a point not held
  // lies at least that far along the axis. The margin makes it strict.
  std::vector<NeighbourRequest<D>> requests;
  std::vector<size_t> asking;
  const int axis = points.Cuts.Axis;
  const int me = comm.rank();
  for (size_t s = 0; s < locals.size(); ++s)
  {
    const auto& p = points.Cloud.Points[static_cast<size_t>(locals[s])];
    const double x = p[axis];
    const double below = points.Cuts.Lower[static_cast<size_t>(me)] - points.Halo;
    const double above = points.Cuts.Lower[static_cast<size_t>(me) + 1] + points.Halo;
    const double room = std::min(x - below, above - x); // +inf on one rank
    if (!(reach[s] * (1.0 + 1e-9) <= room))
    {
      requests.push_back({ p, points.Ids[static_cast<size_t>(locals[s])], reach[s], neighbours });
      asking.push_back(s);
    }
  }
  remote = comm.allReduce(static_cast<std::int64_t>(requests.size()), ReduceOp::Sum);
  if (remote == 0)
  {
    return Status::ok();
  }
  const double diameter = cloudDiameter(points, comm);
  for (auto& q : requests)
  {
    q.Radius = std::min(q.Radius, diameter); // +inf: this rank held too few points
  }
  std::vector<NeighbourCandidate<D>> candidates;
  SLTK_RETURN_IF_ERROR(nearestOwnedOnRanks(points, requests, comm, candidates));
  size_t c = 0;
  for (size_t i = 0; i < requests.size(); ++i)
  {
    const size_t first = c;
    while (c < candidates.size() && candidates[c].Request == static_cast<std::int64_t>(i))
    {
      ++c;
    }
    NeighbourCandidate<D>* nearest = found ? found->data() + asking[i] * static_cast<size_t>(neighbours) : nullptr;
    values[asking[i]] =
      answerAmongCandidates(requests[i], candidates.data() + first, candidates.data() + c, query, nearest).Value;
    for (int j = 0; nearest && j < neighbours; ++j)
    {
      nearest[j].Request = static_cast<std::int64_t>(asking[i]);
    }
  }
  return Status::ok();
}

/// The answers (answerOnOwners) about the points of global indices `sample`,
/// in the sample's order, on every rank: each owner answers about its own. Collective.
template <int D, class Query>
Status sampleOnOwners(const OwnedPoints<D>& points, const std::vector<std::int64_t>& sample, int neighbours,
  const Communicator& comm, const Context& ctx, Query query, std::vector<double>& values, std::int64_t& remote)
{
  struct Answered
  {
    std::int64_t Position;
    double Value;
  };
  std::vector<std::int64_t> position, locals; // this rank's sampled points
  for (size_t i = 0; i < sample.size(); ++i)
  {
    const std::int64_t j = points.ownedLocal(sample[i]);
    if (j >= 0)
    {
      position.push_back(static_cast<std::int64_t>(i));
      locals.push_back(j);
    }
  }
  std::vector<double> answers;
  SLTK_RETURN_IF_ERROR(answerOnOwners(points, locals, neighbours, comm, ctx, query, answers, remote));
  std::vector<Answered> mine(locals.size());
  for (size_t s = 0; s < locals.size(); ++s)
  {
    mine[s] = { position[s], answers[s] };
  }
  values.assign(sample.size(), 0.0);
  for (const Answered& a : comm.allGatherV(mine))
  {
    values[static_cast<size_t>(a.Position)] = a.Value;
  }
  return Status::ok();
}

} // namespace sltk
