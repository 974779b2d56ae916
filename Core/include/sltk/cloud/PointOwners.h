// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PointOwners.h
/// A cloud spread over the ranks by slabs along one axis, each point on the
/// rank that owns its slab, with a halo of the neighbouring slabs' points
/// (Documentation/Distributed.md, "Points to their owners"): the shares a
/// parallel read leaves on the ranks (in file order, CloudFileShares.h) move
/// by one personalised all-to-all, each point with its global index (its
/// place in the file), so that every rank can answer neighbour queries about
/// its own points without the whole cloud.
///
/// A point this rank does not hold lies, along the axis, at least as far from
/// an owned point as the halo's end beyond that point's slab (computed with
/// the rounding the exchange used), so a neighbour query about an owned point
/// whose ball stays short of that end is exact; the others are asked again of
/// the ranks the ball reaches (nearestOwnedOnRanks).

#include "sltk/cloud/PointCloud.h"
#include "sltk/core/Status.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace sltk
{

template <int D>
class PointLocator;

/// The slabs of the ranks: rank r owns the points with Lower[r] <= x_Axis <
/// Lower[r + 1] (Lower[0] = -inf, Lower[size] = +inf).
struct SlabCuts
{
  int Axis = 0;
  std::vector<double> Lower;

  int ranks() const { return static_cast<int>(this->Lower.size()) - 1; }
  /// The rank whose slab holds coordinate x along Axis.
  int ownerOf(double x) const;
};

/// The points one rank holds, its own and its halo, in increasing global
/// index as the whole cloud holds them (so that a neighbour query breaks ties
/// by index as on one rank): Ids[j] is the global index of Cloud.Points[j],
/// Mine[j] whether this rank owns it.
template <int D>
struct OwnedPoints
{
  PointCloud<D> Cloud;
  std::vector<std::int64_t> Ids;
  std::vector<std::uint8_t> Mine;
  std::int64_t Owned = 0; ///< the points this rank owns (Mine's count)
  double Halo = 0.0; ///< the held points are those within Halo of the slab along the axis (+inf: all, as on one rank)
  SlabCuts Cuts;

  std::int64_t held() const { return this->Cloud.size(); }
  /// The position in Cloud of the point with global index `id` when this rank owns it, else -1.
  std::int64_t ownedLocal(std::int64_t id) const;
};

/// Cuts along the longest axis of the cloud's bounding box that give the
/// ranks about equal numbers of points (within about 1% on clouds much larger
/// than 128 points per rank): every rank's `local` points (any share of the
/// cloud) contribute 128 regularly spaced order statistics, weighted by the
/// points they stand for, and the cuts fall where the weights add up to
/// multiples of 1/size. Collective; the same cuts on every rank.
template <int D>
SlabCuts balancedCuts(const PointCloud<D>& local, const Communicator& comm);

/// Moves every rank's `local` points (global indices firstId, firstId + 1, ...)
/// to their owners under `cuts` (non-decreasing, for the ranks running), with
/// the points within `halo` (>= 0, +inf for every point on every rank) of each
/// slab as its halo. Collective.
template <int D>
Status sendToOwners(const PointCloud<D>& local, std::int64_t firstId, const SlabCuts& cuts, double halo,
  const Communicator& comm, OwnedPoints<D>& out);

/// The same for points that already carry their global indices (`ids`, one a
/// point; a rank may send points it does not own, as after thinning). Collective.
template <int D>
Status sendToOwners(const std::vector<std::array<double, D>>& points, const std::vector<std::int64_t>& ids,
  const SlabCuts& cuts, double halo, const Communicator& comm, OwnedPoints<D>& out);

/// A question about the neighbours of a point this rank owns that the points
/// it holds may not answer: the neighbours of X (the point of global index Id)
/// within Radius.
template <int D>
struct NeighbourRequest
{
  std::array<double, D> X;
  std::int64_t Id;
  double Radius;
  int Neighbours;
};

/// A neighbour of request Request's point: its global index and place.
template <int D>
struct NeighbourCandidate
{
  std::int64_t Request;
  std::int64_t Id;
  std::array<double, D> X;
};

/// For every request of this rank, the Neighbours nearest points to X no
/// farther than Radius among the points each rank owns (with the points tied
/// with the farthest of them), except the point itself: the ranks whose slabs
/// come within Radius of X (a margin for the rounding of X +- Radius) answer,
/// so `candidates` (ordered by request, then global index) hold the cloud's
/// nearest neighbours of X whenever Radius reaches at least that far. Collective.
template <int D>
Status nearestOwnedOnRanks(const OwnedPoints<D>& points, const std::vector<NeighbourRequest<D>>& requests,
  const Communicator& comm, std::vector<NeighbourCandidate<D>>& candidates);

/// Keeps the points this rank owns whose flag in `keep` (one per held point)
/// is set: the others leave the cloud, every kept point takes its index in the
/// kept cloud (its index less the points dropped before it: the dropped
/// indices, 8 bytes each, are gathered on every rank), and the halo is sent again. `dropped`: the points dropped on
/// every rank. Collective.
template <int D>
Status keepOwned(
  OwnedPoints<D>& points, const std::vector<std::uint8_t>& keep, const Communicator& comm, std::int64_t& dropped);

/// The values `held` (one per held point, read at the owned ones) that the
/// owners of the points `wanted` (their global indices and places, such as a
/// neighbour query's candidates) hold: out[i] for wanted[i]. A point's owner
/// is the rank of its slab, so one all-to-all asks and one answers.
/// Collective; fails on every rank when a point is not owned where its place says.
template <int D>
Status valuesFromOwners(const OwnedPoints<D>& points, const std::vector<double>& held,
  const std::vector<NeighbourCandidate<D>>& wanted, const Communicator& comm, std::vector<double>& out);

/// The points every rank owns with their coordinate along one axis in an
/// interval of this rank's, each with a value (pointsInIntervals).
template <int D>
struct PointsInInterval
{
  PointCloud<D> Cloud;           ///< in increasing global index
  std::vector<std::int64_t> Ids; ///< their global indices
  std::vector<double> Values;    ///< one a point; empty when no values were given
};

/// The points every rank owns whose coordinate along `axis` lies in this
/// rank's [low, high] (each rank its own interval, such as the rows a run's
/// window reads, recon/RunPoints.h), with their values (`values`: one per held
/// point, read at the owned ones; empty: none), in increasing global index,
/// the order of the whole cloud. Each point goes to the ranks whose intervals
/// hold it, by one all-to-all (the intervals, 16 bytes a rank, are gathered
/// first). Collective; fails on every rank for an axis out of range or not the
/// same on every rank, a NaN bound or values not one per held point.
template <int D>
Status pointsInIntervals(const OwnedPoints<D>& points, const std::vector<double>& values, int axis, double low,
  double high, const Communicator& comm, PointsInInterval<D>& out);

/// The nearest point to each of `queries` (the same on every rank) among
/// every rank's own points, ties by the lowest global index (one rank's
/// PointLocator rule): `distance` and `ids` (+inf and -1 when no rank owns a
/// point), the same on every rank. Each rank searches its points within
/// `radius` (PointLocator::nearestWithin: a query far from a rank's slab costs
/// little there); the queries no rank answers within it are searched again
/// without bound. Two reductions of one value a query (and two more for those).
/// Collective.
template <int D>
void nearestOverRanks(const OwnedPoints<D>& points, const std::vector<std::array<double, D>>& queries, double radius,
  const Communicator& comm, const Context& ctx, std::vector<double>& distance, std::vector<std::int64_t>& ids);

/// nearestOverRanks() for queries that come in batches: the locator of this
/// rank's points is made once. It reads every point the rank holds, its halo
/// too: a halo point is also held by its owner with the same coordinates, so
/// the least distance over the ranks is the same; and since a rank's points
/// are in increasing global index (OwnedPoints), its locator's tie rule (the
/// lowest position) gives its lowest global index at that distance, so the
/// lowest over the ranks is too. `points` must outlive it.
template <int D>
class NearestOverRanks
{
public:
  explicit NearestOverRanks(const OwnedPoints<D>& points);
  explicit NearestOverRanks(const OwnedPoints<D>&&) = delete; // it would outlive them
  ~NearestOverRanks();
  NearestOverRanks(const NearestOverRanks&) = delete;
  NearestOverRanks& operator=(const NearestOverRanks&) = delete;

  /// nearestOverRanks() of `queries` (the same on every rank). Collective.
  void find(const std::vector<std::array<double, D>>& queries, double radius, const Communicator& comm,
    const Context& ctx, std::vector<double>& distance, std::vector<std::int64_t>& ids) const;

private:
  const OwnedPoints<D>& Points;
  std::unique_ptr<PointLocator<D>> Locator;
};

/// The box around every rank's `local` points (inverted, +inf to -inf, when
/// no rank has any): boundingBox() over the ranks. Collective.
template <int D>
Box<D> boundingBoxOverRanks(const PointCloud<D>& local, const Communicator& comm);

/// The global index of this rank's first point when every rank holds `count`
/// consecutive points in rank order (an exclusive prefix sum). Collective.
std::int64_t firstGlobalIndex(std::int64_t count, const Communicator& comm);

extern template SlabCuts balancedCuts(const PointCloud<2>&, const Communicator&);
extern template SlabCuts balancedCuts(const PointCloud<3>&, const Communicator&);
extern template Status sendToOwners(
  const PointCloud<2>&, std::int64_t, const SlabCuts&, double, const Communicator&, OwnedPoints<2>&);
extern template Status sendToOwners(
  const PointCloud<3>&, std::int64_t, const SlabCuts&, double, const Communicator&, OwnedPoints<3>&);
extern template Status sendToOwners<2>(const std::vector<std::array<double, 2>>&, const std::vector<std::int64_t>&,
  const SlabCuts&, double, const Communicator&, OwnedPoints<2>&);
extern template Status sendToOwners<3>(const std::vector<std::array<double, 3>>&, const std::vector<std::int64_t>&,
  const SlabCuts&, double, const Communicator&, OwnedPoints<3>&);
extern template Status nearestOwnedOnRanks(const OwnedPoints<2>&, const std::vector<NeighbourRequest<2>>&,
  const Communicator&, std::vector<NeighbourCandidate<2>>&);
extern template Status nearestOwnedOnRanks(const OwnedPoints<3>&, const std::vector<NeighbourRequest<3>>&,
  const Communicator&, std::vector<NeighbourCandidate<3>>&);
extern template Status keepOwned(OwnedPoints<2>&, const std::vector<std::uint8_t>&, const Communicator&, std::int64_t&);
extern template Status keepOwned(OwnedPoints<3>&, const std::vector<std::uint8_t>&, const Communicator&, std::int64_t&);
extern template Status valuesFromOwners(const OwnedPoints<2>&, const std::vector<double>&,
  const std::vector<NeighbourCandidate<2>>&, const Communicator&, std::vector<double>&);
extern template Status valuesFromOwners(const OwnedPoints<3>&, const std::vector<double>&,
  const std::vector<NeighbourCandidate<3>>&, const Communicator&, std::vector<double>&);
extern template void nearestOverRanks<2>(const OwnedPoints<2>&, const std::vector<std::array<double, 2>>&, double,
  const Communicator&, const Context&, std::vector<double>&, std::vector<std::int64_t>&);
extern template void nearestOverRanks<3>(const OwnedPoints<3>&, const std::vector<std::array<double, 3>>&, double,
  const Communicator&, const Context&, std::vector<double>&, std::vector<std::int64_t>&);
extern template Status pointsInIntervals(
  const OwnedPoints<2>&, const std::vector<double>&, int, double, double, const Communicator&, PointsInInterval<2>&);
extern template Status pointsInIntervals(
  const OwnedPoints<3>&, const std::vector<double>&, int, double, double, const Communicator&, PointsInInterval<3>&);
extern template Box<2> boundingBoxOverRanks(const PointCloud<2>&, const Communicator&);
extern template Box<3> boundingBoxOverRanks(const PointCloud<3>&, const Communicator&);
extern template class NearestOverRanks<2>;
extern template class NearestOverRanks<3>;
extern template struct OwnedPoints<2>;
extern template struct OwnedPoints<3>;

} // namespace sltk
