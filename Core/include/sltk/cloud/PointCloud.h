// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PointCloud.h
/// An unorganised point cloud P = {Q_1, ..., Q_N} (thesis 4.1) in D = 2 or 3
/// dimensions, stored as N x D doubles, and its validation: the checks every
/// reconstruction entry point runs before it allocates a grid.

#include "sltk/core/Status.h"

#include <array>
#include <cstdint>
#include <vector>

namespace sltk
{

/// The most points one process indexes (PointLocator's 32-bit tables): a
/// larger cloud is refused by validateCloud(), a larger share by
/// validateCloudShares(), a larger gathered cloud by the plan.
constexpr std::int64_t MaximumIndexedPoints = 4294967295;

template <int D>
struct PointCloud
{
  static_assert(D == 2 || D == 3, "point clouds are 2D or 3D");
  std::vector<std::array<double, D>> Points;

  std::int64_t size() const { return static_cast<std::int64_t>(this->Points.size()); }
};

/// Axis-aligned bounding box.
template <int D>
struct Box
{
  std::array<double, D> Min{};
  std::array<double, D> Max{};
  double extent(int axis) const { return this->Max[axis] - this->Min[axis]; }
  /// The largest extent: the edge of the minimal cube around the box (Delta P of (5.10)).
  double largestExtent() const
  {
    double edge = 0.0;
    for (int a = 0; a < D; ++a)
    {
      edge = edge < this->extent(a) ? this->extent(a) : edge;
    }
    return edge;
  }
};

/// Bounding box of a non-empty cloud.
template <int D>
Box<D> boundingBox(const PointCloud<D>& cloud);

/// Checks a cloud for reconstruction: at least D + 1 points, finite
/// coordinates, at least D + 1 distinct points, not all on one line (2D) or
/// one plane (3D), coordinates whose offset from the origin leaves enough
/// precision for the grid, at most MaximumIndexedPoints points. The message
/// names the first problem and the fix.
template <int D>
Status validateCloud(const PointCloud<D>& cloud);

class Communicator;

/// validateCloud() of the cloud whose shares the ranks hold (`share`: this
/// rank's points, global indices firstId, firstId + 1, ...: a parallel read's
/// shares, CloudFileShares.h), with the same checks, decisions and messages as
/// on one rank holding it whole (point indices are global), the same on every
/// rank. Fails on every rank when the shares are not consecutive in rank order
/// (each firstId the points of the ranks before) or a share has more than
/// MaximumIndexedPoints points. Collective.
template <int D>
Status validateCloudShares(const PointCloud<D>& share, std::int64_t firstId, const Communicator& comm);

/// validateCloud() of the cloud whose points the ranks own: `held` the points
/// this rank holds, `ids` their global indices (in any order), `mine` whether
/// it owns each (OwnedPoints, PointOwners.h: a point is owned by one rank,
/// the others may hold it as a halo). The same checks, decisions and messages
/// as on one rank holding the owned points in global index order. Collective.
template <int D>
Status validateOwnedPoints(const PointCloud<D>& held, const std::vector<std::int64_t>& ids,
  const std::vector<std::uint8_t>& mine, const Communicator& comm);

/// A 3D cloud with no z extent as a 2D cloud in its plane z = `z` (2D
/// reconstruction); false, and `flat` untouched, when the cloud has a z extent
/// or is empty.
bool flattenIfPlanar(const PointCloud<3>& cloud, PointCloud<2>& flat, double& z);

/// The same for a share of a cloud whose bounding box is `whole` (over every
/// rank's share, boundingBoxOverRanks; inverted when the cloud is empty): every
/// share is flattened when the whole cloud has no z extent.
bool flattenIfPlanar(const PointCloud<3>& cloud, const Box<3>& whole, PointCloud<2>& flat, double& z);

extern template Box<2> boundingBox(const PointCloud<2>&);
extern template Box<3> boundingBox(const PointCloud<3>&);
extern template Status validateCloud(const PointCloud<2>&);
extern template Status validateCloud(const PointCloud<3>&);
extern template Status validateCloudShares(const PointCloud<2>&, std::int64_t, const Communicator&);
extern template Status validateCloudShares(const PointCloud<3>&, std::int64_t, const Communicator&);
extern template Status validateOwnedPoints(
  const PointCloud<2>&, const std::vector<std::int64_t>&, const std::vector<std::uint8_t>&, const Communicator&);
extern template Status validateOwnedPoints(
  const PointCloud<3>&, const std::vector<std::int64_t>&, const std::vector<std::uint8_t>&, const Communicator&);

} // namespace sltk
