// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudThinning.h
/// Voxel-grid thinning of a point cloud before Algorithm 1: the points in each
/// cubic cell of edge `cell` (cells anchored at the bounding box's minimum)
/// are replaced by their mean. Beyond the thesis, for merged range scans: the
/// grid of run r cannot carry detail finer than dx^(r) (4.36), so points much
/// closer than that only cost time in the distance (4.4.2) and the error
/// Err_P (4.35); averaging the points of overlapping, noisy scans also
/// reduces the noise the model (4.9) would otherwise fit.

#include "sltk/cloud/PointCloud.h"
#include "sltk/cloud/PointOwners.h"

namespace sltk
{

/// Writes the cell means of `cloud` to `thinned`, ordered by cell (x fastest):
/// deterministic, and independent of the order of the points within a cell
/// only up to rounding. Fails for a non-positive cell or one so small that the
/// cells cannot be numbered in 64 bits.
template <int D>
Status thinCloud(const PointCloud<D>& cloud, double cell, PointCloud<D>& thinned);

/// thinCloud() of a cloud spread over the ranks by owners (PointOwners.h):
/// the same cells (anchored at the box of every rank's points), each averaged
/// by the rank of its lower face along the slabs' axis from its points in
/// global index order, so every mean is the one-rank mean bit for bit; the
/// means replace the points, each under its index in the one-rank thinned
/// cloud (the rows of cells per rank, gathered, place them: 24 bytes a row),
/// sent to their owners with the same cuts and halo. `total`: the thinned
/// cloud's points over every rank. The points are freed before the exchange
/// (its records hold them): when the move to the owners fails, `points` is
/// left empty. Collective.
template <int D>
Status thinOnRanks(OwnedPoints<D>& points, double cell, const Communicator& comm, std::int64_t& total);

extern template Status thinCloud(const PointCloud<2>&, double, PointCloud<2>&);
extern template Status thinCloud(const PointCloud<3>&, double, PointCloud<3>&);
extern template Status thinOnRanks(OwnedPoints<2>&, double, const Communicator&, std::int64_t&);
extern template Status thinOnRanks(OwnedPoints<3>&, double, const Communicator&, std::int64_t&);

} // namespace sltk
