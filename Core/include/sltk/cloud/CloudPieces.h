// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudPieces.h
/// The whole cloud on every rank from what the ranks hold. The reconstruction
/// needs the whole cloud on every rank (h_P (4.36), the box and the distance
/// see every point). A pipeline asked for the whole cloud gives every rank the
/// same points; a caller that hands each rank its own piece (a distributed
/// data set, points on rank 0 only, as ParaView's CSV reader does) gives
/// different ones, and then the whole cloud is their union.

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Communicator.h"

namespace sltk
{

/// Collective. When the ranks hold different clouds, replaces every rank's
/// cloud by their union and returns true; otherwise leaves it and returns
/// false (always on one rank).
/// - The clouds differ when their point counts, or the sums (mod 2^64) of a
///   hash of each point's coordinate bits, which do not depend on the points'
///   order, differ. A non-finite coordinate on any rank stops the join (the
///   validation then refuses the cloud on every rank, with no gather first).
/// - The union is every rank's points in rank order, the exact duplicates of
///   an earlier point dropped (pieces that overlap, such as ghost points).
template <int D>
bool joinCloudPieces(PointCloud<D>& cloud, const Communicator& comm);

/// Collective. Whether every rank holds the same points (joinCloudPieces' count
/// and order-free hash, at least one point, finite coordinates): the whole cloud
/// on every rank, not shares of it. False on one rank.
template <int D>
bool sameCloudOnEveryRank(const PointCloud<D>& cloud, const Communicator& comm);

extern template bool sameCloudOnEveryRank(const PointCloud<2>&, const Communicator&);
extern template bool sameCloudOnEveryRank(const PointCloud<3>&, const Communicator&);
extern template bool joinCloudPieces(PointCloud<2>&, const Communicator&);
extern template bool joinCloudPieces(PointCloud<3>&, const Communicator&);

} // namespace sltk
