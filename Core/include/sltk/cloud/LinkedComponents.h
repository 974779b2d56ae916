// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LinkedComponents.h
/// The connected components of a cloud whose points are linked when they are
/// closer than a radius of either end: points i and j are linked when
/// |p_i - p_j| < max(r_i, r_j) (PointLocator::within from each end). The
/// cloud's components (recon/PointClusters.h, cloudComponents: r_i from the
/// local density spacing) and its groups far apart (a uniform r: the advice of
/// separate runs, ReconstructionPlan.h) are both this graph.
///
/// On the ranks (PointOwners.h) every owner links its own points to the points
/// it holds within their radii, with a halo at least as wide as the largest
/// radius, so every link is seen by the owner of one of its ends; a component
/// of one rank that holds a halo point meets, through that point, the component
/// of the point's owner, and those meetings (a few edges a cut) are gathered on
/// every rank and joined there (Documentation/Distributed.md, "The cloud's
/// components and its groups far apart on the owners").

#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"

#include <cstdint>
#include <vector>

namespace sltk
{

/// Links every point i of the locator's cloud (every one whose `mine` flag is
/// set, when `mine` is given) to the points within radius[i] of it
/// (PointLocator::within): unite(parent, i, j) in i's order, then the hits'.
/// `parent` is a forest over the locator's cloud (DisjointSets.h).
template <int D>
void linkWithinRadii(const PointLocator<D>& locator, const std::vector<double>& radius,
  const std::vector<std::uint8_t>* mine, std::vector<std::int64_t>& parent);

/// The components of the whole cloud from every rank's own points.
struct LinkedComponents
{
  std::int64_t Count = 0; ///< over every rank
  /// Per held point: at the owned ones, the smallest global index in its
  /// component (the same label on every rank, for any ranks' count); -1 at the halo's.
  std::vector<std::int64_t> Label;
};

/// The components of the cloud the ranks own, linked by `radius` (one per
/// held point, read at the owned ones; finite, >= 0). When points.Halo is
/// narrower than the largest radius, the owned points are sent again with
/// that halo first. The count and the labels are the one-rank ones for any
/// number of ranks and any cuts. Fails on every rank for a radius that is
/// negative or not finite, or global indices of 2^53 or more. Collective.
template <int D>
Status linkedComponentsOnRanks(const OwnedPoints<D>& points, const std::vector<double>& radius,
  const Communicator& comm, const Context& ctx, LinkedComponents& out);

/// The boxes around the groups of the cloud's points in which points closer
/// than `link` are linked (linkedComponentsOnRanks with a uniform radius), in
/// the order of their labels, when there are 2 to `maxGroups` groups; empty
/// otherwise. The same on every rank. Collective.
template <int D>
Status groupBoxesOnRanks(const OwnedPoints<D>& points, double link, std::int64_t maxGroups, const Communicator& comm,
  const Context& ctx, std::vector<Box<D>>& boxes);

/// The whole `cloud` as one rank's owned points (no cuts, every point its own,
/// global indices 0, 1, ...): the one-rank entry to the functions above.
template <int D>
OwnedPoints<D> ownedOnOneRank(const PointCloud<D>& cloud);

extern template void linkWithinRadii(
  const PointLocator<2>&, const std::vector<double>&, const std::vector<std::uint8_t>*, std::vector<std::int64_t>&);
extern template void linkWithinRadii(
  const PointLocator<3>&, const std::vector<double>&, const std::vector<std::uint8_t>*, std::vector<std::int64_t>&);
extern template Status linkedComponentsOnRanks(
  const OwnedPoints<2>&, const std::vector<double>&, const Communicator&, const Context&, LinkedComponents&);
extern template Status linkedComponentsOnRanks(
  const OwnedPoints<3>&, const std::vector<double>&, const Communicator&, const Context&, LinkedComponents&);
extern template Status groupBoxesOnRanks(
  const OwnedPoints<2>&, double, std::int64_t, const Communicator&, const Context&, std::vector<Box<2>>&);
extern template Status groupBoxesOnRanks(
  const OwnedPoints<3>&, double, std::int64_t, const Communicator&, const Context&, std::vector<Box<3>>&);
extern template OwnedPoints<2> ownedOnOneRank(const PointCloud<2>&);
extern template OwnedPoints<3> ownedOnOneRank(const PointCloud<3>&);

} // namespace sltk
