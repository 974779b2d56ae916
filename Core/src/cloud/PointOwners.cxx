// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PointOwners.h"

#include "sltk/cloud/PointLocator.h"

#include "RankParts.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>

namespace sltk
{

int SlabCuts::ownerOf(double x) const
{
  // The last slab whose lower cut is at most x (Lower[0] = -inf holds every x).
  const auto above = std::upper_bound(this->Lower.begin() + 1, this->Lower.end() - 1, x);
  return static_cast<int>(above - this->Lower.begin()) - 1;
}

template <int D>
Box<D> boundingBoxOverRanks(const PointCloud<D>& local, const Communicator& comm)
{
  Box<D> box;
  box.Min.fill(std::numeric_limits<double>::infinity());
  box.Max.fill(-std::numeric_limits<double>::infinity());
  if (local.size() > 0)
  {
    box = boundingBox(local);
  }
  comm.allReduce(box.Min.data(), D, ReduceOp::Min);
  comm.allReduce(box.Max.data(), D, ReduceOp::Max);
  return box;
}

template Box<2> boundingBoxOverRanks(const PointCloud<2>&, const Communicator&);
template Box<3> boundingBoxOverRanks(const PointCloud<3>&, const Communicator&);

std::int64_t firstGlobalIndex(std::int64_t count, const Communicator& comm)
{
  std::vector<std::int64_t> counts(static_cast<size_t>(comm.size()));
  comm.allGather(&count, sizeof(count), counts.data());
  return std::accumulate(counts.begin(), counts.begin() + comm.rank(), std::int64_t(0));
}

namespace
{
constexpr int SamplesPerRank = 128;
constexpr double Infinity = std::numeric_limits<double>::infinity();

/// An order statistic of one rank's coordinates and the points it stands for.
struct WeightedSample
{
  double Value;
  double Weight;
};

/// The longest axis of the bounding box of every rank's points (the first of equal ones).
template <int D>
int longestAxis(const PointCloud<D>& local, const Communicator& comm)
{
  const Box<D> box = boundingBoxOverRanks(local, comm);
  int axis = 0;
  for (int a = 1; a < D; ++a)
  {
    axis = box.extent(a) > box.extent(axis) ? a : axis;
  }
  return axis;
}

/// One personalised all-to-all of records, `send` grouped by destination rank
/// (`counts` records each); `parts`: where each rank's records start.
template <class Record>
std::vector<Record> exchangeRecords(const std::vector<Record>& send, const std::vector<std::int64_t>& counts,
  const Communicator& comm, std::vector<size_t>& parts)
{
  std::vector<std::int64_t> received;
  std::vector<Record> records = comm.allToAllRecords(send, counts, &received);
  parts = startsOf(received);
  return records;
}

/// A point and its global index, as the exchange sends it.
template <int D>
struct PointRecord
{
  std::int64_t Id;
  std::array<double, D> X;
};

/// The ranks that hold coordinate x (its owner and the slabs within `halo`), in increasing order.
template <class Visit>
void holdersOf(double x, const SlabCuts& cuts, double halo, Visit visit)
{
  const int ranks = cuts.ranks();
  if (std::isinf(halo))
  {
    for (int r = 0; r < ranks; ++r)
    {
      visit(r);
    }
    return;
  }
  const int owner = cuts.ownerOf(x);
  int first = owner;
  while (first > 0 && x < cuts.Lower[static_cast<size_t>(first)] + halo) // within halo of slab first - 1
  {
    --first;
  }
  for (int r = first; r < owner; ++r)
  {
    visit(r);
  }
  visit(owner);
  for (int r = owner + 1; r < ranks && x >= cuts.Lower[static_cast<size_t>(r)] - halo; ++r)
  {
    visit(r);
  }
}

/// The exchange of sendToOwners and keepOwned: points with their global indices.
template <int D>
Status exchange(const std::vector<std::array<double, D>>& points, const std::vector<std::int64_t>& ids,
  const SlabCuts& cuts, double halo, const Communicator& comm, OwnedPoints<D>& out)
{
  if (cuts.ranks() != comm.size() || cuts.Axis < 0 || cuts.Axis >= D)
  {
    return Status::invalidArgument("the slab cuts are for " + std::to_string(cuts.ranks()) + " ranks, not the " +
      std::to_string(comm.size()) + " running");
  }
  for (size_t r = 1; r < cuts.Lower.size(); ++r)
  {
    if (!(cuts.Lower[r - 1] <= cuts.Lower[r])) // NaN fails too
    {
      return Status::invalidArgument("the slab cuts must be non-decreasing numbers");
    }
  }
  if (!(halo >= 0.0))
  {
    return Status::invalidArgument("the halo of the points' slabs must be >= 0");
  }
  const size_t ranks = static_cast<size_t>(comm.size());
  const int axis = cuts.Axis;
  // The points this rank keeps stay out of the exchange: a share read near its owner's slab
  // (a file written along the slabs' axis) moves little and is not copied twice more.
  const int me = comm.rank();
  std::vector<std::int64_t> counts;
  std::vector<PointRecord<D>> kept;
  std::vector<PointRecord<D>> send = groupByRank<PointRecord<D>>(
    ranks, counts,
    [&](const auto& emit)
    {
      for (size_t j = 0; j < points.size(); ++j)
      {
        holdersOf(points[j][axis], cuts, halo,
          [&](int r) {
            emit(static_cast<size_t>(r), [&](size_t) { return PointRecord<D>{ ids[j], points[j] }; });
          });
      }
    },
    me, &kept);
  std::vector<size_t> parts;
  std::vector<PointRecord<D>> records = exchangeRecords(send, counts, comm, parts);
  send = {};
  records.insert(records.end(), kept.begin(), kept.end());
  kept = {};
  // In increasing global index, whatever the shares were (a rank receives a point once).
  std::sort(
    records.begin(), records.end(), [](const PointRecord<D>& a, const PointRecord<D>& b) { return a.Id < b.Id; });
  out.Cloud.Points.resize(records.size());
  out.Ids.resize(records.size());
  out.Mine.resize(records.size());
  out.Owned = 0;
  for (size_t j = 0; j < records.size(); ++j)
  {
    out.Cloud.Points[j] = records[j].X;
    out.Ids[j] = records[j].Id;
    out.Mine[j] = cuts.ownerOf(records[j].X[axis]) == me ? 1 : 0;
    out.Owned += out.Mine[j];
  }
  out.Halo = cuts.ranks() == 1 ? Infinity : halo; // one rank holds every point
  out.Cuts = cuts;
  return Status::ok();
}
} // namespace

template <int D>
SlabCuts balancedCuts(const PointCloud<D>& cloud, const Communicator& comm)
{
  const std::vector<std::array<double, D>>& local = cloud.Points;
  SlabCuts cuts;
  cuts.Axis = longestAxis(cloud, comm);
  const int ranks = comm.size();
  cuts.Lower.assign(static_cast<size_t>(ranks) + 1, Infinity);
  cuts.Lower[0] = -Infinity;
  if (ranks == 1)
  {
    return cuts;
  }
  std::vector<double> x(local.size());
  for (size_t j = 0; j < local.size(); ++j)
  {
    x[j] = local[j][cuts.Axis];
  }
  std::sort(x.begin(), x.end());
  const size_t samples = std::min<size_t>(SamplesPerRank, x.size());
  std::vector<WeightedSample> mine(samples);
  for (size_t s = 0; s < samples; ++s)
  {
    // The middle of the s-th of `samples` equal runs of the sorted coordinates.
    const size_t at = static_cast<size_t>((static_cast<double>(s) + 0.5) * static_cast<double>(x.size()) / samples);
    mine[s] = { x[std::min(at, x.size() - 1)], static_cast<double>(x.size()) / static_cast<double>(samples) };
  }
  std::vector<WeightedSample> all = comm.allGatherV(mine);
  std::sort(all.begin(), all.end(), [](const WeightedSample& a, const WeightedSample& b) { return a.Value < b.Value; });
  double total = 0.0;
  for (const WeightedSample& s : all)
  {
    total += s.Weight;
  }
  double before = 0.0; // the weight of the samples below the current one
  size_t k = 0;
  for (int r = 1; r < ranks; ++r)
  {
    const double target = total * r / ranks;
    while (k < all.size() && before + all[k].Weight < target)
    {
      before += all[k++].Weight;
    }
    cuts.Lower[static_cast<size_t>(r)] = k < all.size() ? all[k].Value : Infinity;
  }
  return cuts;
}

template <int D>
Status sendToOwners(const PointCloud<D>& local, std::int64_t firstId, const SlabCuts& cuts, double halo,
  const Communicator& comm, OwnedPoints<D>& out)
{
  std::vector<std::int64_t> ids(local.Points.size());
  std::iota(ids.begin(), ids.end(), firstId);
  return exchange<D>(local.Points, ids, cuts, halo, comm, out);
}

template <int D>
Status sendToOwners(const std::vector<std::array<double, D>>& points, const std::vector<std::int64_t>& ids,
  const SlabCuts& cuts, double halo, const Communicator& comm, OwnedPoints<D>& out)
{
  SLTK_RETURN_IF_ERROR(comm.agree(points.size() == ids.size()
      ? Status::ok()
      : Status::invalidArgument("sendToOwners: one global index per point is needed")));
  return exchange<D>(points, ids, cuts, halo, comm, out);
}

namespace
{
/// A request as it travels: its index on the asking rank.
template <int D>
struct RequestRecord
{
  std::array<double, D> X;
  double Radius;
  std::int64_t Id;
  std::int64_t Request;
  std::int64_t Neighbours;
};

/// The owned points nearest to a request's point (its Neighbours, with ties), from the held points' locator.
template <int D>
void answerRequest(const OwnedPoints<D>& points, const PointLocator<D>& locator, const RequestRecord<D>& q,
  std::vector<std::int64_t>& found, std::vector<std::pair<double, std::int64_t>>& near)
{
  locator.within(q.X, std::nextafter(q.Radius, Infinity), -1, found);
  near.clear();
  for (const std::int64_t j : found)
  {
    if (points.Mine[static_cast<size_t>(j)] && points.Ids[static_cast<size_t>(j)] != q.Id)
    {
      double d2 = 0.0;
      for (int a = 0; a < D; ++a)
      {
        const double t = points.Cloud.Points[static_cast<size_t>(j)][a] - q.X[a];
        d2 += t * t;
      }
      near.push_back({ d2, j });
    }
  }
  std::sort(near.begin(), near.end());
  // The k nearest and every point as near as the k-th (a margin for another rounding of the distance).
  size_t keep = std::min(near.size(), static_cast<size_t>(q.Neighbours));
  const double last = keep > 0 ? near[keep - 1].first * (1.0 + 1e-12) : 0.0;
  while (keep < near.size() && near[keep].first <= last)
  {
    ++keep;
  }
  near.resize(keep);
}
} // namespace

template <int D>
Status nearestOwnedOnRanks(const OwnedPoints<D>& points, const std::vector<NeighbourRequest<D>>& requests,
  const Communicator& comm, std::vector<NeighbourCandidate<D>>& candidates)
{
  const size_t ranks = static_cast<size_t>(comm.size());
  const int axis = points.Cuts.Axis;
  // To the ranks whose slabs come within Radius of X along the axis.
  const auto reached = [&](const NeighbourRequest<D>& q, int& first, int& last)
  {
    // A neighbour at distance Radius may lie past the rounded X -+ Radius along the axis: a margin.
    const double margin = (std::fabs(q.X[axis]) + q.Radius) * 1e-12;
    first = points.Cuts.ownerOf(q.X[axis] - q.Radius - margin);
    last = points.Cuts.ownerOf(q.X[axis] + q.Radius + margin);
  };
  std::vector<std::int64_t> counts;
  const std::vector<RequestRecord<D>> send = groupByRank<RequestRecord<D>>(ranks, counts,
    [&](const auto& emit)
    {
      for (size_t i = 0; i < requests.size(); ++i)
      {
        const auto& q = requests[i];
        int first = 0, last = 0;
        reached(q, first, last);
        for (int r = first; r <= last; ++r)
        {
          emit(static_cast<size_t>(r),
            [&](size_t) {
              return RequestRecord<D>{ q.X, q.Radius, q.Id, static_cast<std::int64_t>(i), q.Neighbours };
            });
        }
      }
    });
  std::vector<size_t> parts;
  const std::vector<RequestRecord<D>> asked = exchangeRecords(send, counts, comm, parts);
  // Each request's nearest owned points, back to the rank that asked.
  std::vector<NeighbourCandidate<D>> answers;
  std::fill(counts.begin(), counts.end(), 0);
  if (!asked.empty() && points.held() > 0)
  {
    const PointLocator<D> locator(points.Cloud);
    std::vector<std::int64_t> found;
    std::vector<std::pair<double, std::int64_t>> near;
    for (size_t r = 0; r < ranks; ++r)
    {
      for (size_t m = parts[r]; m < parts[r + 1]; ++m)
      {
        answerRequest(points, locator, asked[m], found, near);
        for (const auto& n : near)
        {
          answers.push_back({ asked[m].Request, points.Ids[static_cast<size_t>(n.second)],
            points.Cloud.Points[static_cast<size_t>(n.second)] });
        }
        counts[r] += static_cast<std::int64_t>(near.size());
      }
    }
  }
  candidates = exchangeRecords(answers, counts, comm, parts);
  std::sort(candidates.begin(), candidates.end(),
    [](const NeighbourCandidate<D>& a, const NeighbourCandidate<D>& b)
    { return a.Request != b.Request ? a.Request < b.Request : a.Id < b.Id; });
  return Status::ok();
}

template <int D>
Status keepOwned(
  OwnedPoints<D>& points, const std::vector<std::uint8_t>& keep, const Communicator& comm, std::int64_t& dropped)
{
  std::vector<std::int64_t> gone;
  for (size_t j = 0; j < points.Ids.size(); ++j)
  {
    if (points.Mine[j] && !keep[j])
    {
      gone.push_back(points.Ids[j]);
    }
  }
  std::vector<std::int64_t> all = comm.allGatherV(gone);
  std::sort(all.begin(), all.end());
  dropped = static_cast<std::int64_t>(all.size());
  std::vector<std::array<double, D>> mine;
  std::vector<std::int64_t> ids;
  for (size_t j = 0; j < points.Ids.size(); ++j)
  {
    if (points.Mine[j] && keep[j])
    {
      mine.push_back(points.Cloud.Points[j]);
      ids.push_back(points.Ids[j] - (std::lower_bound(all.begin(), all.end(), points.Ids[j]) - all.begin()));
    }
  }
  const SlabCuts cuts = points.Cuts;
  return exchange<D>(mine, ids, cuts, points.Halo, comm, points);
}

template <int D>
Status valuesFromOwners(const OwnedPoints<D>& points, const std::vector<double>& held,
  const std::vector<NeighbourCandidate<D>>& wanted, const Communicator& comm, std::vector<double>& out)
{
  SLTK_RETURN_IF_ERROR(comm.agree(points.Cuts.ranks() == comm.size()
      ? Status::ok()
      : Status::invalidArgument("valuesFromOwners: the points' cuts are not for the ranks running")));
  const size_t ranks = static_cast<size_t>(comm.size());
  const int me = comm.rank();
  const double missing = std::numeric_limits<double>::quiet_NaN();
  bool found = held.size() == points.Ids.size();
  const auto lookUp = [&](std::int64_t id)
  {
    const std::int64_t j = points.ownedLocal(id);
    found = found && j >= 0;
    return j >= 0 && found ? held[static_cast<size_t>(j)] : missing;
  };
  out.assign(wanted.size(), missing);
  std::vector<int> owner(wanted.size());
  for (size_t i = 0; i < wanted.size(); ++i)
  {
    owner[i] = points.Cuts.ownerOf(wanted[i].X[static_cast<size_t>(points.Cuts.Axis)]);
    if (owner[i] == me)
    {
      out[i] = lookUp(wanted[i].Id);
    }
  }
  // The others' indices to each owner in `wanted`'s order (asked[slot]: their place there);
  // the values come back in the order asked.
  std::vector<size_t> asked(wanted.size());
  std::vector<std::int64_t> counts;
  const std::vector<std::int64_t> send = groupByRank<std::int64_t>(ranks, counts,
    [&](const auto& emit)
    {
      for (size_t i = 0; i < wanted.size(); ++i)
      {
        if (owner[i] != me)
        {
          emit(static_cast<size_t>(owner[i]),
            [&](size_t slot)
            {
              asked[slot] = i;
              return wanted[i].Id;
            });
        }
      }
    });
  std::vector<size_t> parts;
  const std::vector<std::int64_t> ids = exchangeRecords(send, counts, comm, parts);
  std::vector<double> answers(ids.size());
  for (size_t m = 0; m < ids.size(); ++m)
  {
    answers[m] = lookUp(ids[m]);
  }
  for (size_t r = 0; r < ranks; ++r)
  {
    counts[r] = static_cast<std::int64_t>(parts[r + 1] - parts[r]);
  }
  const std::vector<double> values = exchangeRecords(answers, counts, comm, parts);
  for (size_t m = 0; m < values.size(); ++m)
  {
    out[asked[m]] = values[m];
  }
  return comm.agree(found ? Status::ok()
                          : Status::invalidArgument("valuesFromOwners: a point is not owned where its place says, or "
                                                    "the values are not one per held point"));
}

template <int D>
NearestOverRanks<D>::NearestOverRanks(const OwnedPoints<D>& points)
  : Points(points)
{
  if (points.held() > 0)
  {
    this->Locator = std::make_unique<PointLocator<D>>(points.Cloud);
  }
}

template <int D>
NearestOverRanks<D>::~NearestOverRanks() = default;

template <int D>
void NearestOverRanks<D>::find(const std::vector<std::array<double, D>>& queries, double radius,
  const Communicator& comm, const Context& ctx, std::vector<double>& distance, std::vector<std::int64_t>& ids) const
{
  constexpr std::int64_t None = std::numeric_limits<std::int64_t>::max();
  distance.assign(queries.size(), Infinity);
  ids.assign(queries.size(), None);
  // The nearest of every rank for the queries `asked`, `bounded` within the radius.
  const auto answer = [&](const std::vector<size_t>& asked, bool bounded)
  {
    std::vector<double> d(asked.size(), Infinity);
    std::vector<std::int64_t> id(asked.size(), None);
    if (this->Locator)
    {
      ctx.parallelFor(0, static_cast<Index>(asked.size()),
        [&](Index b, Index e)
        {
          for (Index q = b; q < e; ++q)
          {
            const auto& x = queries[asked[static_cast<size_t>(q)]];
            const auto hit = bounded ? this->Locator->nearestWithin(x, radius) : this->Locator->nearest(x);
            d[static_cast<size_t>(q)] = hit.Distance;
            id[static_cast<size_t>(q)] = hit.Index >= 0 ? this->Points.Ids[static_cast<size_t>(hit.Index)] : None;
          }
        });
    }
    std::vector<double> least(d);
    comm.allReduce(least.data(), least.size(), ReduceOp::Min);
    for (size_t q = 0; q < asked.size(); ++q)
    {
      id[q] = d[q] == least[q] ? id[q] : None;
    }
    comm.allReduce(id.data(), id.size(), ReduceOp::Min);
    for (size_t q = 0; q < asked.size(); ++q)
    {
      distance[asked[q]] = least[q];
      ids[asked[q]] = id[q];
    }
  };
  std::vector<size_t> asked(queries.size());
  std::iota(asked.begin(), asked.end(), size_t(0));
  answer(asked, true);
  asked.clear();
  for (size_t q = 0; q < queries.size(); ++q)
  {
    if (ids[q] == None)
    {
      asked.push_back(q); // the same on every rank: after the reductions
    }
  }
  if (!asked.empty() && comm.allReduce(this->Points.Owned, ReduceOp::Sum) > 0)
  {
    answer(asked, false);
  }
  for (auto& id : ids)
  {
    id = id == None ? -1 : id;
  }
}

template <int D>
void nearestOverRanks(const OwnedPoints<D>& points, const std::vector<std::array<double, D>>& queries, double radius,
  const Communicator& comm, const Context& ctx, std::vector<double>& distance, std::vector<std::int64_t>& ids)
{
  NearestOverRanks<D>(points).find(queries, radius, comm, ctx, distance, ids);
}

namespace
{
/// A point, its global index and its value, as pointsInIntervals sends them.
template <int D>
struct ValuedPointRecord
{
  std::int64_t Id;
  std::array<double, D> X;
  double Value;
};

/// One rank's interval of pointsInIntervals, and its axis.
struct Interval
{
  double Low, High;
  std::int64_t Axis;
};

/// Calls visit(r) for every rank r whose interval holds x, in increasing r: by a
/// search from the first interval that ends at or after x when the intervals'
/// both ends grow with the rank (the windows of a run's slabs), else one by one.
template <class Visit>
void intervalsHolding(double x, const std::vector<Interval>& intervals, bool ordered, Visit visit)
{
  size_t r = 0;
  if (ordered)
  {
    r = static_cast<size_t>(
      std::lower_bound(intervals.begin(), intervals.end(), x, [](const Interval& i, double v) { return i.High < v; }) -
      intervals.begin());
  }
  for (; r < intervals.size() && !(ordered && intervals[r].Low > x); ++r)
  {
    if (intervals[r].Low <= x && x <= intervals[r].High)
    {
      visit(static_cast<int>(r));
    }
  }
}
} // namespace

template <int D>
Status pointsInIntervals(const OwnedPoints<D>& points, const std::vector<double>& values, int axis, double low,
  double high, const Communicator& comm, PointsInInterval<D>& out)
{
  out = PointsInInterval<D>{};
  const bool valued = comm.anyRank(!values.empty());
  const bool usable = axis >= 0 && axis < D && !std::isnan(low) && !std::isnan(high) &&
    (!valued || values.size() == static_cast<size_t>(points.held()));
  SLTK_RETURN_IF_ERROR(comm.agree(usable ? Status::ok()
                                         : Status::invalidArgument("pointsInIntervals: the axis is out of range, a "
                                                                   "bound is NaN or the values are not one per held "
                                                                   "point on every rank")));
  std::vector<Interval> intervals(static_cast<size_t>(comm.size()));
  const Interval mine{ low, high, axis };
  comm.allGather(&mine, sizeof(Interval), intervals.data());
  for (const Interval& i : intervals) // every rank sees the same intervals: the same verdict without a reduction
  {
    if (i.Axis != axis)
    {
      return Status::invalidArgument("pointsInIntervals: the ranks' intervals are along different axes");
    }
  }
  bool ordered = true;
  for (size_t r = 1; r < intervals.size(); ++r)
  {
    ordered = ordered && intervals[r].Low >= intervals[r - 1].Low && intervals[r].High >= intervals[r - 1].High;
  }
  const size_t ranks = intervals.size();
  std::vector<std::int64_t> counts;
  const std::vector<ValuedPointRecord<D>> send = groupByRank<ValuedPointRecord<D>>(ranks, counts,
    [&](const auto& emit)
    {
      for (size_t j = 0; j < points.Mine.size(); ++j)
      {
        if (points.Mine[j])
        {
          intervalsHolding(points.Cloud.Points[j][static_cast<size_t>(axis)], intervals, ordered,
            [&](int r)
            {
              emit(static_cast<size_t>(r),
                [&](size_t) {
                  return ValuedPointRecord<D>{ points.Ids[j], points.Cloud.Points[j], valued ? values[j] : 0.0 };
                });
            });
        }
      }
    });
  std::vector<size_t> parts;
  std::vector<ValuedPointRecord<D>> records = exchangeRecords(send, counts, comm, parts);
  std::sort(records.begin(), records.end(),
    [](const ValuedPointRecord<D>& a, const ValuedPointRecord<D>& b) { return a.Id < b.Id; });
  out.Cloud.Points.resize(records.size());
  out.Ids.resize(records.size());
  out.Values.resize(valued ? records.size() : 0);
  for (size_t j = 0; j < records.size(); ++j)
  {
    out.Cloud.Points[j] = records[j].X;
    out.Ids[j] = records[j].Id;
    if (valued)
    {
      out.Values[j] = records[j].Value;
    }
  }
  return Status::ok();
}

template <int D>
std::int64_t OwnedPoints<D>::ownedLocal(std::int64_t id) const
{
  const auto it = std::lower_bound(this->Ids.begin(), this->Ids.end(), id);
  const std::int64_t j = it - this->Ids.begin();
  return it != this->Ids.end() && *it == id && this->Mine[static_cast<size_t>(j)] ? j : -1;
}

template Status keepOwned(OwnedPoints<2>&, const std::vector<std::uint8_t>&, const Communicator&, std::int64_t&);
template Status keepOwned(OwnedPoints<3>&, const std::vector<std::uint8_t>&, const Communicator&, std::int64_t&);
template Status valuesFromOwners(const OwnedPoints<2>&, const std::vector<double>&,
  const std::vector<NeighbourCandidate<2>>&, const Communicator&, std::vector<double>&);
template Status valuesFromOwners(const OwnedPoints<3>&, const std::vector<double>&,
  const std::vector<NeighbourCandidate<3>>&, const Communicator&, std::vector<double>&);
template void nearestOverRanks<2>(const OwnedPoints<2>&, const std::vector<std::array<double, 2>>&, double,
  const Communicator&, const Context&, std::vector<double>&, std::vector<std::int64_t>&);
template void nearestOverRanks<3>(const OwnedPoints<3>&, const std::vector<std::array<double, 3>>&, double,
  const Communicator&, const Context&, std::vector<double>&, std::vector<std::int64_t>&);
template Status pointsInIntervals(
  const OwnedPoints<2>&, const std::vector<double>&, int, double, double, const Communicator&, PointsInInterval<2>&);
template Status pointsInIntervals(
  const OwnedPoints<3>&, const std::vector<double>&, int, double, double, const Communicator&, PointsInInterval<3>&);
template class NearestOverRanks<2>;
template class NearestOverRanks<3>;
template struct OwnedPoints<2>;
template struct OwnedPoints<3>;
template Status sendToOwners<2>(const std::vector<std::array<double, 2>>&, const std::vector<std::int64_t>&,
  const SlabCuts&, double, const Communicator&, OwnedPoints<2>&);
template Status sendToOwners<3>(const std::vector<std::array<double, 3>>&, const std::vector<std::int64_t>&,
  const SlabCuts&, double, const Communicator&, OwnedPoints<3>&);
template SlabCuts balancedCuts(const PointCloud<2>&, const Communicator&);
template SlabCuts balancedCuts(const PointCloud<3>&, const Communicator&);
template Status sendToOwners(
  const PointCloud<2>&, std::int64_t, const SlabCuts&, double, const Communicator&, OwnedPoints<2>&);
template Status sendToOwners(
  const PointCloud<3>&, std::int64_t, const SlabCuts&, double, const Communicator&, OwnedPoints<3>&);
template Status nearestOwnedOnRanks(const OwnedPoints<2>&, const std::vector<NeighbourRequest<2>>&, const Communicator&,
  std::vector<NeighbourCandidate<2>>&);
template Status nearestOwnedOnRanks(const OwnedPoints<3>&, const std::vector<NeighbourRequest<3>>&, const Communicator&,
  std::vector<NeighbourCandidate<3>>&);

} // namespace sltk
