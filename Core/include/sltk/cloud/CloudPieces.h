// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudPieces.h
/// The whole cloud on every rank from what the ranks hold. The reconstruction
/// needs the whole cloud on every rank (h_P (4.36), the box and the distance
/// see every point). A pipeline asked for the whole cloud gives every rank the
/// same points; a caller that hands each rank its own piece (a distributed
/// data set, points on rank 0 only) gives different ones, and then the
/// whole cloud is their union.

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Communicator.h"

namespace sltk
{

/// Collective. When the ranks' clouds differ (their sizes, or the sums,
/// sums of squares, minima and maxima of their coordinates), replaces every
/// rank's cloud by the union of all ranks' points in rank order and returns
/// true; when every rank holds the same cloud, leaves it and returns false.
/// Serial: false.
template <int D>
bool joinCloudPieces(PointCloud<D>& cloud, const Communicator& comm);

extern template bool joinCloudPieces(PointCloud<2>&, const Communicator&);
extern template bool joinCloudPieces(PointCloud<3>&, const Communicator&);

} // namespace sltk
