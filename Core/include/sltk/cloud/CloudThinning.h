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

namespace sltk
{

/// Writes the cell means of `cloud` to `thinned`, ordered by cell (x fastest):
/// deterministic, and independent of the order of the points within a cell
/// only up to rounding. Fails for a non-positive cell or one so small that the
/// cells cannot be numbered in 64 bits.
template <int D>
Status thinCloud(const PointCloud<D>& cloud, double cell, PointCloud<D>& thinned);

extern template Status thinCloud(const PointCloud<2>&, double, PointCloud<2>&);
extern template Status thinCloud(const PointCloud<3>&, double, PointCloud<3>&);

} // namespace sltk
