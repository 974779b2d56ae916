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
#include "sltk/core/Index.h"
#include "sltk/exec/Communicator.h"

namespace sltk
{

/// Collective. Whether the ranks hold different clouds: their point counts or
/// the sums (mod 2^64) of a hash of each point's coordinate bits, which do not
/// depend on the points' order. False on one rank, and when any rank holds a
/// non-finite coordinate (the validation then refuses the cloud on every rank,
/// with no gather first).
template <int D>
bool cloudsDiffer(const PointCloud<D>& cloud, const Communicator& comm);

/// Collective. Every rank's points in rank order, the exact duplicates of an
/// earlier point dropped (pieces that overlap, such as ghost points); returns
/// how many were dropped.
template <int D>
Index unionOfPieces(PointCloud<D>& cloud, const Communicator& comm);

/// Collective. When the ranks' clouds differ (cloudsDiffer), replaces every
/// rank's cloud by their union (unionOfPieces) and returns true; otherwise
/// leaves it and returns false.
template <int D>
bool joinCloudPieces(PointCloud<D>& cloud, const Communicator& comm);

extern template bool cloudsDiffer(const PointCloud<2>&, const Communicator&);
extern template bool cloudsDiffer(const PointCloud<3>&, const Communicator&);
extern template Index unionOfPieces(PointCloud<2>&, const Communicator&);
extern template Index unionOfPieces(PointCloud<3>&, const Communicator&);
extern template bool joinCloudPieces(PointCloud<2>&, const Communicator&);
extern template bool joinCloudPieces(PointCloud<3>&, const Communicator&);

} // namespace sltk
